#include "dcel/geometry/line_order.hpp"

#include "dcel/geometry/directions.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::detail {

DirectedLine::DirectedLine(Point a, Point b) : a_(a), b_(b), lex_forward_(lex_less(a, b)) {}

Sign DirectedLine::side(Point p) const { return orient2d(a_, b_, p); }

// A point X + s (b - a) of L lies on side sign(s * cross(d - c, b - a)) of
// line(c, d), for X the crossing: ahead of X is the side of that cross product.
Sign DirectedLine::ahead_side(Point c, Point d) const { return cross_sign(c, d, a_, b_); }

Sign DirectedLine::point_vs_crossing(Point p, Point c, Point d) const {
    const Sign s = orient2d(c, d, p);
    if (s == Sign::Zero) return Sign::Zero;  // p is on L and on line(c, d): it is the crossing
    return s == ahead_side(c, d) ? Sign::Positive : Sign::Negative;
}

Sign DirectedLine::compare(const LineEvent& x, const LineEvent& y) const {
    if (!x.crossing && !y.crossing) {
        if (x.p == y.p) return Sign::Zero;
        // Points of one line are ordered along it by lex order, one way or the other.
        const bool x_first = lex_less(x.p, y.p) == lex_forward_;
        return x_first ? Sign::Negative : Sign::Positive;
    }
    if (!x.crossing) return point_vs_crossing(x.p, y.c, y.d);
    if (!y.crossing) return -point_vs_crossing(y.p, x.c, x.d);
    if ((x.c == y.c && x.d == y.d) || (x.c == y.d && x.d == y.c)) return Sign::Zero;
    // Does y's segment lie in a closed half-plane of line(x)? Then its
    // crossing is ahead of x's exactly when that half-plane is the one ahead.
    const Sign s1 = orient2d(x.c, x.d, y.c);
    const Sign s2 = orient2d(x.c, x.d, y.d);
    if (to_int(s1) * to_int(s2) >= 0) {
        const Sign where = s1 != Sign::Zero ? s1 : s2;
        return where == ahead_side(x.c, x.d) ? Sign::Negative : Sign::Positive;
    }
    // Otherwise y straddles line(x), so x lies in a closed half-plane of line(y).
    const Sign t1 = orient2d(y.c, y.d, x.c);
    const Sign t2 = orient2d(y.c, y.d, x.d);
    const Sign where = t1 != Sign::Zero ? t1 : t2;
    return where == ahead_side(y.c, y.d) ? Sign::Positive : Sign::Negative;
}

}  // namespace dcel::detail
