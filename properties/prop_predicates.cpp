// The exact predicates against rational arithmetic, on random and
// adversarial triples.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "dcel/geometry/predicates.hpp"
#include "support/exact_oracle.hpp"
#include "support/point_gen.hpp"

namespace dcel::props {
namespace {

RC_GTEST_PROP(Predicates, prop_orient2d_agrees_with_rationals, ()) {
    const Triple t = *adversarial_triples();
    const Point a = t.p[0], b = t.p[1], c = t.p[2];
    const int expected = orient_sign(a, b, c);
    RC_ASSERT(to_int(orient2d(a, b, c)) == expected);
    // The symmetries: a rotation of the arguments agrees, a swap negates.
    RC_ASSERT(to_int(orient2d(b, c, a)) == expected);
    RC_ASSERT(to_int(orient2d(b, a, c)) == -expected);
}

RC_GTEST_PROP(Predicates, prop_compare_angle_agrees_with_rationals, ()) {
    const Triple t = *adversarial_triples();
    const Point centre = t.p[0], a = t.p[1], b = t.p[2];
    RC_PRE(!(a == centre) && !(b == centre));  // directions need a second point
    RC_ASSERT(to_int(compare_angle(centre, a, b)) == angle_order(centre, a, b));
    RC_ASSERT(to_int(compare_angle(centre, b, a)) == -angle_order(centre, a, b));
}

}  // namespace
}  // namespace dcel::props
