#include "dcel/geometry/segments.hpp"

#include "dcel/geometry/predicates.hpp"

namespace dcel::detail {

bool strictly_inside_segment(Point a, Point b, Point p) { return !(p == a) && !(p == b) && on_segment(a, b, p); }

Contact segment_contact(Point a, Point b, Point c, Point d) {
    const Sign o1 = orient2d(a, b, c);
    const Sign o2 = orient2d(a, b, d);
    if (o1 == Sign::Zero && o2 == Sign::Zero) {
        // Collinear: points on one line are ordered along it by lex order.
        const Point s1 = lex_less(a, b) ? a : b;
        const Point e1 = lex_less(a, b) ? b : a;
        const Point s2 = lex_less(c, d) ? c : d;
        const Point e2 = lex_less(c, d) ? d : c;
        if (lex_less(e1, s2) || lex_less(e2, s1)) return Contact::None;
        if (e1 == s2 || e2 == s1) return Contact::SharedEndpoint;
        return Contact::Overlap;
    }
    const Sign o3 = orient2d(c, d, a);
    const Sign o4 = orient2d(c, d, b);
    if (to_int(o1) * to_int(o2) < 0 && to_int(o3) * to_int(o4) < 0) return Contact::Crossing;
    if ((o1 == Sign::Zero && strictly_inside_segment(a, b, c)) || (o2 == Sign::Zero && strictly_inside_segment(a, b, d)) ||
        (o3 == Sign::Zero && strictly_inside_segment(c, d, a)) || (o4 == Sign::Zero && strictly_inside_segment(c, d, b))) {
        return Contact::Touch;
    }
    if (a == c || a == d || b == c || b == d) return Contact::SharedEndpoint;
    return Contact::None;
}

}  // namespace dcel::detail
