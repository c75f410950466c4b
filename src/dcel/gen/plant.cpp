// plant(): one defect added to a valid graph. Each attempt builds a new
// segment around a chosen edge e and keeps it only when the brute-force check
// confirms the intended contact with e, and no contact with anything else, so
// the defect is exactly the one asked for.
#include <cmath>
#include <iterator>

#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/gen/rng.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::gen {
namespace {

struct Attempt {
    std::vector<Point> new_points;               // appended as new vertices
    std::vector<std::pair<int, int>> new_edges;  // ids: >= 0 existing vertex, < 0 new point -(i+1)
};

bool point_free(const PlanarGraph& g, Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    for (const Point& q : g.vertices) {
        if (q == p) return false;
    }
    return true;
}

// A point strictly inside segment ab, exactly on it, or nothing.
std::optional<Point> interior_point(Point a, Point b, Rng& rng) {
    static const double kFractions[] = {0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875};
    const std::size_t first = rng.below(std::size(kFractions));
    for (std::size_t i = 0; i < std::size(kFractions); ++i) {
        const double t = kFractions[(first + i) % std::size(kFractions)];
        const Point p{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
        if (!(p == a) && !(p == b) && on_closed_segment(a, b, p)) return p;
    }
    return std::nullopt;
}

bool proper_crossing(Point p, Point q, Point a, Point b) {
    return to_int(orient2d(p, q, a)) * to_int(orient2d(p, q, b)) < 0 &&
           to_int(orient2d(a, b, p)) * to_int(orient2d(a, b, q)) < 0;
}

// Apply the attempt and check that it adds exactly the contacts wanted: the
// new edges meet edge e (and nothing else) other than at shared endpoints.
std::optional<PlanarGraph> try_attempt(const PlanarGraph& g, std::size_t e, const Attempt& a, Defect d) {
    PlanarGraph out = g;
    const auto base = static_cast<int>(g.vertices.size());
    for (const Point& p : a.new_points) {
        if (!point_free(out, p)) return std::nullopt;
        out.vertices.push_back(p);
    }
    auto id = [&](int v) { return VertexId(static_cast<Index>(v >= 0 ? v : base - v - 1)); };
    const std::size_t old_edges = g.edges.size();
    for (const auto& [u, v] : a.new_edges) {
        if (id(u) == id(v)) return std::nullopt;
        out.edges.push_back({id(u), id(v)});
    }
    auto pt = [&](VertexId v) { return out.vertices[v.index()]; };
    const GraphEdge target = g.edges[e];
    for (std::size_t k = old_edges; k < out.edges.size(); ++k) {
        const Point p = pt(out.edges[k].u);
        const Point q = pt(out.edges[k].v);
        for (std::size_t j = 0; j < old_edges; ++j) {
            const bool conflict = segments_conflict(p, q, pt(out.edges[j].u), pt(out.edges[j].v));
            if (conflict != (j == e)) return std::nullopt;
        }
        // The contact must be of the kind asked for: rounding may have
        // turned an overlap into a touch, or a crossing into a touch.
        const bool collinear = orient2d(pt(target.u), pt(target.v), p) == Sign::Zero &&
                               orient2d(pt(target.u), pt(target.v), q) == Sign::Zero;
        if (d == Defect::Crossing && !proper_crossing(p, q, pt(target.u), pt(target.v))) return std::nullopt;
        if ((d == Defect::Overlap) != collinear) return std::nullopt;
        // Old vertices on a new edge: only e's own endpoints (an overlap may
        // run past them).
        for (Index w = 0; w < static_cast<Index>(base); ++w) {
            const VertexId v(w);
            if (v == out.edges[k].u || v == out.edges[k].v || v == target.u || v == target.v) continue;
            if (on_closed_segment(p, q, g.vertices[w])) return std::nullopt;
        }
    }
    // New points must not lie on old edges other than e.
    for (const Point& np : a.new_points) {
        for (std::size_t j = 0; j < old_edges; ++j) {
            if (j != e && on_closed_segment(pt(out.edges[j].u), pt(out.edges[j].v), np)) return std::nullopt;
        }
    }
    if (!find_problem(out)) return std::nullopt;  // the defect must be real
    return out;
}

// Candidate segments for each defect around edge ab (a and b are existing
// vertices ia, ib). Several sizes, since rounding may spoil one.
std::vector<Attempt> attempts(Defect d, const PlanarGraph& g, std::size_t e, Rng& rng) {
    const int ia = static_cast<int>(g.edges[e].u.index());
    const int ib = static_cast<int>(g.edges[e].v.index());
    const Point a = g.vertices[static_cast<std::size_t>(ia)];
    const Point b = g.vertices[static_cast<std::size_t>(ib)];
    const Point normal{-(b.y - a.y), b.x - a.x};
    std::vector<Attempt> out;
    const std::optional<Point> inside = interior_point(a, b, rng);
    for (const int shift : {1, 3, 6, 10, 20, 40}) {
        const double s = std::ldexp(1.0, -shift);
        switch (d) {
            case Defect::Crossing: {
                // Through a point near the middle, across the line of e.
                const Point m = inside ? *inside : Point{a.x * 0.5 + b.x * 0.5, a.y * 0.5 + b.y * 0.5};
                out.push_back(
                    {{{m.x + normal.x * s, m.y + normal.y * s}, {m.x - normal.x * s, m.y - normal.y * s}}, {{-1, -2}}});
                break;
            }
            case Defect::Touch: {
                if (!inside) return out;
                const Point m = *inside;
                const double side = rng.chance(1, 2) ? s : -s;
                if (shift == 1 && rng.chance(1, 4)) out.push_back({{m}, {}});  // an isolated vertex on e
                out.push_back({{m, {m.x + normal.x * side, m.y + normal.y * side}}, {{-1, -2}}});
                break;
            }
            case Defect::Overlap: {
                if (!inside) return out;
                const Point m = *inside;
                switch (rng.below(3)) {
                    case 0: out.push_back({{m}, {{-1, rng.chance(1, 2) ? ia : ib}}}); break;  // along e from an end
                    case 1: {
                        const std::optional<Point> m2 = interior_point(a, m, rng);
                        if (m2) out.push_back({{*m2, m}, {{-1, -2}}});  // strictly inside e
                        break;
                    }
                    default: {
                        // From inside e to past its end b, on the same line.
                        const Point past{b.x + (b.x - a.x) * s, b.y + (b.y - a.y) * s};
                        out.push_back({{m, past}, {{-1, -2}}});
                        break;
                    }
                }
                break;
            }
        }
    }
    return out;
}

}  // namespace

std::optional<PlanarGraph> plant(const PlanarGraph& g, Defect d, std::uint64_t seed) {
    if (g.edges.empty()) return std::nullopt;
    Rng rng(seed);
    std::vector<std::size_t> order(g.edges.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    rng.shuffle(order);
    // A handful of edges is plenty: most edges admit every defect.
    for (std::size_t i = 0; i < order.size() && i < 8; ++i) {
        for (const Attempt& a : attempts(d, g, order[i], rng)) {
            if (std::optional<PlanarGraph> out = try_attempt(g, order[i], a, d)) {
                // Put the new edges at a random place among the old ones, so
                // the defect is not always the last edge.
                std::vector<GraphEdge> added(out->edges.begin() + static_cast<std::ptrdiff_t>(g.edges.size()),
                                             out->edges.end());
                out->edges.resize(g.edges.size());
                const auto where = static_cast<std::ptrdiff_t>(rng.below(g.edges.size() + 1));
                out->edges.insert(out->edges.begin() + where, added.begin(), added.end());
                return out;
            }
        }
    }
    return std::nullopt;
}

}  // namespace dcel::gen
