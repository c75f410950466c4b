#include "support/exact_oracle.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

namespace dcel::props {
namespace {

__extension__ typedef __int128 Wide;  // __extension__: no -Wpedantic warning

bool fits_wide(double v) { return std::fabs(v) < 0x1p62 && std::trunc(v) == v; }

int sign(const Rational& r) { return r > 0 ? 1 : (r < 0 ? -1 : 0); }

// Coordinates compared exactly (doubles compare exactly; -0.0 == 0.0).
int compare(double a, double b) { return a < b ? -1 : (a > b ? 1 : 0); }

bool between(double lo, double x, double hi) { return std::min(lo, hi) <= x && x <= std::max(lo, hi); }

}  // namespace

Rational exact(double v) { return Rational(v); }

int orient_sign(Point a, Point b, Point c) {
    if (fits_wide(a.x) && fits_wide(a.y) && fits_wide(b.x) && fits_wide(b.y) && fits_wide(c.x) && fits_wide(c.y)) {
        const Wide acx = static_cast<Wide>(static_cast<long long>(a.x)) - static_cast<long long>(c.x);
        const Wide acy = static_cast<Wide>(static_cast<long long>(a.y)) - static_cast<long long>(c.y);
        const Wide bcx = static_cast<Wide>(static_cast<long long>(b.x)) - static_cast<long long>(c.x);
        const Wide bcy = static_cast<Wide>(static_cast<long long>(b.y)) - static_cast<long long>(c.y);
        const Wide det = acx * bcy - acy * bcx;
        return det > 0 ? 1 : (det < 0 ? -1 : 0);
    }
    const Rational det = (exact(a.x) - exact(c.x)) * (exact(b.y) - exact(c.y)) -
                         (exact(a.y) - exact(c.y)) * (exact(b.x) - exact(c.x));
    return sign(det);
}

int angle_order(Point centre, Point a, Point b) {
    // Quadrants 0..3, counterclockwise from east: [0, 90), [90, 180), ...
    auto quadrant = [&](Point p) {
        const int dx = compare(p.x, centre.x);
        const int dy = compare(p.y, centre.y);
        if (dx > 0 && dy >= 0) return 0;
        if (dx <= 0 && dy > 0) return 1;
        if (dx < 0 && dy <= 0) return 2;
        return 3;
    };
    const int qa = quadrant(a), qb = quadrant(b);
    if (qa != qb) return qa < qb ? -1 : 1;
    return -orient_sign(centre, a, b);  // within a quadrant: a before b when b is counterclockwise of a
}

Rational twice_area(const std::vector<Point>& ring) {
    Rational sum = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point a = ring[i], b = ring[(i + 1) % ring.size()];
        sum += exact(a.x) * exact(b.y) - exact(a.y) * exact(b.x);
    }
    return sum;
}

bool is_nearest_double(double v, const Rational& exact) {
    constexpr double kMax = std::numeric_limits<double>::max();
    const Rational overflow = Rational(kMax) + Rational(std::ldexp(1.0, 970));  // halfway to 2^1024
    if (std::isinf(v)) return v > 0 ? exact >= overflow : exact <= -overflow;
    if (!std::isfinite(v)) return false;
    const Rational error = abs(Rational(v) - exact);
    for (const double neighbour : {std::nextafter(v, HUGE_VAL), std::nextafter(v, -HUGE_VAL)}) {
        if (std::isinf(neighbour)) continue;  // beyond v lies overflow, checked above by symmetry
        const Rational other = abs(Rational(neighbour) - exact);
        if (other < error) return false;
        // A tie goes to the even significand: the last bit of the pattern.
        if (other == error && (std::bit_cast<std::uint64_t>(std::fabs(v)) & 1U) != 0) return false;
    }
    return std::fabs(v) < kMax || abs(exact) < overflow;
}

bool strictly_inside(Point p, const std::vector<Point>& ring) {
    int winding_parity = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point a = ring[i], b = ring[(i + 1) % ring.size()];
        const bool a_above = a.y > p.y, b_above = b.y > p.y;
        if (a_above == b_above) continue;      // does not straddle the ray's line
        if (a.x < p.x && b.x < p.x) continue;  // wholly to the left
        // The edge crosses the ray when p is on the edge's left going up,
        // or on its right going down.
        const int o = orient_sign(a, b, p);
        if ((b_above && o > 0) || (!b_above && o < 0)) winding_parity ^= 1;
    }
    return winding_parity != 0;
}

bool strictly_on_segment(Point a, Point b, Point p) {
    if (p == a || p == b) return false;
    return between(a.x, p.x, b.x) && between(a.y, p.y, b.y) && orient_sign(a, b, p) == 0;
}

Meeting meeting(Point a, Point b, Point c, Point d) {
    const bool same_ends = (a == c && b == d) || (a == d && b == c);
    if (same_ends) return Meeting::Same;
    const int o1 = orient_sign(a, b, c), o2 = orient_sign(a, b, d);
    const int o3 = orient_sign(c, d, a), o4 = orient_sign(c, d, b);
    if (o1 == 0 && o2 == 0) {
        // Collinear: count the points of one strictly inside the other.
        const int inside = strictly_on_segment(a, b, c) + strictly_on_segment(a, b, d) + strictly_on_segment(c, d, a) +
                           strictly_on_segment(c, d, b);
        if (inside > 0) return Meeting::Overlap;
        const bool shared = a == c || a == d || b == c || b == d;
        return shared ? Meeting::SharedEndpoint : Meeting::None;
    }
    if (o1 * o2 < 0 && o3 * o4 < 0) return Meeting::Crossing;
    if (strictly_on_segment(a, b, c) || strictly_on_segment(a, b, d) || strictly_on_segment(c, d, a) ||
        strictly_on_segment(c, d, b)) {
        return Meeting::Touch;
    }
    const bool shared = a == c || a == d || b == c || b == d;
    return shared ? Meeting::SharedEndpoint : Meeting::None;
}

Defects find_defects(const PlanarGraph& g) {
    Defects out;
    auto pt = [&](VertexId v) { return g.vertices[v.index()]; };
    std::map<std::pair<double, double>, Index> at;
    for (Index v = 0; v < g.vertices.size(); ++v) {
        const auto [it, fresh] = at.emplace(std::pair{g.vertices[v].x, g.vertices[v].y}, v);
        if (!fresh) out.duplicate_points.emplace_back(it->second, v);
    }
    std::map<std::pair<Index, Index>, Index> pairs;
    for (Index k = 0; k < g.edges.size(); ++k) {
        const Index u = g.edges[k].u.index(), v = g.edges[k].v.index();
        const std::pair<Index, Index> key{std::min(u, v), std::max(u, v)};
        const auto [it, fresh] = pairs.emplace(key, k);
        if (!fresh) out.duplicate_edges.emplace_back(it->second, k);
    }
    for (Index k = 0; k < g.edges.size(); ++k) {
        const Point a = pt(g.edges[k].u), b = pt(g.edges[k].v);
        for (Index j = k + 1; j < g.edges.size(); ++j) {
            const Point c = pt(g.edges[j].u), d = pt(g.edges[j].v);
            // Disjoint bounding boxes: the segments cannot meet.
            if (std::max(c.x, d.x) < std::min(a.x, b.x) || std::max(a.x, b.x) < std::min(c.x, d.x) ||
                std::max(c.y, d.y) < std::min(a.y, b.y) || std::max(a.y, b.y) < std::min(c.y, d.y)) {
                continue;
            }
            const Meeting m = meeting(a, b, c, d);
            if (m != Meeting::None && m != Meeting::SharedEndpoint) out.edge_pairs.push_back({k, j, m});
        }
        for (Index v = 0; v < g.vertices.size(); ++v) {
            if (strictly_on_segment(a, b, g.vertices[v])) out.vertex_in_edge.emplace_back(v, k);
        }
    }
    return out;
}

}  // namespace dcel::props
