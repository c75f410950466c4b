// The exact predicates against rational arithmetic, on random and
// adversarial triples.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "dcel/geometry/predicates.hpp"
#include "oracles/exact.hpp"
#include "support/point_gen.hpp"

namespace dcel::props {
namespace {

// A predicate call costs nanoseconds and a graph case milliseconds, so each
// case checks a batch of triples: the same case budget reaches far more of
// the rare inputs where a floating-point sign goes wrong.
constexpr std::size_t kBatch = 32;

void check_orient2d(const Triple& t) {
    const Point a = t.p[0], b = t.p[1], c = t.p[2];
    const int expected = oracle::orientation(a, b, c);
    // Every order of the arguments: a rotation agrees, a swap negates. Each
    // order rounds differently, so each is a separate chance to go wrong.
    RC_ASSERT(to_int(orient2d(a, b, c)) == expected);
    RC_ASSERT(to_int(orient2d(b, c, a)) == expected);
    RC_ASSERT(to_int(orient2d(c, a, b)) == expected);
    RC_ASSERT(to_int(orient2d(b, a, c)) == -expected);
    RC_ASSERT(to_int(orient2d(a, c, b)) == -expected);
    RC_ASSERT(to_int(orient2d(c, b, a)) == -expected);
}

RC_GTEST_PROP(Predicates, prop_orient2d_agrees_with_rationals, ()) {
    for (const Triple& t : *rc::gen::container<std::vector<Triple>>(kBatch, adversarial_triples())) check_orient2d(t);
}

RC_GTEST_PROP(Predicates, prop_compare_angle_agrees_with_rationals, ()) {
    for (const Triple& t : *rc::gen::container<std::vector<Triple>>(kBatch, adversarial_triples())) {
        const Point centre = t.p[0], a = t.p[1], b = t.p[2];
        if (a == centre || b == centre) continue;  // a direction needs a second point
        RC_ASSERT(to_int(compare_angle(centre, a, b)) == oracle::angle_order(centre, a, b));
        RC_ASSERT(to_int(compare_angle(centre, b, a)) == -oracle::angle_order(centre, a, b));
    }
}

}  // namespace
}  // namespace dcel::props
