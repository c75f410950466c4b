#include "dcel/gen/graph_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <utility>

#include "dcel/gen/brute_force.hpp"

namespace dcel::gen {
namespace {

__extension__ typedef __int128 Wide;  // NOLINT(modernize-use-using)

// Filed coordinates are integers below 2^40: the products in for_each_bucket
// stay below 2^83, far inside 128 bits.
constexpr double kFiledLimit = 0x1p40;

template <class T>
T floor_div(T a, T b) {  // b > 0
    const T q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}
}  // namespace

std::size_t GraphBuilder::PointHash::operator()(Point p) const {
    // + 0.0 turns -0.0 into 0.0, which operator== calls the same point.
    const std::size_t hx = std::hash<double>{}(p.x + 0.0);
    const std::size_t hy = std::hash<double>{}(p.y + 0.0);
    return hx ^ (hy + 0x9e3779b97f4a7c15ULL + (hx << 6U) + (hx >> 2U));
}

GraphBuilder::GraphBuilder(std::int64_t cell)
    : cell_(std::max<std::int64_t>(cell, 1)), buckets_(std::size_t{1} << bucket_bits_) {}

bool GraphBuilder::filed(Point p) const {
    return std::fabs(p.x) < kFiledLimit && std::fabs(p.y) < kFiledLimit && std::trunc(p.x) == p.x && std::trunc(p.y) == p.y;
}

std::int64_t GraphBuilder::cell_of(double coordinate) const {
    return floor_div(static_cast<std::int64_t>(coordinate), cell_);
}

std::size_t GraphBuilder::bucket(std::int64_t cx, std::int64_t cy) const {
    // Blocks of 4 x 4 cells share one run of 16 buckets (neighbouring cells
    // stay near in memory); blocks are spread by Fibonacci hashing, so no
    // shape of graph piles many cells into one bucket.
    const std::uint64_t block = static_cast<std::uint64_t>(cx >> 2) * 0x9e3779b97f4a7c15ULL ^
                                static_cast<std::uint64_t>(cy >> 2) * 0xc2b2ae3d27d4eb4fULL;
    const auto within = static_cast<std::size_t>((cx & 3) | ((cy & 3) << 2));
    return static_cast<std::size_t>(((block * 0x9e3779b97f4a7c15ULL) >> (64 - (bucket_bits_ - 4))) << 4) | within;
}

template <class Visit>
void GraphBuilder::for_each_bucket(Point a, Point b, Visit visit) const {
    if (b.x < a.x) std::swap(a, b);
    const auto ax = static_cast<std::int64_t>(a.x), ay = static_cast<std::int64_t>(a.y);
    const auto bx = static_cast<std::int64_t>(b.x), by = static_cast<std::int64_t>(b.y);
    const std::int64_t c = cell_;
    for (std::int64_t k = floor_div(ax, c); k <= floor_div(bx, c); ++k) {
        // The closed x-range of the segment within column k (its right end
        // on the next column's boundary: a little more than needed is fine),
        // and the y-range it spans there, y = n / den; the rows are those of
        // floor(y) (the same as those of y, since c is an integer).
        std::int64_t y_lo = std::min(ay, by), y_hi = std::max(ay, by);
        if (ax != bx) {
            const std::int64_t x0 = std::max(ax, k * c), x1 = std::min(bx, (k + 1) * c);
            const Wide den = bx - ax;
            const Wide n0 = static_cast<Wide>(ay) * den + static_cast<Wide>(x0 - ax) * (by - ay);
            const Wide n1 = static_cast<Wide>(ay) * den + static_cast<Wide>(x1 - ax) * (by - ay);
            y_lo = static_cast<std::int64_t>(floor_div(std::min(n0, n1), den));
            y_hi = static_cast<std::int64_t>(floor_div(std::max(n0, n1), den));
        }
        for (std::int64_t r = floor_div(y_lo, c); r <= floor_div(y_hi, c); ++r) visit(bucket(k, r));
    }
}

void GraphBuilder::file_vertex(Index v) {
    if (!filed(g_.vertices[v])) {
        loose_vertices_.push_back(v);
        return;
    }
    buckets_[bucket_of(g_.vertices[v])].push_back(v | kVertex);
    ++filed_items_;
}

void GraphBuilder::file_edge(Index e) {
    const Point a = g_.vertices[g_.edges[e].u.index()];
    const Point b = g_.vertices[g_.edges[e].v.index()];
    if (!filed(a) || !filed(b)) {
        loose_edges_.push_back(e);
        return;
    }
    for_each_bucket(a, b, [&](std::size_t k) {
        std::vector<Index>& list = buckets_[k];
        if (list.empty() || list.back() != e) {
            list.push_back(e);
            ++filed_items_;
        }
    });
}

void GraphBuilder::grow_if_full() {
    if (filed_items_ <= 2 * buckets_.size()) return;
    // Four times the buckets, everything filed again: amortized O(1) per filing.
    bucket_bits_ += 2;
    buckets_.assign(std::size_t{1} << bucket_bits_, {});
    loose_vertices_.clear();
    loose_edges_.clear();
    filed_items_ = 0;
    for (Index v = 0; v < g_.vertices.size(); ++v) file_vertex(v);
    for (Index e = 0; e < g_.edges.size(); ++e) file_edge(e);
}

std::optional<VertexId> GraphBuilder::find(Point p) const {
    const auto it = at_.find(p);
    if (it == at_.end()) return std::nullopt;
    return it->second;
}

bool GraphBuilder::on_some_edge(Point p) const {
    auto on = [&](Index e) {
        const GraphEdge& edge = g_.edges[e];
        return on_closed_segment(g_.vertices[edge.u.index()], g_.vertices[edge.v.index()], p);
    };
    if (!filed(p)) {
        for (Index e = 0; e < g_.edges.size(); ++e) {
            if (on(e)) return true;
        }
        return false;
    }
    if (std::any_of(loose_edges_.begin(), loose_edges_.end(), on)) return true;
    const std::vector<Index>& here = buckets_[bucket_of(p)];
    return std::any_of(here.begin(), here.end(), [&](Index item) { return (item & kVertex) == 0 && on(item); });
}

std::optional<VertexId> GraphBuilder::add_point(Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || at_.contains(p) || on_some_edge(p)) return std::nullopt;
    const VertexId id(static_cast<Index>(g_.vertices.size()));
    g_.vertices.push_back(p);
    vertex_mark_.push_back(0);
    at_.emplace(p, id);
    file_vertex(id.index());
    grow_if_full();
    return id;
}

std::optional<VertexId> GraphBuilder::point(Point p) {
    if (const std::optional<VertexId> v = find(p)) return v;
    return add_point(p);
}

void GraphBuilder::remove_last_vertex() {
    const Point p = g_.vertices.back();
    const auto id = static_cast<Index>(g_.vertices.size() - 1);
    // Found from the back: it is the newest vertex (a growth may have filed
    // edges after it).
    std::vector<Index>& list = filed(p) ? buckets_[bucket_of(p)] : loose_vertices_;
    const Index item = filed(p) ? (id | kVertex) : id;
    list.erase(std::next(std::find(list.rbegin(), list.rend(), item)).base());
    if (filed(p)) --filed_items_;
    at_.erase(p);
    g_.vertices.pop_back();
    vertex_mark_.pop_back();
}

bool GraphBuilder::can_add_edge(VertexId u, VertexId v) const {
    // A second copy of an edge needs no test of its own: segments_conflict
    // calls the same segment a conflict, and the copy covers the same cells.
    if (u == v || u.index() >= g_.vertices.size() || v.index() >= g_.vertices.size()) return false;
    const Point a = g_.vertices[u.index()];
    const Point b = g_.vertices[v.index()];
    if (query_ == UINT32_MAX) {  // the marks would wrap around: start them afresh
        std::fill(edge_mark_.begin(), edge_mark_.end(), 0);
        std::fill(vertex_mark_.begin(), vertex_mark_.end(), 0);
        query_ = 0;
    }
    ++query_;
    auto edge_meets = [&](Index e) {
        if (edge_mark_[e] == query_) return false;
        edge_mark_[e] = query_;
        const GraphEdge& f = g_.edges[e];
        return segments_conflict(a, b, g_.vertices[f.u.index()], g_.vertices[f.v.index()]);
    };
    auto vertex_on = [&](Index w) {
        if (vertex_mark_[w] == query_ || w == u.index() || w == v.index()) return false;
        vertex_mark_[w] = query_;
        return on_closed_segment(a, b, g_.vertices[w]);
    };
    if (!filed(a) || !filed(b)) {
        for (Index e = 0; e < g_.edges.size(); ++e) {
            if (edge_meets(e)) return false;
        }
        for (Index w = 0; w < g_.vertices.size(); ++w) {
            if (vertex_on(w)) return false;
        }
        return true;
    }
    if (std::any_of(loose_edges_.begin(), loose_edges_.end(), edge_meets) ||
        std::any_of(loose_vertices_.begin(), loose_vertices_.end(), vertex_on)) {
        return false;
    }
    bool clear = true;
    for_each_bucket(a, b, [&](std::size_t k) {
        if (!clear) return;
        const std::vector<Index>& list = buckets_[k];
        clear = std::none_of(list.begin(), list.end(), [&](Index item) {
            return (item & kVertex) != 0 ? vertex_on(item & ~kVertex) : edge_meets(item);
        });
    });
    return clear;
}

bool GraphBuilder::add_edge(VertexId u, VertexId v) {
    if (!can_add_edge(u, v)) return false;
    const auto id = static_cast<Index>(g_.edges.size());
    g_.edges.push_back({u, v});
    edge_mark_.push_back(0);
    file_edge(id);
    grow_if_full();
    return true;
}

bool GraphBuilder::add_segment(Point a, Point b) {
    const std::size_t before = g_.vertices.size();
    const std::optional<VertexId> u = point(a);
    const std::optional<VertexId> v = u ? point(b) : std::nullopt;
    if (u && v && add_edge(*u, *v)) return true;
    while (g_.vertices.size() > before) remove_last_vertex();
    return false;
}

}  // namespace dcel::gen
