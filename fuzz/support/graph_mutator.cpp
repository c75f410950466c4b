#include "support/graph_mutator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "dcel/gen/generate.hpp"
#include "oracles/brute_force.hpp"
#include "oracles/exact.hpp"
#include "oracles/union_find.hpp"

namespace dcel::fuzz {
namespace {

std::int64_t between(gen::Rng& rng, std::int64_t lo, std::int64_t hi) { return rng.between(lo, hi); }

Index pick(gen::Rng& rng, std::size_t n) { return static_cast<Index>(rng.below(n)); }

// v moved by k ulps (towards +inf for k > 0).
double ulps(double v, std::int64_t k) {
    for (; k > 0; --k) v = std::nextafter(v, HUGE_VAL);
    for (; k < 0; ++k) v = std::nextafter(v, -HUGE_VAL);
    return v;
}

// A coordinate near v: a few ulps away, a small or power-of-two step away,
// rounded to an integer, halved or doubled.
double nudge(double v, gen::Rng& rng) {
    switch (rng.below(6)) {
        case 0:
        case 1: return ulps(v, between(rng, -3, 3));
        case 2: return v + static_cast<double>(between(rng, -2, 2));
        case 3: return v + std::ldexp(rng.chance(1, 2) ? 1.0 : -1.0, static_cast<int>(between(rng, -40, 8)));
        case 4: return std::round(v);
        default: return rng.chance(1, 2) ? v * 0.5 : v * 2;
    }
}

// A fraction t for a point a + t (b - a): inside the segment, or beyond
// either end; the point is rounded, so it lies on or within rounding of
// the line through a and b.
double fraction(gen::Rng& rng) {
    static constexpr double kFractions[] = {0.5, 1.0 / 3, 2.0 / 3, 0.25, 0.75, 0.1, -1, 2, -0.5, 1.5};
    return kFractions[rng.below(std::size(kFractions))];
}

Point along(Point a, Point b, double t) { return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}; }

void erase_edge(PlanarGraph& g, std::size_t e) { g.edges.erase(g.edges.begin() + static_cast<std::ptrdiff_t>(e)); }

// Removes vertex v and its edges; later vertices shift down by one.
void erase_vertex(PlanarGraph& g, Index v) {
    std::erase_if(g.edges, [&](const GraphEdge& e) { return e.u.index() == v || e.v.index() == v; });
    for (GraphEdge& e : g.edges) {
        if (e.u.index() > v) e.u = VertexId(e.u.index() - 1);
        if (e.v.index() > v) e.v = VertexId(e.v.index() - 1);
    }
    g.vertices.erase(g.vertices.begin() + static_cast<std::ptrdiff_t>(v));
}

// An edge whose ends exist (a broken graph may have others), by index.
std::optional<std::size_t> pick_edge(const PlanarGraph& g, gen::Rng& rng) {
    for (int attempt = 0; attempt < 4 && !g.edges.empty(); ++attempt) {
        const std::size_t e = rng.below(g.edges.size());
        if (g.edges[e].u.index() < g.vertices.size() && g.edges[e].v.index() < g.vertices.size()) return e;
    }
    return std::nullopt;
}

Index add_point(PlanarGraph& g, Point p) {
    g.vertices.push_back(p);
    return static_cast<Index>(g.vertices.size() - 1);
}

// ---- Mutations. Each returns false when it does not apply to g.

bool move_vertex(PlanarGraph& g, gen::Rng& rng) {
    if (g.vertices.empty()) return false;
    Point& p = g.vertices[pick(rng, g.vertices.size())];
    const int which = static_cast<int>(rng.below(3));
    if (which != 1) p.x = nudge(p.x, rng);
    if (which != 0) p.y = nudge(p.y, rng);
    return true;
}

// v moved onto the line through a and b, or within rounding of it: where
// exact and floating-point orientation disagree. Often a-b is an edge (v
// lands next to it: the sweep's question) or v is a neighbour of a (two
// edges at a become nearly parallel: the ring sort's question).
bool onto_line(PlanarGraph& g, gen::Rng& rng) {
    const std::size_t n = g.vertices.size();
    if (n < 3) return false;
    Index v = pick(rng, n), a = pick(rng, n), b = pick(rng, n);
    if (const std::optional<std::size_t> e = pick_edge(g, rng); e && rng.chance(2, 3)) {
        a = g.edges[*e].u.index();
        b = g.edges[*e].v.index();
        if (rng.chance(1, 2)) {  // a neighbour of a, if it has another
            for (const GraphEdge& f : g.edges) {
                if (f.u.index() == a && f.v.index() != b && f.v.index() < n && rng.chance(1, 2)) v = f.v.index();
                if (f.v.index() == a && f.u.index() != b && f.u.index() < n && rng.chance(1, 2)) v = f.u.index();
            }
        }
    }
    if (v == a || v == b || a == b) return false;
    Point p = along(g.vertices[a], g.vertices[b], fraction(rng));
    if (rng.chance(1, 3)) {
        double& c = rng.chance(1, 2) ? p.x : p.y;
        c = ulps(c, between(rng, -2, 2));
    }
    g.vertices[v] = p;
    return true;
}

// v moved a few ulps from another vertex w (onto w itself when breaking).
bool beside_vertex(PlanarGraph& g, gen::Rng& rng, Validity validity) {
    if (g.vertices.size() < 2) return false;
    const Index v = pick(rng, g.vertices.size()), w = pick(rng, g.vertices.size());
    if (v == w) return false;
    Point p = g.vertices[w];
    const std::int64_t k = validity == Validity::Break ? between(rng, -2, 2) : (rng.chance(1, 2) ? 1 : -1);
    double& c = rng.chance(1, 2) ? p.x : p.y;
    c = ulps(c, k);
    g.vertices[v] = p;
    return true;
}

// A new isolated vertex near an existing one, on or near an edge's line, or
// at the midpoint of two vertices.
bool add_vertex(PlanarGraph& g, gen::Rng& rng) {
    if (g.vertices.empty()) {
        g.vertices.push_back({static_cast<double>(between(rng, -4, 4)), static_cast<double>(between(rng, -4, 4))});
        return true;
    }
    const Point a = g.vertices[pick(rng, g.vertices.size())];
    const Point b = g.vertices[pick(rng, g.vertices.size())];
    switch (rng.below(3)) {
        case 0: add_point(g, {nudge(a.x, rng), nudge(a.y, rng)}); break;
        case 1: add_point(g, along(a, b, fraction(rng))); break;
        default: add_point(g, {ulps(along(a, b, 0.5).x, between(rng, -1, 1)), along(a, b, 0.5).y}); break;
    }
    return true;
}

// An edge between two vertices: any two, or (often) two close in id, which
// generated graphs place close in the plane.
bool add_edge(PlanarGraph& g, gen::Rng& rng) {
    const std::size_t n = g.vertices.size();
    if (n < 2) return false;
    const Index u = pick(rng, n);
    const Index w = rng.chance(1, 2) ? pick(rng, n)
                                     : static_cast<Index>((u + 1 + rng.below(std::min<std::size_t>(n - 1, 6))) % n);
    if (u == w) return false;
    g.edges.push_back({VertexId(u), VertexId(w)});
    return true;
}

bool drop_edge(PlanarGraph& g, gen::Rng& rng) {
    if (g.edges.empty()) return false;
    erase_edge(g, pick(rng, g.edges.size()));
    return true;
}

bool drop_vertex(PlanarGraph& g, gen::Rng& rng) {
    if (g.vertices.empty()) return false;
    erase_vertex(g, pick(rng, g.vertices.size()));
    return true;
}

// Edge u-w replaced by u-m and m-w, m at (or within rounding of) a point of
// the segment.
bool split_edge(PlanarGraph& g, gen::Rng& rng) {
    const std::optional<std::size_t> picked = pick_edge(g, rng);
    if (!picked) return false;
    const std::size_t e = *picked;
    const GraphEdge old = g.edges[e];
    static constexpr double kInside[] = {0.5, 0.25, 0.75, 1.0 / 3};
    const Point m = along(g.vertices[old.u.index()], g.vertices[old.v.index()], kInside[rng.below(std::size(kInside))]);
    const Index mid = add_point(g, m);
    g.edges[e] = {old.u, VertexId(mid)};
    g.edges.push_back({VertexId(mid), old.v});
    return true;
}

// One of the generators' exact transforms (skipped when it would round).
bool transform(PlanarGraph& g, gen::Rng& rng) {
    static constexpr gen::Transform kKinds[] = {gen::Transform::Translate, gen::Transform::Rotate90, gen::Transform::Mirror,
                                                gen::Transform::ScalePow2};
    const gen::Transform kind = kKinds[rng.below(std::size(kKinds))];
    std::int64_t amount = 0;
    if (kind == gen::Transform::Translate) {
        amount = rng.chance(1, 2) ? between(rng, -16, 16)
                                  : (rng.chance(1, 2) ? 1 : -1) * (std::int64_t{1} << between(rng, 20, 52));
    } else if (kind == gen::Transform::ScalePow2) {
        amount = rng.chance(3, 4) ? between(rng, -8, 8) : between(rng, -900, 900);
    }
    auto moved = gen::apply(g, kind, amount);
    if (!moved) return false;
    g = std::move(*moved);
    return true;
}

// ---- Defects, for Validity::Break.

// An edge from a vertex on one side of edge a-b to one on the other.
bool crossing_edge(PlanarGraph& g, gen::Rng& rng) {
    const std::optional<std::size_t> picked = pick_edge(g, rng);
    if (!picked || g.vertices.size() < 4) return false;
    const GraphEdge e = g.edges[*picked];
    const Point a = g.vertices[e.u.index()], b = g.vertices[e.v.index()];
    std::vector<Index> left, right;
    for (Index v = 0; v < g.vertices.size(); ++v) {
        const int o = oracle::orientation(a, b, g.vertices[v]);
        (o > 0 ? left : right).push_back(v);
        if (o == 0) right.pop_back();
    }
    if (left.empty() || right.empty()) return false;
    g.edges.push_back({VertexId(left[rng.below(left.size())]), VertexId(right[rng.below(right.size())])});
    return true;
}

// A vertex put on an edge (the rounded midpoint: on it or within rounding).
bool touch(PlanarGraph& g, gen::Rng& rng) {
    const std::optional<std::size_t> picked = pick_edge(g, rng);
    if (!picked || g.vertices.size() < 3) return false;
    const GraphEdge e = g.edges[*picked];
    const Index v = pick(rng, g.vertices.size());
    if (v == e.u.index() || v == e.v.index()) return false;
    g.vertices[v] = along(g.vertices[e.u.index()], g.vertices[e.v.index()], 0.5);
    return true;
}

// A new vertex p = b + (b - a) and the edge a-p, which runs along a-b.
bool overlap(PlanarGraph& g, gen::Rng& rng) {
    const std::optional<std::size_t> picked = pick_edge(g, rng);
    if (!picked) return false;
    const GraphEdge e = g.edges[*picked];
    const Index p = add_point(g, along(g.vertices[e.u.index()], g.vertices[e.v.index()], 2));
    g.edges.push_back({e.u, VertexId(p)});
    return true;
}

bool duplicate(PlanarGraph& g, gen::Rng& rng) {
    if (g.edges.empty() || rng.chance(1, 3)) {
        if (g.vertices.size() < 2) return false;
        g.vertices[pick(rng, g.vertices.size())] = g.vertices[pick(rng, g.vertices.size())];
        return true;
    }
    const GraphEdge e = g.edges[pick(rng, g.edges.size())];
    g.edges.push_back({e.v, e.u});
    return true;
}

// Rare inputs build() must refuse cleanly: a non-finite coordinate, an
// index out of range, a self-loop.
bool bad_element(PlanarGraph& g, gen::Rng& rng) {
    if (g.vertices.empty()) return false;
    switch (rng.below(3)) {
        case 0: g.vertices[pick(rng, g.vertices.size())].y = rng.chance(1, 2) ? NAN : -INFINITY; break;
        case 1:
            g.edges.push_back({VertexId(pick(rng, g.vertices.size())), VertexId(static_cast<Index>(g.vertices.size()))});
            break;
        default: {
            const auto v = VertexId(pick(rng, g.vertices.size()));
            g.edges.push_back({v, v});
        }
    }
    return true;
}

// The vertices of the component of g containing v (by union-find; edges
// with an end out of range, which a broken graph may have, join nothing).
std::vector<Index> component_of(const PlanarGraph& g, Index v) {
    oracle::UnionFind uf(g.vertices.size());
    for (const GraphEdge& e : g.edges) {
        if (e.u.index() < g.vertices.size() && e.v.index() < g.vertices.size()) uf.unite(e.u.index(), e.v.index());
    }
    std::vector<Index> out;
    for (Index w = 0; w < g.vertices.size(); ++w) {
        if (uf.find(w) == uf.find(v)) out.push_back(w);
    }
    return out;
}

// A copy of `part` (vertices of `from`, with the edges among them) scaled by
// 2^-shrink and moved so that its first vertex lands at `at`.
void paste(PlanarGraph& g, const PlanarGraph& from, const std::vector<Index>& part, int shrink, Point at) {
    std::vector<Index> new_id(from.vertices.size(), kNoIndex);
    const Point origin = from.vertices[part.front()];
    for (const Index v : part) {
        new_id[v] = static_cast<Index>(g.vertices.size());
        const Point p = from.vertices[v];
        g.vertices.push_back({at.x + std::ldexp(p.x - origin.x, -shrink), at.y + std::ldexp(p.y - origin.y, -shrink)});
    }
    for (const GraphEdge& e : from.edges) {
        if (e.u.index() < new_id.size() && e.v.index() < new_id.size() && new_id[e.u.index()] != kNoIndex &&
            new_id[e.v.index()] != kNoIndex) {
            g.edges.push_back({VertexId(new_id[e.u.index()]), VertexId(new_id[e.v.index()])});
        }
    }
}

// Where to put a copy: inside a triangle of three vertices (the rounded
// centroid: often inside a face), beside a vertex, or beyond the graph.
Point landing_point(const PlanarGraph& g, gen::Rng& rng) {
    if (g.vertices.empty()) return {0, 0};
    const Point a = g.vertices[pick(rng, g.vertices.size())];
    const Point b = g.vertices[pick(rng, g.vertices.size())];
    const Point c = g.vertices[pick(rng, g.vertices.size())];
    switch (rng.below(3)) {
        case 0: return {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
        case 1: return {nudge(a.x, rng), nudge(a.y, rng)};
        default: {
            double right = a.x;
            for (const Point& p : g.vertices) right = std::max(right, p.x);
            return {right + 1 + static_cast<double>(rng.below(4)), a.y};
        }
    }
}

// A component of `from` (a random vertex's), pasted into g at a landing
// point, scaled down until it fits.
bool insert_component(PlanarGraph& g, const PlanarGraph& from, gen::Rng& rng, Validity validity, const GraphLimits& limits) {
    if (from.vertices.empty()) return false;
    const std::vector<Index> part = component_of(from, pick(rng, from.vertices.size()));
    if (g.vertices.size() + part.size() > limits.vertices) return false;
    const Point at = landing_point(g, rng);
    const PlanarGraph before = g;
    for (int shrink = static_cast<int>(rng.below(4)); shrink < 64; shrink += 6) {
        paste(g, from, part, shrink, at);
        if (g.edges.size() > limits.edges) break;
        if (validity == Validity::Break || still_valid(g, before)) return true;
        g = before;
    }
    g = before;
    return false;
}

// A mutation's result: none made, valid by construction (deletions, exact
// transforms), or to be checked.
enum class Outcome { None, Valid, Check };

Outcome checked(bool made) { return made ? Outcome::Check : Outcome::None; }

Outcome one_mutation(PlanarGraph& g, gen::Rng& rng, Validity validity, const GraphLimits& limits) {
    // Growth is refused at the limits, and the more often the closer a
    // graph gets to them: sizes settle well below, where runs are fast,
    // and still reach the limits now and then.
    const bool full = g.vertices.size() >= limits.vertices || g.edges.size() >= limits.edges ||
                      rng.below(limits.vertices) < g.vertices.size();
    const bool over = g.vertices.size() > limits.vertices || g.edges.size() > limits.edges;
    if (over) return (rng.chance(1, 2) ? drop_vertex(g, rng) : drop_edge(g, rng)) ? Outcome::Valid : Outcome::None;
    switch (rng.below(validity == Validity::Break ? 16 : 12)) {
        case 0: return checked(move_vertex(g, rng));
        case 1:
        case 2: return checked(onto_line(g, rng));
        case 3: return checked(beside_vertex(g, rng, validity));
        case 4: return checked(!full && add_vertex(g, rng));
        case 5:
        case 6: return checked(!full && add_edge(g, rng));
        case 7: return drop_edge(g, rng) ? Outcome::Valid : Outcome::None;
        case 8: return drop_vertex(g, rng) ? Outcome::Valid : Outcome::None;
        case 9: return checked(!full && split_edge(g, rng));
        case 10: return transform(g, rng) ? Outcome::Valid : Outcome::None;
        case 11: return !full && insert_component(g, PlanarGraph(g), rng, validity, limits) ? Outcome::Valid : Outcome::None;
        case 12: return checked(!full && crossing_edge(g, rng));
        case 13: return checked(touch(g, rng));
        case 14: return checked(!full && overlap(g, rng));
        default: return checked(rng.chance(1, 4) ? bad_element(g, rng) : duplicate(g, rng));
    }
}

}  // namespace

bool is_valid(const PlanarGraph& g) { return oracle::find_defects(g).empty(); }

bool still_valid(const PlanarGraph& g, const PlanarGraph& before) {
    const std::size_t n = g.vertices.size(), m = g.edges.size();
    std::vector<char> moved(n, 0), touched(m, 0);
    for (Index v = 0; v < n; ++v) moved[v] = v >= before.vertices.size() || !(g.vertices[v] == before.vertices[v]) ? 1 : 0;
    for (std::size_t k = 0; k < m; ++k) {
        const GraphEdge& e = g.edges[k];
        if (e.u.index() >= n || e.v.index() >= n || e.u == e.v) return false;
        touched[k] = k >= before.edges.size() || !(e == before.edges[k]) || moved[e.u.index()] != 0 ||
                     moved[e.v.index()] != 0;
    }
    auto point = [&](VertexId v) { return g.vertices[v.index()]; };
    // Moved and new vertices: finite, at no other vertex's point, inside no edge.
    for (Index v = 0; v < n; ++v) {
        if (moved[v] == 0) continue;
        const Point p = g.vertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
        for (Index w = 0; w < n; ++w) {
            if (w != v && g.vertices[w] == p) return false;
        }
        for (const GraphEdge& e : g.edges) {
            if (oracle::strictly_on_segment(point(e.u), point(e.v), p)) return false;
        }
    }
    // Changed edges and those at moved vertices: no duplicate, no vertex
    // inside, no contact with another edge but a shared end.
    for (std::size_t k = 0; k < m; ++k) {
        if (touched[k] == 0) continue;
        const GraphEdge e = g.edges[k];
        const Point a = point(e.u), b = point(e.v);
        for (Index w = 0; w < n; ++w) {
            if (oracle::strictly_on_segment(a, b, g.vertices[w])) return false;
        }
        for (std::size_t j = 0; j < m; ++j) {
            if (j == k || (touched[j] != 0 && j < k)) continue;  // each touched pair once
            const GraphEdge f = g.edges[j];
            if (std::minmax(e.u, e.v) == std::minmax(f.u, f.v)) return false;
            const oracle::Meeting how = oracle::meeting(a, b, point(f.u), point(f.v));
            if (how != oracle::Meeting::None && how != oracle::Meeting::SharedEndpoint) return false;
        }
    }
    return true;
}

bool mutate_graph(PlanarGraph& g, gen::Rng& rng, Validity validity, const GraphLimits& limits) {
    // A mutation that would break a valid graph is undone and another tried.
    for (int attempt = 0; attempt < 16; ++attempt) {
        PlanarGraph candidate = g;
        const Outcome made = one_mutation(candidate, rng, validity, limits);
        if (made == Outcome::None) continue;
        if (validity == Validity::Keep && made == Outcome::Check && !still_valid(candidate, g)) continue;
        g = std::move(candidate);
        return true;
    }
    return false;
}

bool cross_over(PlanarGraph& g, const PlanarGraph& other, gen::Rng& rng, Validity validity, const GraphLimits& limits) {
    return insert_component(g, other, rng, validity, limits);
}

}  // namespace dcel::fuzz
