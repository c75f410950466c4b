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

#include <cmath>

#include "dcel/geometry/point.hpp"
#include "dcel/geometry/sign.hpp"

namespace dcel {

// The filter's two stages are inline (orient2d is the inner loop of the ring
// sorts and the sweep); everything the filter cannot certify goes to
// orient2d_slow, which redoes the whole computation.
[[nodiscard]] inline Sign orient2d(Point a, Point b, Point c);

// The exact stages alone (FMA stage, then ExactSum): what orient2d calls when
// its filter cannot decide. Correct for every input, just slower.
[[nodiscard]] Sign orient2d_slow(Point a, Point b, Point c);

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

namespace detail {
// Shewchuk's ccwerrboundA, (3 + 16 eps) eps with eps = 2^-53: it bounds the
// error of the filter's determinant relative to |detleft| + |detright|.
inline constexpr double kOrientFilterBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
// Below this the products may underflow. Above it, any absolute error from
// underflow (at most 2^-1074 a product) is smaller than the 16 eps^2 slack in
// the bound, so the relative bound stays valid.
inline constexpr double kOrientFilterMinimum = 0x1p-900;
}  // namespace detail

inline Sign orient2d(Point a, Point b, Point c) {
    const double acx = a.x - c.x;
    const double bcx = b.x - c.x;
    const double acy = a.y - c.y;
    const double bcy = b.y - c.y;
    // A rounded difference is zero exactly when the true one is, so when each
    // product has a zero factor the determinant is exactly zero. This is the
    // common "c is an endpoint" case, which the filter cannot certify.
    if ((acx == 0 || bcy == 0) && (acy == 0 || bcx == 0)) return Sign::Zero;
    const double detleft = acx * bcy;
    const double detright = acy * bcx;
    const double det = detleft - detright;
    const double detsum = std::fabs(detleft) + std::fabs(detright);
    if (detsum >= detail::kOrientFilterMinimum && std::isfinite(detsum) &&
        std::fabs(det) > detail::kOrientFilterBound * detsum) {
        return sign_of(det);
    }
    return orient2d_slow(a, b, c);
}

}  // namespace dcel
