#include "dcel/gen/brute_force.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include "dcel/geometry/predicates.hpp"

namespace dcel::gen {
namespace {

struct Box {
    double x0, x1, y0, y1;
};
Box box(Point a, Point b) { return {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y)}; }
bool boxes_meet(const Box& p, const Box& q) { return p.x0 <= q.x1 && q.x0 <= p.x1 && p.y0 <= q.y1 && q.y0 <= p.y1; }

std::string point_text(Point p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; }

}  // namespace

bool on_closed_segment(Point a, Point b, Point p) {
    const Box bx = box(a, b);
    if (p.x < bx.x0 || p.x > bx.x1 || p.y < bx.y0 || p.y > bx.y1) return false;
    return orient2d(a, b, p) == Sign::Zero;
}

bool segments_conflict(Point a, Point b, Point c, Point d) {
    if (!boxes_meet(box(a, b), box(c, d))) return false;
    const bool ac = a == c, ad = a == d, bc = b == c, bd = b == d;
    if ((ac && bd) || (ad && bc)) return true;  // the same segment
    if (ac || ad || bc || bd) {
        // One shared point w; the others x (on ab) and y (on cd) meet the
        // other segment only if the two run along one line in one direction.
        const Point w = (ac || ad) ? a : b;
        const Point x = (ac || ad) ? b : a;
        const Point y = (ac || bc) ? d : c;
        if (orient2d(w, x, y) != Sign::Zero) return false;
        const bool x_after = w.x != x.x ? x.x > w.x : x.y > w.y;
        const bool y_after = w.x != y.x ? y.x > w.x : y.y > w.y;
        return x_after == y_after;
    }
    const int o1 = to_int(orient2d(a, b, c));
    const int o2 = to_int(orient2d(a, b, d));
    const int o3 = to_int(orient2d(c, d, a));
    const int o4 = to_int(orient2d(c, d, b));
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && on_closed_segment(a, b, c)) || (o2 == 0 && on_closed_segment(a, b, d)) ||
           (o3 == 0 && on_closed_segment(c, d, a)) || (o4 == 0 && on_closed_segment(c, d, b));
}

std::optional<std::string> find_problem(const PlanarGraph& g) {
    const std::size_t n = g.vertices.size();
    for (std::size_t v = 0; v < n; ++v) {
        const Point p = g.vertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return "vertex " + std::to_string(v) + " is not finite";
    }
    std::set<std::pair<double, double>> seen;  // -0.0 == 0.0, as the set compares with <
    for (std::size_t v = 0; v < n; ++v) {
        const Point p = g.vertices[v];
        if (!seen.insert({p.x, p.y}).second) return "two vertices at " + point_text(p);
    }
    std::set<std::pair<Index, Index>> pairs;
    for (std::size_t k = 0; k < g.edges.size(); ++k) {
        const GraphEdge& e = g.edges[k];
        if (e.u.index() >= n || e.v.index() >= n) return "edge " + std::to_string(k) + " names a missing vertex";
        if (e.u == e.v) return "edge " + std::to_string(k) + " is a self-loop";
        if (!pairs.insert(std::minmax(e.u.index(), e.v.index())).second) {
            return "edge " + std::to_string(k) + " duplicates another";
        }
    }
    for (std::size_t k = 0; k < g.edges.size(); ++k) {
        const Point a = g.vertices[g.edges[k].u.index()];
        const Point b = g.vertices[g.edges[k].v.index()];
        for (std::size_t j = k + 1; j < g.edges.size(); ++j) {
            const Point c = g.vertices[g.edges[j].u.index()];
            const Point d = g.vertices[g.edges[j].v.index()];
            if (segments_conflict(a, b, c, d)) {
                return "edges " + std::to_string(k) + " and " + std::to_string(j) + " meet other than at an endpoint";
            }
        }
        for (std::size_t v = 0; v < n; ++v) {
            if (VertexId(static_cast<Index>(v)) == g.edges[k].u || VertexId(static_cast<Index>(v)) == g.edges[k].v) {
                continue;
            }
            if (on_closed_segment(a, b, g.vertices[v])) {
                return "vertex " + std::to_string(v) + " lies on edge " + std::to_string(k);
            }
        }
    }
    return std::nullopt;
}

}  // namespace dcel::gen
