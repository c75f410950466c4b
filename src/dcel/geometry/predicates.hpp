// Exact geometric predicates on points with double coordinates.
//
// Convention (pinned by a test on a known triangle): orient2d(a, b, c) is
// Positive when a, b, c turn counterclockwise, Negative when clockwise, Zero
// when collinear. It is the sign of the determinant
//     | ax ay 1 |
//     | bx by 1 |
//     | cx cy 1 |
// computed exactly for every finite double input: a floating-point filter
// with a proven error bound decides most calls, an FMA-based stage handles
// exact differences, and ExactSum decides the rest. No epsilon, no atan2.
#pragma once

#include "dcel/geometry/point.hpp"
#include "dcel/geometry/sign.hpp"

namespace dcel {

[[nodiscard]] Sign orient2d(Point a, Point b, Point c);

// The same determinant by ExactSum alone: slower, simpler, used by tests.
[[nodiscard]] Sign orient2d_exact(Point a, Point b, Point c);

// Directions around a centre, ordered counterclockwise starting at the
// positive x axis: angle 0 (east) first, just below 2*pi last.
//   angular_half(c, p): 0 when the direction c->p has angle in [0, pi), else 1.
//   compare_angle(c, a, b): Negative when c->a comes first, Zero when c->a and
//   c->b point the same way, Positive when c->b comes first.
// Requires a != c and b != c.
[[nodiscard]] int angular_half(Point centre, Point p);
[[nodiscard]] Sign compare_angle(Point centre, Point a, Point b);

// True when p lies on the closed segment [a, b]; exact.
[[nodiscard]] bool on_segment(Point a, Point b, Point p);

}  // namespace dcel
