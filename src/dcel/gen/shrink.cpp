// Shrinking: smaller valid graphs derived from a valid one, most aggressive
// first. Dropping edges or vertices keeps a graph valid (a subset of
// non-crossing segments and distinct points is still one), so those
// candidates need no check. Moving points can create contacts, so every
// snapped candidate is checked by brute force: the whole graph for a global
// snap, the moved vertex against everything for a single one.
//
// Termination: every candidate is smaller in (edges, vertices, non-integer
// coordinates, coordinate magnitudes), compared in that order; the last part
// only ever decreases pointwise (no coordinate grows, one shrinks).
#include <algorithm>
#include <cmath>
#include <map>

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
// remaining vertices keep their order and are renumbered.
PlanarGraph without_vertices(const PlanarGraph& g, const std::vector<char>& drop) {
    PlanarGraph out;
    std::vector<Index> new_id(g.vertices.size(), kNoIndex);
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        if (drop[v] != 0) continue;
        new_id[v] = static_cast<Index>(out.vertices.size());
        out.vertices.push_back(g.vertices[v]);
    }
    for (const GraphEdge& e : g.edges) {
        if (drop[e.u.index()] == 0 && drop[e.v.index()] == 0) {
            out.edges.push_back({VertexId(new_id[e.u.index()]), VertexId(new_id[e.v.index()])});
        }
    }
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

}  // namespace

std::vector<PlanarGraph> shrink_candidates(const PlanarGraph& g) {
    std::vector<PlanarGraph> out;
    const std::size_t e = g.edges.size();
    const std::size_t n = g.vertices.size();
    if (n == 0) return out;
    out.emplace_back();  // the empty graph
    // Edges: all of them, then halves, quarters, ..., single edges.
    for (std::size_t chunk = e; chunk >= 1; chunk /= 2) {
        for (std::size_t begin = 0; begin < e; begin += chunk)
            out.push_back(without_edges(g, begin, std::min(e, begin + chunk)));
        if (chunk == 1) break;
    }
    // Vertices: every isolated one at once, then each vertex with its edges.
    std::vector<char> isolated(n, 1);
    for (const GraphEdge& ge : g.edges) isolated[ge.u.index()] = isolated[ge.v.index()] = 0;
    if (std::count(isolated.begin(), isolated.end(), 1) > 1) out.push_back(without_vertices(g, isolated));
    for (std::size_t v = 0; v < n; ++v) {
        std::vector<char> drop(n, 0);
        drop[v] = 1;
        out.push_back(without_vertices(g, drop));
    }
    // Global snaps, each checked by brute force.
    const std::size_t fractions = non_integers(g);
    auto consider = [&](PlanarGraph c) {
        if ((non_integers(c) < fractions || (non_integers(c) == fractions && magnitudes_shrank(g, c))) && !find_problem(c)) {
            out.push_back(std::move(c));
        }
    };
    if (std::optional<PlanarGraph> s = scaled_to_integers(g)) consider(std::move(*s));
    consider(ranks(g));
    PlanarGraph rounded = g;
    for (Point& p : rounded.vertices) p = {std::round(p.x), std::round(p.y)};
    consider(std::move(rounded));
    PlanarGraph half = g;
    for (Point& p : half.vertices) p = {is_integer(p.x) ? halved(p.x) : p.x, is_integer(p.y) ? halved(p.y) : p.y};
    consider(std::move(half));
    // One vertex at a time: round a fractional point, or halve an integer
    // one's coordinates (both, or one of them).
    for (Index v = 0; v < n; ++v) {
        const Point p = g.vertices[v];
        std::vector<Point> targets;
        if (!is_integer(p.x) || !is_integer(p.y)) {
            targets.push_back({std::round(p.x), std::round(p.y)});
        } else {
            targets = {{halved(p.x), halved(p.y)}, {halved(p.x), p.y}, {p.x, halved(p.y)}};
        }
        for (const Point target : targets) {
            if (target == p) continue;
            PlanarGraph c = g;
            c.vertices[v] = target;
            const bool smaller = non_integers(c) < fractions || magnitudes_shrank(g, c);
            if (smaller && move_is_valid(c, v)) out.push_back(std::move(c));
        }
    }
    return out;
}

PlanarGraph shrink(PlanarGraph g, const std::function<bool(const PlanarGraph&)>& still_fails, std::size_t max_steps) {
    std::size_t steps = 0;
    for (bool progress = true; progress;) {
        progress = false;
        for (PlanarGraph& c : shrink_candidates(g)) {
            if (steps++ >= max_steps) return g;
            if (still_fails(c)) {
                g = std::move(c);
                progress = true;
                break;
            }
        }
    }
    return g;
}

}  // namespace dcel::gen
