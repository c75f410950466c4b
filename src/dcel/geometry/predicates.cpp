#include "dcel/geometry/predicates.hpp"

#include <algorithm>
#include <cmath>

#include "dcel/geometry/exact_sum.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::ExactSum;
namespace {

using detail::kOrientFilterBound;
using detail::kOrientFilterMinimum;

// Knuth's TwoSum: s + t == a + b exactly (no overflow assumed).
inline void two_sum(double a, double b, double& s, double& t) {
    s = a + b;
    const double bv = s - a;
    const double av = s - bv;
    t = (a - av) + (b - bv);
}

// The exact sign of a + b + c + d, for finite terms of magnitude below 2^1020
// (so no partial sum overflows). Sums into a nonoverlapping expansion with
// TwoSum; the sign of such an expansion is that of its largest nonzero part.
Sign sign_of_sum4(double a, double b, double c, double d) {
    double e[4] = {a, 0, 0, 0};
    int n = 1;
    for (const double x : {b, c, d}) {
        double q = x;
        for (int i = 0; i < n; ++i) {
            double s = 0;
            double t = 0;
            two_sum(q, e[i], s, t);
            e[i] = t;
            q = s;
        }
        e[n++] = q;
    }
    for (int i = n - 1; i >= 0; --i) {
        if (e[i] != 0) return sign_of(e[i]);
    }
    return Sign::Zero;
}

// True when a - b was computed exactly (the rounding tail is zero).
inline bool exact_difference(double a, double b, double diff) {
    const double bv = a - diff;
    const double av = diff + bv;
    return (a - av) + (bv - b) == 0;
}

// FMA recovers the rounding error of p = x * y exactly when p is exactly zero
// (a factor is zero) or lies well inside the normal range. A product that
// underflowed to zero from nonzero factors is not safe.
inline bool product_is_safe(double x, double y, double p) {
    if (x == 0 || y == 0) return true;
    const double m = std::fabs(p);
    return m >= 0x1p-960 && m <= 0x1p1020;
}

}  // namespace

Sign orient2d_exact(Point a, Point b, Point c) {
    ExactSum sum;
    sum.add_product(a.x, b.y);
    sum.subtract_product(a.x, c.y);
    sum.subtract_product(a.y, b.x);
    sum.add_product(a.y, c.x);
    sum.add_product(b.x, c.y);
    sum.subtract_product(b.y, c.x);
    return sum.sign();
}

Sign orient2d_slow(Point a, Point b, Point c) {
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
    if (detsum >= kOrientFilterMinimum && std::isfinite(detsum) && std::fabs(det) > kOrientFilterBound * detsum) {
        return sign_of(det);
    }
    // Stage B: when the four differences are exact, the determinant is
    // detleft + e1 - detright - e2 with FMA-recovered rounding errors e1, e2.
    if (std::isfinite(det) && exact_difference(a.x, c.x, acx) && exact_difference(b.x, c.x, bcx) &&
        exact_difference(a.y, c.y, acy) && exact_difference(b.y, c.y, bcy) && product_is_safe(acx, bcy, detleft) &&
        product_is_safe(acy, bcx, detright)) {
        const double e1 = std::fma(acx, bcy, -detleft);
        const double e2 = std::fma(acy, bcx, -detright);
        return sign_of_sum4(detleft, e1, -detright, -e2);
    }
    return orient2d_exact(a, b, c);
}

int angular_half(Point centre, Point p) { return (p.y > centre.y || (p.y == centre.y && p.x > centre.x)) ? 0 : 1; }

Sign compare_angle(Point centre, Point a, Point b) {
    const int ha = angular_half(centre, a);
    const int hb = angular_half(centre, b);
    if (ha != hb) return ha < hb ? Sign::Negative : Sign::Positive;
    // Within one half-plane the angles differ by less than pi, so the turn
    // from c->a to c->b decides: counterclockwise means c->a comes first.
    return -orient2d(centre, a, b);
}

bool on_segment(Point a, Point b, Point p) {
    if (orient2d(a, b, p) != Sign::Zero) return false;
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y && p.y <= std::max(a.y, b.y);
}

}  // namespace dcel
