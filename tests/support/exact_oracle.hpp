// Independent exact arithmetic for the properties: the oracles that the
// library is judged against. Nothing here calls the library's predicates
// (orient2d, compare_angle, segment_contact, ExactSum): signs come from
// 128-bit integers when every coordinate is an integer below 2^62, and from
// boost::multiprecision::cpp_rational otherwise.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/graph.hpp"

namespace dcel::props {

using Rational = boost::multiprecision::cpp_rational;

[[nodiscard]] Rational exact(double v);

// Sign (-1, 0, 1) of the determinant | a-c  b-c |: positive when a, b, c turn
// counterclockwise.
[[nodiscard]] int orient_sign(Point a, Point b, Point c);

// Angular order around a centre, counterclockwise from east, decided by the
// quadrant of each direction and then the sign of a cross product. Negative
// when c->a comes first, 0 when they point the same way. Requires a, b != c.
[[nodiscard]] int angle_order(Point centre, Point a, Point b);

// Twice the signed area of a closed polygon (counterclockwise positive).
[[nodiscard]] Rational twice_area(const std::vector<Point>& ring);

// Is v the double nearest to `exact` (ties to even; +-inf past the point
// where rounding overflows)? Decided in rationals, so it checks a claim of
// correct rounding without trusting any conversion.
[[nodiscard]] bool is_nearest_double(double v, const Rational& exact);

// Is p strictly inside the closed polygon ring? p must not lie on it. Counts
// the crossings of the ray from p towards +x (half-open in y), so weakly
// simple rings (a dangling edge walked there and back) count correctly.
[[nodiscard]] bool strictly_inside(Point p, const std::vector<Point>& ring);

// How two closed segments meet.
enum class Meeting { None, SharedEndpoint, Crossing, Touch, Overlap, Same };
[[nodiscard]] Meeting meeting(Point a, Point b, Point c, Point d);

// p strictly inside the segment ab (on it and not an endpoint).
[[nodiscard]] bool strictly_on_segment(Point a, Point b, Point p);

// Every defect of g by brute force: duplicate points, duplicate edges, pairs
// of edges meeting other than at a shared endpoint, vertices inside edges.
struct Defects {
    std::vector<std::pair<Index, Index>> duplicate_points;
    std::vector<std::pair<Index, Index>> duplicate_edges;
    struct EdgePair {
        Index e1, e2;
        Meeting how;
    };
    std::vector<EdgePair> edge_pairs;                     // e1 < e2, how != None/SharedEndpoint
    std::vector<std::pair<Index, Index>> vertex_in_edge;  // (vertex, edge)
    [[nodiscard]] bool empty() const {
        return duplicate_points.empty() && duplicate_edges.empty() && edge_pairs.empty() && vertex_in_edge.empty();
    }
};
[[nodiscard]] Defects find_defects(const PlanarGraph& g);

}  // namespace dcel::props
