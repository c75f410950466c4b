// Property: an edit that must be refused (the oracle, build() on the graph
// it would make, says so) is refused with TopologyError or InvalidInput and
// leaves the DCEL exactly as it was, array for array; and one that must not
// be refused succeeds. Checked for every step: a growing script first (to
// reach a map with some structure), then a script of hostile steps, most of
// which must be refused.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>  // after gtest.h, which it needs

#include "dcel/dump.hpp"
#include "edit_steps.hpp"
#include "support/rebuild_compare.hpp"

namespace dcel::props {
namespace {

// Tries one step; returns whether it was refused.
bool attempt(Dcel& d, const Step& s) {
    const Resolved r = resolve(d, s);
    if (!r.applicable) return false;
    const bool valid = expected_valid(d, s, r);
    const DcelDump before = to_dump(d);
    bool refused = false;
    try {
        (void)apply(d, s, r);
    } catch (const TopologyError&) {
        refused = true;
    } catch (const InvalidInput&) {
        refused = true;
    }
    RC_ASSERT(refused == !valid);
    if (refused) {
        RC_ASSERT(test_support::same_dump(before, to_dump(d)));
    } else {
        const auto problem = test_support::soundness_problem(d);
        if (problem) RC_FAIL(*problem);
    }
    return refused;
}

RC_GTEST_PROP(EditProperties, prop_refused_edit_changes_nothing, ()) {
    const int which = *rc::gen::inRange(0, 3);
    const std::vector<Step> growth = *script(growing_step());
    const std::vector<Step> attempts = *rc::gen::container<std::vector<Step>>(hostile_step());
    Dcel d = build(start_map(which));
    int refusals = 0;
    for (const Step& s : growth) refusals += attempt(d, s) ? 1 : 0;
    for (const Step& s : attempts) refusals += attempt(d, s) ? 1 : 0;
    RC_CLASSIFY(refusals >= 10, "10+ refusals");
    RC_CLASSIFY(refusals == 0, "no refusal");
}

}  // namespace
}  // namespace dcel::props
