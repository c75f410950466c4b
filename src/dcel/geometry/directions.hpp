// Exact signs for directions given as point pairs: the direction of p -> q.
// Used where a direction does not start at an input point (a stabbing line
// seen from a vertex), so orient2d alone cannot express it.
#pragma once

#include "dcel/geometry/point.hpp"
#include "dcel/geometry/sign.hpp"

namespace dcel::detail {

// The sign of the cross product (q1 - p1) x (q2 - p2): Positive when the
// second direction turns counterclockwise from the first (by less than pi).
// orient2d(a, b, c) == cross_sign(a, b, a, c). Exact for all finite doubles.
[[nodiscard]] Sign cross_sign(Point p1, Point q1, Point p2, Point q2);

// Directions ordered counterclockwise from east, as compare_angle orders
// them: Negative when p1 -> q1 comes first, Zero when both point the same way.
// Requires p1 != q1 and p2 != q2. compare_angle(c, a, b) ==
// compare_direction(c, a, c, b).
[[nodiscard]] Sign compare_direction(Point p1, Point q1, Point p2, Point q2);

// True when direction m lies strictly inside the wedge swept counterclockwise
// from direction s to direction r (a full turn when s and r point the same
// way). Each direction is a point pair; all three must be non-degenerate.
struct Direction {
    Point from;
    Point to;
};
[[nodiscard]] bool strictly_between_ccw(Direction s, Direction m, Direction r);

}  // namespace dcel::detail
