// Exact plane geometry for the oracles, independent of src/dcel/geometry.
//
// One idea throughout: convert exactly, then compute exactly. Every finite
// double is an integer times a power of two, so the operands of a cross
// product, scaled by one common power of two, are integers. When those
// integers fit in 62 bits, the products and their difference fit in a
// 128-bit integer, which decides the sign at once; up to 125 bits, the
// differences still fit one and the products are compared as 256-bit
// numbers; beyond (exponents far apart: subnormals beside ordinary values,
// values near DBL_MAX) GMP's arbitrary-precision integers do it.
// Nothing here uses error bounds, expansions or the library's predicates
// (orient2d, compare_angle, segment_contact, ExactSum), so a bug there
// cannot hide here. Values that are not signs (areas, positions along a
// line) are GMP rationals.
#pragma once

#include <boost/multiprecision/gmp.hpp>
#include <cstdint>
#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel::oracle {

using BigInt = boost::multiprecision::mpz_int;
using Rational = boost::multiprecision::mpq_rational;

// The exact value of a finite double.
[[nodiscard]] Rational exact(double v);
[[nodiscard]] int sign_of(const Rational& r);

// Sign (-1, 0, +1) of the cross product (q1 - p1) x (q2 - p2).
[[nodiscard]] int cross_sign(Point p1, Point q1, Point p2, Point q2);

// Sign of (b - a) x (c - a): +1 when a, b, c turn counterclockwise.
[[nodiscard]] int orientation(Point a, Point b, Point c);

// The direction from p1 to q1 against the direction from p2 to q2,
// counterclockwise from east: the upper half-plane [0, pi) (dy > 0, or dy == 0
// and dx > 0, decided by comparing coordinates) comes first, and within a
// half-plane the cross product decides. -1 when p1->q1 comes first, 0 when
// they point the same way. Requires p1 != q1 and p2 != q2.
[[nodiscard]] int direction_order(Point p1, Point q1, Point p2, Point q2);

// The angular order of c->a and c->b around c (direction_order from c).
[[nodiscard]] int angle_order(Point centre, Point a, Point b);

// Twice the signed area of a closed polygon (counterclockwise positive).
[[nodiscard]] Rational twice_area(const std::vector<Point>& ring);

// Winding number of the closed polygon ring around p, which must not lie on
// it: +1 per counterclockwise turn. Weakly simple rings (a dangling edge
// walked there and back) count correctly, since such edges cancel.
[[nodiscard]] int winding_number(Point p, const std::vector<Point>& ring);

// Is v the double nearest to `exact` (ties to even; +-inf past the point
// where rounding overflows)? Decided in rationals, so it checks a claim of
// correct rounding without trusting any conversion.
[[nodiscard]] bool is_nearest_double(double v, const Rational& exact);

// p on the closed segment ab and different from both ends.
[[nodiscard]] bool strictly_on_segment(Point a, Point b, Point p);

// How two closed segments ab and cd (a != b, c != d) meet: not at all, at
// one shared endpoint, crossing at a point inside both, an endpoint of one
// inside the other (touch), collinear sharing more than a point (overlap),
// or the same segment.
enum class Meeting { None, SharedEndpoint, Crossing, Touch, Overlap, Same };
[[nodiscard]] Meeting meeting(Point a, Point b, Point c, Point d);

// Where p lies along a->b (a != b), as t with p = a + t (b - a) when p is on
// the line (its projection otherwise): 0 at a, 1 at b.
[[nodiscard]] Rational parameter_of_point(Point a, Point b, Point p);

// Where the line through c and d crosses the line a->b (not parallel), as t
// with the crossing at a + t (b - a).
[[nodiscard]] Rational parameter_of_crossing(Point a, Point b, Point c, Point d);

// The points of one graph, for many exact tests among them by index: when
// one common power of two turns every coordinate into an integer of at
// most 62 bits (the usual case), the integers are kept and each
// orientation is two 128-bit products; otherwise (or with a non-finite
// coordinate) each test takes the per-call route above. The same answers
// either way. Holds a reference to the points.
class ExactPoints {
public:
    explicit ExactPoints(const std::vector<Point>& points);
    [[nodiscard]] Point point(Index i) const { return (*points_)[i]; }
    [[nodiscard]] int orientation(Index a, Index b, Index c) const;
    [[nodiscard]] int angle_order(Index centre, Index a, Index b) const;
    [[nodiscard]] bool strictly_on_segment(Index a, Index b, Index p) const;
    [[nodiscard]] Meeting meeting(Index a, Index b, Index c, Index d) const;

private:
    const std::vector<Point>* points_;
    bool integers_ = false;
    std::vector<std::int64_t> x_, y_;  // the scaled coordinates, when integers_
};

}  // namespace dcel::oracle
