#include "dcel/geometry/directions.hpp"

#include <cmath>

#include "dcel/geometry/exact_sum.hpp"

namespace dcel::detail {
namespace {

constexpr double kEpsilon = 0x1p-53;
// Each of the four rounded differences and the two products carries a
// relative error of at most eps, and the final subtraction one more: the
// computed determinant is within (4 eps + O(eps^2)) * (|l| + |r|) of the
// exact one. 8 eps is a safe margin. Below 2^-900 underflow could matter.
constexpr double kFilterBound = 8 * kEpsilon;
constexpr double kFilterMinimum = 0x1p-900;

// 0 when the direction p -> q has angle in [0, pi), else 1 (as angular_half).
int half_of(Point p, Point q) { return (q.y > p.y || (q.y == p.y && q.x > p.x)) ? 0 : 1; }

}  // namespace

Sign cross_sign(Point p1, Point q1, Point p2, Point q2) {
    const double l = (q1.x - p1.x) * (q2.y - p2.y);
    const double r = (q1.y - p1.y) * (q2.x - p2.x);
    const double det = l - r;
    const double magnitude = std::fabs(l) + std::fabs(r);
    if (magnitude >= kFilterMinimum && std::isfinite(magnitude) && std::fabs(det) > kFilterBound * magnitude) {
        return sign_of(det);
    }
    // (q1x - p1x)(q2y - p2y) - (q1y - p1y)(q2x - p2x), expanded into products
    // of input coordinates, each exact in ExactSum.
    ExactSum sum;
    sum.add_product(q1.x, q2.y);
    sum.subtract_product(q1.x, p2.y);
    sum.subtract_product(p1.x, q2.y);
    sum.add_product(p1.x, p2.y);
    sum.subtract_product(q1.y, q2.x);
    sum.add_product(q1.y, p2.x);
    sum.add_product(p1.y, q2.x);
    sum.subtract_product(p1.y, p2.x);
    return sum.sign();
}

Sign compare_direction(Point p1, Point q1, Point p2, Point q2) {
    const int h1 = half_of(p1, q1);
    const int h2 = half_of(p2, q2);
    if (h1 != h2) return h1 < h2 ? Sign::Negative : Sign::Positive;
    // Within one half-plane the two differ by less than pi: a counterclockwise
    // turn from the first to the second means the first comes first.
    return -cross_sign(p1, q1, p2, q2);
}

bool strictly_between_ccw(Direction s, Direction m, Direction r) {
    auto cmp = [](Direction x, Direction y) { return compare_direction(x.from, x.to, y.from, y.to); };
    const Sign sr = cmp(s, r);
    if (sr == Sign::Zero) return cmp(s, m) != Sign::Zero;  // a full turn: all but s itself
    const bool after_s = cmp(s, m) == Sign::Negative;
    const bool before_r = cmp(m, r) == Sign::Negative;
    // Without wrapping past east (s before r) m must be after s and before r;
    // when the wedge wraps past east, either will do.
    return sr == Sign::Negative ? (after_s && before_r) : (after_s || before_r);
}

}  // namespace dcel::detail
