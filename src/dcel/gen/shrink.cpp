// Shrinking: smaller valid graphs derived from a valid one, most aggressive
// first, made one at a time (ShrinkCandidates), so that shrinking a large
// graph holds one candidate in memory, not thousands.
//
// The steps, in order:
//   1. the empty graph;
//   2. every isolated vertex at once;
//   3. each connected component alone, then each dropped (when there are
//      several);
//   4. in a graph of 64 vertices or more, blocks of vertices dropped with
//      their edges: halves, quarters, ..., down to a sixteenth, so that it
//      halves in a few steps even when a dropped edge would change its
//      failure (leaving a vertex bare); then runs of edges dropped: all of
//      them, then halves, quarters, ..., single edges; then each vertex
//      with its edges;
//   5. each vertex of degree 2 merged away: a-v-b becomes the edge a-b;
//   6. each edge contracted: v is removed and its other edges go to u;
//   7. global snaps towards small integers: exact ones first (a power-of-two
//      scaling to integers or down to them, a translation to the origin),
//      then ranks, rounding, halving;
//   8. one vertex at a time moved towards small integers.
// Steps 5 and 6 keep cycles closed while they remove vertices, so a failure
// that needs a face survives them. Dropping edges or vertices keeps a graph
// valid (a subset of non-crossing segments and distinct points is still one);
// every other step is checked by brute force, against the moved vertex or the
// new edges only where the rest is unchanged.
//
// Termination: every candidate is smaller in (edges, vertices, non-integer
// coordinates, coordinate magnitudes), compared in that order; the last part
// only ever decreases pointwise (no coordinate grows, one shrinks). Steps 5
// and 6 remove a vertex and an edge each.
#include <algorithm>
#include <climits>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "dcel/core/union_find.hpp"
#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/generate.hpp"

namespace dcel::gen {
namespace {

bool is_integer(double v) { return std::trunc(v) == v; }

std::size_t non_integers(const PlanarGraph& g) {
    std::size_t n = 0;
    for (const Point& p : g.vertices)
        n += static_cast<std::size_t>(!is_integer(p.x)) + static_cast<std::size_t>(!is_integer(p.y));
    return n;
}

// No coordinate grew in magnitude and at least one shrank.
bool magnitudes_shrank(const PlanarGraph& before, const PlanarGraph& after) {
    bool smaller = false;
    for (std::size_t i = 0; i < before.vertices.size(); ++i) {
        for (const auto& [x, y] :
             {std::pair{before.vertices[i].x, after.vertices[i].x}, std::pair{before.vertices[i].y, after.vertices[i].y}}) {
            if (std::fabs(y) > std::fabs(x)) return false;
            smaller = smaller || std::fabs(y) < std::fabs(x);
        }
    }
    return smaller;
}

PlanarGraph without_edges(const PlanarGraph& g, std::size_t begin, std::size_t end) {
    PlanarGraph out;
    out.vertices = g.vertices;
    out.edges.reserve(g.edges.size() - (end - begin));
    out.edges.insert(out.edges.end(), g.edges.begin(), g.edges.begin() + static_cast<std::ptrdiff_t>(begin));
    out.edges.insert(out.edges.end(), g.edges.begin() + static_cast<std::ptrdiff_t>(end), g.edges.end());
    return out;
}

// g without the vertices for which drop[v] holds, nor their edges; the
// remaining vertices keep their order and are renumbered. `extra` edges (in
// old ids) are appended.
PlanarGraph without_vertices(const PlanarGraph& g, const std::vector<char>& drop, const std::vector<GraphEdge>& extra = {}) {
    PlanarGraph out;
    std::vector<Index> new_id(g.vertices.size(), kNoIndex);
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        if (drop[v] != 0) continue;
        new_id[v] = static_cast<Index>(out.vertices.size());
        out.vertices.push_back(g.vertices[v]);
    }
    auto keep = [&](const GraphEdge& e) {
        if (drop[e.u.index()] == 0 && drop[e.v.index()] == 0) {
            out.edges.push_back({VertexId(new_id[e.u.index()]), VertexId(new_id[e.v.index()])});
        }
    };
    for (const GraphEdge& e : g.edges) keep(e);
    for (const GraphEdge& e : extra) keep(e);
    return out;
}

// Each coordinate replaced by its rank among the distinct values on its
// axis: the smallest integers with the same x order and y order.
PlanarGraph ranks(const PlanarGraph& g) {
    std::map<double, double> xs, ys;  // -0.0 and 0.0 share a key
    for (const Point& p : g.vertices) {
        xs.emplace(p.x, 0);
        ys.emplace(p.y, 0);
    }
    double r = 0;
    for (auto& [x, rank] : xs) rank = r++;
    r = 0;
    for (auto& [y, rank] : ys) rank = r++;
    PlanarGraph out = g;
    for (Point& p : out.vertices) p = {xs[p.x], ys[p.y]};
    return out;
}

// The smallest power of two that makes every coordinate an integer, when
// scaling by it is exact; nothing otherwise.
std::optional<PlanarGraph> scaled_to_integers(const PlanarGraph& g) {
    int k = 0;
    for (const Point& p : g.vertices) {
        for (const double v : {p.x, p.y}) {
            if (v == 0 || is_integer(v)) continue;
            int e = 0;
            (void)std::frexp(v, &e);
            k = std::max(k, 53 - e);  // v * 2^(53 - e) is an integer
        }
    }
    if (k == 0) return std::nullopt;
    return apply(g, Transform::ScalePow2, k);
}

// Divided by the largest power of two that divides every coordinate (exact:
// huge coordinates that are small integers times 2^k become those integers).
std::optional<PlanarGraph> scaled_down(const PlanarGraph& g) {
    int k = INT_MAX;
    for (const Point& p : g.vertices) {
        for (const double v : {p.x, p.y}) {
            if (v == 0) continue;
            int e = 0;
            const double m = std::frexp(v, &e);                        // v = m 2^e, m in [0.5, 1)
            auto bits = static_cast<std::int64_t>(std::ldexp(m, 53));  // v = bits 2^(e - 53), exactly
            int tz = 0;
            while ((bits & 1) == 0) {
                bits >>= 1;
                ++tz;
            }
            k = std::min(k, e - 53 + tz);
        }
    }
    if (k == INT_MAX || k <= 0) return std::nullopt;
    return apply(g, Transform::ScalePow2, -k);
}

// Moved so that the smallest x and the smallest y are 0, when that is exact.
std::optional<PlanarGraph> moved_to_origin(const PlanarGraph& g) {
    if (g.vertices.empty()) return std::nullopt;
    double mx = g.vertices[0].x, my = g.vertices[0].y;
    for (const Point& p : g.vertices) {
        mx = std::min(mx, p.x);
        my = std::min(my, p.y);
    }
    PlanarGraph out = g;
    for (Point& p : out.vertices) {
        const Point q{p.x - mx, p.y - my};
        if (q.x + mx != p.x || q.y + my != p.y) return std::nullopt;  // rounded
        p = q;
    }
    return out;
}

double halved(double v) { return std::trunc(v / 2); }

// Is g still valid after vertex v moved? (g is valid apart from v's move.)
bool move_is_valid(const PlanarGraph& g, Index v) {
    const Point p = g.vertices[v];
    for (Index w = 0; w < g.vertices.size(); ++w) {
        if (w != v && g.vertices[w] == p) return false;
    }
    for (std::size_t k = 0; k < g.edges.size(); ++k) {
        const GraphEdge& e = g.edges[k];
        const Point a = g.vertices[e.u.index()], b = g.vertices[e.v.index()];
        const bool mine = e.u.index() == v || e.v.index() == v;
        if (!mine) {
            if (on_closed_segment(a, b, p)) return false;
            continue;
        }
        for (std::size_t j = 0; j < g.edges.size(); ++j) {
            if (j != k && segments_conflict(a, b, g.vertices[g.edges[j].u.index()], g.vertices[g.edges[j].v.index()])) {
                return false;
            }
        }
        for (Index w = 0; w < g.vertices.size(); ++w) {
            if (w != e.u.index() && w != e.v.index() && on_closed_segment(a, b, g.vertices[w])) return false;
        }
    }
    return true;
}

// Can the segment a-b (vertices of g) join g, ignoring the edges in `gone`
// and the vertex `removed`? No duplicate, no contact with another edge, no
// vertex inside it.
bool new_edge_fits(const PlanarGraph& g, Index a, Index b, const std::vector<char>& gone, Index removed) {
    if (a == b) return false;
    const Point pa = g.vertices[a], pb = g.vertices[b];
    for (std::size_t k = 0; k < g.edges.size(); ++k) {
        if (gone[k] != 0) continue;
        const GraphEdge& e = g.edges[k];
        const Index u = e.u.index(), v = e.v.index();
        if ((u == a && v == b) || (u == b && v == a)) return false;
        if (segments_conflict(pa, pb, g.vertices[u], g.vertices[v])) return false;
    }
    for (Index w = 0; w < g.vertices.size(); ++w) {
        if (w != a && w != b && w != removed && on_closed_segment(pa, pb, g.vertices[w])) return false;
    }
    return true;
}

// The edges of each vertex, as edge indexes.
std::vector<std::vector<std::size_t>> incidence(const PlanarGraph& g) {
    std::vector<std::vector<std::size_t>> inc(g.vertices.size());
    for (std::size_t k = 0; k < g.edges.size(); ++k) {
        inc[g.edges[k].u.index()].push_back(k);
        inc[g.edges[k].v.index()].push_back(k);
    }
    return inc;
}

Index other_end(const GraphEdge& e, Index v) { return e.u.index() == v ? e.v.index() : e.u.index(); }

// g without its isolated vertices, when it has more than one (one alone is
// left to the vertex-by-vertex stage).
std::optional<PlanarGraph> without_isolated_vertices(const PlanarGraph& g) {
    std::vector<char> isolated(g.vertices.size(), 1);
    for (const GraphEdge& ge : g.edges) isolated[ge.u.index()] = isolated[ge.v.index()] = 0;
    if (std::count(isolated.begin(), isolated.end(), 1) > 1) return without_vertices(g, isolated);
    return std::nullopt;
}

// g without the one vertex v (and its edges), with `extra` edges (old ids) added.
PlanarGraph without_vertex(const PlanarGraph& g, Index v, const std::vector<GraphEdge>& extra = {}) {
    std::vector<char> drop(g.vertices.size(), 0);
    drop[v] = 1;
    return without_vertices(g, drop, extra);
}

// The connected component of each vertex, numbered in order of each
// component's first vertex, and how many there are.
std::pair<std::vector<Index>, std::size_t> number_components(const PlanarGraph& g) {
    const auto n = static_cast<Index>(g.vertices.size());
    dcel::detail::UnionFind sets(n);
    for (const GraphEdge& ge : g.edges) (void)sets.unite(ge.u.index(), ge.v.index());
    std::map<Index, Index> number;  // root -> component
    std::vector<Index> component_of(n);
    for (Index v = 0; v < n; ++v) {
        component_of[v] = number.emplace(sets.find(v), static_cast<Index>(number.size())).first->second;
    }
    return {std::move(component_of), number.size()};
}

// The global snaps, the exact maps first (the graph keeps its shape), then
// the ones that move points relative to each other; nothing past the last.
std::optional<PlanarGraph> global_snap(const PlanarGraph& g, std::size_t which) {
    switch (which) {
        case 0: return scaled_to_integers(g);
        case 1: return scaled_down(g);
        case 2: return moved_to_origin(g);
        case 3: return ranks(g);
        case 4: {
            PlanarGraph c = g;
            for (Point& p : c.vertices) p = {std::round(p.x), std::round(p.y)};
            return c;
        }
        case 5: {
            PlanarGraph c = g;
            for (Point& p : c.vertices) p = {is_integer(p.x) ? halved(p.x) : p.x, is_integer(p.y) ? halved(p.y) : p.y};
            return c;
        }
        default: return std::nullopt;
    }
}
constexpr std::size_t kGlobalSnaps = 6;

// Where the move `target` (0, 1 or 2) takes the point p: a fractional point
// is rounded (target 0 only), an integer one has both coordinates halved,
// or x, or y. Nothing when the target does not apply or would not move p.
std::optional<Point> moved_point(Point p, std::size_t target) {
    Point to;
    if (!is_integer(p.x) || !is_integer(p.y)) {
        if (target != 0) return std::nullopt;
        to = {std::round(p.x), std::round(p.y)};
    } else {
        to = target == 0 ? Point{halved(p.x), halved(p.y)} : target == 1 ? Point{halved(p.x), p.y} : Point{p.x, halved(p.y)};
    }
    if (to == p) return std::nullopt;
    return to;
}

}  // namespace

ShrinkCandidates::ShrinkCandidates(PlanarGraph g) : ShrinkCandidates(std::move(g), Position{}) {}

// Resuming past it, the one cheap candidate that drops every isolated
// vertex still comes first: removing edges leaves vertices bare.
ShrinkCandidates::ShrinkCandidates(PlanarGraph g, Position start)
    : g_(std::move(g)),
      fractions_(non_integers(g_)),
      stage_(start.stage == Stage::Done ? Stage::Empty : start.stage),
      isolated_first_(stage_ > Stage::Isolated),
      chunk_(g_.edges.size()) {
    if (stage_ == Stage::VertexRuns) start_vertex_runs(start.chunk);
    if (stage_ == Stage::Edges) start_edges(start.chunk);
}

std::optional<PlanarGraph> ShrinkCandidates::next() {
    if (isolated_first_) {
        isolated_first_ = false;
        if (std::optional<PlanarGraph> c = without_isolated_vertices(g_)) {
            last_ = {Stage::Isolated, 0};
            return c;
        }
    }
    for (;;) {
        const Position here{stage_, stage_ == Stage::Edges || stage_ == Stage::VertexRuns ? chunk_ : 0};
        std::optional<PlanarGraph> c = step();
        if (c) {
            last_ = here;
            return c;
        }
        if (stage_ == Stage::Done) return std::nullopt;
    }
}

// One step of the current stage: a candidate, or nothing (this step had
// none, or the stage ended and the next one begins with the next call).
std::optional<PlanarGraph> ShrinkCandidates::step() {
    switch (stage_) {
        case Stage::Empty: return empty_step();
        case Stage::Isolated: next_stage(Stage::Components); return without_isolated_vertices(g_);
        case Stage::Components: return components_step();
        case Stage::VertexRuns: return vertex_runs_step();
        case Stage::Edges: return edges_step();
        case Stage::Vertices: return vertices_step();
        case Stage::MergeDegree2: return merge_degree2_step();
        case Stage::Contract: return contract_step();
        case Stage::GlobalSnaps: return global_snaps_step();
        case Stage::Moves: return moves_step();
        case Stage::Done: return std::nullopt;
    }
    return std::nullopt;
}

std::optional<PlanarGraph> ShrinkCandidates::empty_step() {
    stage_ = Stage::Isolated;
    if (g_.vertices.empty()) {
        stage_ = Stage::Done;
        return std::nullopt;
    }
    return PlanarGraph{};
}

// First each component alone (a failure inside one component shrinks to it
// at once), then each component dropped.
std::optional<PlanarGraph> ShrinkCandidates::components_step() {
    const std::size_t n = g_.vertices.size();
    if (component_of_.empty() && n > 0) std::tie(component_of_, components_) = number_components(g_);
    if (components_ < 2 || index_ >= 2 * components_) {
        start_vertex_runs(0);
        return std::nullopt;
    }
    const bool keep_only = index_ < components_;
    const std::size_t k = index_ % components_;
    ++index_;
    std::vector<char> drop(n, 0);
    for (Index v = 0; v < n; ++v) drop[v] = static_cast<char>((component_of_[v] == k) != keep_only);
    return without_vertices(g_, drop);
}

// Blocks of chunk_ consecutive vertices dropped in turn, with their edges;
// then blocks half as long, down to a sixteenth of the vertices. About 30
// candidates in all, whatever the size; only for graphs of at least
// kVertexRunsFrom vertices, where the edge runs after it may cost
// thousands of candidates that change the failure (a dropped edge leaves a
// bare vertex). A small graph shrinks as well without them, and its path to
// small integer coordinates stays the one it was.
std::optional<PlanarGraph> ShrinkCandidates::vertex_runs_step() {
    constexpr std::size_t kVertexRunsFrom = 64;
    const std::size_t n = g_.vertices.size();
    const std::size_t smallest = std::max<std::size_t>(2, n / 16);
    if (n < kVertexRunsFrom) {
        start_edges(0);
        return std::nullopt;
    }
    if (index_ >= n) {
        chunk_ /= 2;
        index_ = 0;
    }
    if (chunk_ < smallest) {
        start_edges(0);
        return std::nullopt;
    }
    const std::size_t begin = index_;
    index_ += chunk_;
    std::vector<char> drop(n, 0);
    std::fill(drop.begin() + static_cast<std::ptrdiff_t>(begin),
              drop.begin() + static_cast<std::ptrdiff_t>(std::min(n, begin + chunk_)), 1);
    return without_vertices(g_, drop);
}

// Runs of chunk_ edges dropped in turn; then runs half as long, down to
// single edges.
std::optional<PlanarGraph> ShrinkCandidates::edges_step() {
    const std::size_t e = g_.edges.size();
    if (chunk_ == 0 || e == 0) {
        next_stage(Stage::Vertices);
        return std::nullopt;
    }
    if (index_ >= e) {
        if (chunk_ == 1) {
            next_stage(Stage::Vertices);
            return std::nullopt;
        }
        chunk_ /= 2;
        index_ = 0;
    }
    const std::size_t begin = index_;
    index_ += chunk_;
    return without_edges(g_, begin, std::min(e, begin + chunk_));
}

std::optional<PlanarGraph> ShrinkCandidates::vertices_step() {
    if (index_ >= g_.vertices.size()) {
        next_stage(Stage::MergeDegree2);
        return std::nullopt;
    }
    return without_vertex(g_, static_cast<Index>(index_++));
}

// Vertex v of degree 2, a-v-b, becomes the edge a-b when that fits.
std::optional<PlanarGraph> ShrinkCandidates::merge_degree2_step() {
    if (incident_.empty()) incident_ = incidence(g_);
    if (index_ >= g_.vertices.size()) {
        next_stage(Stage::Contract);
        return std::nullopt;
    }
    const auto v = static_cast<Index>(index_++);
    if (incident_[v].size() != 2) return std::nullopt;
    const Index a = other_end(g_.edges[incident_[v][0]], v);
    const Index b = other_end(g_.edges[incident_[v][1]], v);
    std::vector<char> gone(g_.edges.size(), 0);
    gone[incident_[v][0]] = gone[incident_[v][1]] = 1;
    if (!new_edge_fits(g_, a, b, gone, v)) return std::nullopt;
    return without_vertex(g_, v, {{VertexId(a), VertexId(b)}});
}

// Edge u-v: v goes, its other edges go to u. Only a vertex of low degree:
// checking many new edges costs O(degree E).
std::optional<PlanarGraph> ShrinkCandidates::contract_step() {
    if (incident_.empty()) incident_ = incidence(g_);
    if (index_ >= g_.edges.size()) {
        next_stage(Stage::GlobalSnaps);
        return std::nullopt;
    }
    constexpr std::size_t kMaxContractedDegree = 8;
    const GraphEdge& ge = g_.edges[index_++];
    const Index u = ge.u.index(), v = ge.v.index();
    if (incident_[v].size() > kMaxContractedDegree) return std::nullopt;
    std::vector<char> gone(g_.edges.size(), 0);
    for (const std::size_t k : incident_[v]) gone[k] = 1;
    std::vector<GraphEdge> moved;
    for (const std::size_t k : incident_[v]) {
        const Index w = other_end(g_.edges[k], v);
        if (w == u) continue;
        if (!new_edge_fits(g_, u, w, gone, v)) return std::nullopt;
        // The new edges share u; they must not overlap one another.
        for (const GraphEdge& m : moved) {
            if (segments_conflict(g_.vertices[u], g_.vertices[w], g_.vertices[u], g_.vertices[m.v.index()])) {
                return std::nullopt;
            }
        }
        moved.push_back({VertexId(u), VertexId(w)});
    }
    return without_vertex(g_, v, moved);
}

// A global snap is taken when it has fewer non-integer coordinates, or as
// many and smaller magnitudes, and is still valid (brute force).
std::optional<PlanarGraph> ShrinkCandidates::global_snaps_step() {
    const std::size_t which = index_++;
    if (which >= kGlobalSnaps) {
        next_stage(Stage::Moves);
        return std::nullopt;
    }
    std::optional<PlanarGraph> c = global_snap(g_, which);
    if (!c) return std::nullopt;
    const std::size_t fractions = non_integers(*c);
    const bool smaller = fractions < fractions_ || (fractions == fractions_ && magnitudes_shrank(g_, *c));
    if (!smaller || find_problem(*c)) return std::nullopt;
    return c;
}

// Vertex index_ / 3 moved to target index_ % 3 (moved_point), when that is
// smaller and valid.
std::optional<PlanarGraph> ShrinkCandidates::moves_step() {
    if (index_ >= 3 * g_.vertices.size()) {
        stage_ = Stage::Done;
        return std::nullopt;
    }
    const auto v = static_cast<Index>(index_ / 3);
    const std::size_t t = index_++ % 3;
    const std::optional<Point> target = moved_point(g_.vertices[v], t);
    if (!target) return std::nullopt;
    PlanarGraph c = g_;
    c.vertices[v] = *target;
    const bool smaller = non_integers(c) < fractions_ || magnitudes_shrank(g_, c);
    if (!smaller || !move_is_valid(c, v)) return std::nullopt;
    return c;
}

void ShrinkCandidates::next_stage(Stage s) {
    stage_ = s;
    index_ = 0;
}

// The first block is half the vertices (or `chunk`, resuming, when smaller).
void ShrinkCandidates::start_vertex_runs(std::size_t chunk) {
    next_stage(Stage::VertexRuns);
    const std::size_t half = g_.vertices.size() / 2;
    chunk_ = chunk != 0 ? std::min(chunk, half) : half;
}

// The first run is every edge (or `chunk`, resuming, when smaller).
void ShrinkCandidates::start_edges(std::size_t chunk) {
    next_stage(Stage::Edges);
    chunk_ = chunk != 0 ? std::min(chunk, g_.edges.size()) : g_.edges.size();
}

std::vector<PlanarGraph> shrink_candidates(const PlanarGraph& g) {
    std::vector<PlanarGraph> out;
    ShrinkCandidates candidates(g);
    while (std::optional<PlanarGraph> c = candidates.next()) out.push_back(std::move(*c));
    return out;
}

GreedyShrink shrink_greedily(PlanarGraph g, const std::function<bool(const PlanarGraph&)>& still_fails,
                             const std::function<bool()>& stop) {
    GreedyShrink out{std::move(g)};
    ShrinkCandidates::Position resume;
    for (;;) {
        bool moved = false;
        ShrinkCandidates candidates(out.graph, resume);
        while (std::optional<PlanarGraph> c = candidates.next()) {
            if (stop()) {
                out.stopped = true;
                return out;
            }
            ++out.tried;
            if (still_fails(*c)) {
                out.graph = std::move(*c);
                ++out.taken;
                resume = candidates.position();
                moved = true;
                break;
            }
        }
        if (moved) continue;
        if (resume.stage == ShrinkCandidates::Stage::Empty) return out;  // a whole pass found nothing
        resume = {};                                                     // once more from the start
    }
}

PlanarGraph shrink(PlanarGraph g, const std::function<bool(const PlanarGraph&)>& still_fails, std::size_t max_steps) {
    std::size_t steps = 0;
    return shrink_greedily(std::move(g), still_fails, [&] { return steps++ >= max_steps; }).graph;
}

}  // namespace dcel::gen
