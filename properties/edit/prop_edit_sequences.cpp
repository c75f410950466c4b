// Property: after any sequence of edits, validate() accepts the DCEL and it
// equals the rebuild of its own graph; an edit succeeds exactly when the
// oracle (build() on the resulting graph) says it must; and user data stays
// on the right elements.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>  // after gtest.h, which it needs
#include <algorithm>

#include "edit_steps.hpp"
#include "support/rebuild_compare.hpp"
#include "tracked_data.hpp"

namespace dcel::props {
namespace {

RC_GTEST_PROP(EditProperties, prop_edit_sequences_match_rebuild, ()) {
    const int which = *rc::gen::inRange(0, 3);
    const std::vector<Step> steps = *script(growing_step());
    Dcel d = build(start_map(which));
    TrackedData data(d);
    int applied = 0;
    for (const Step& s : steps) {
        const Resolved r = resolve(d, s);
        if (!r.applicable) continue;
        const bool valid = expected_valid(d, s, r);
        const auto samples = data.sample(d);
        bool refused = false;
        Change c;
        try {
            c = apply(d, s, r);
        } catch (const TopologyError&) {
            refused = true;
        } catch (const InvalidInput&) {
            refused = true;
        }
        RC_ASSERT(refused == !valid);
        if (refused) continue;
        ++applied;
        data.follow(c, d);
        const auto problem = test_support::soundness_problem(d);
        if (problem) RC_FAIL("after " + std::to_string(applied) + " edits: " + *problem);
        RC_ASSERT(data.problem(d) == "");
        RC_ASSERT(data.labels_problem(d, samples) == "");
    }
    RC_CLASSIFY(applied >= 20, "20+ edits applied");
    RC_CLASSIFY(d.num_faces() >= 3, "3+ faces at the end");
    RC_CLASSIFY(std::any_of(steps.begin(), steps.end(), [](const Step& s) { return s.op == Op::MergeEdges; }), "has merges");
}

}  // namespace
}  // namespace dcel::props
