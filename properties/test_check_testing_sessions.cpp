// dcel/testing/check_testing_sessions.hpp as a user would use it, on C++
// session implementations (support/planted_sessions.hpp): at the helpers'
// default settings (RapidCheck's: 100 cases, max_size 100; ctest runs this
// binary with an empty RC_PARAMS) each planted bug of docs/checking.md's
// table is caught on every one of seeds 1 to 10, and the right
// implementation passes all 10. Each run prints the agreeing sessions before
// the failure and the shrunk counterexample's size (docs/library.md has the
// table). The unit tests check one session and what a failure says.
#include "dcel/testing/check_testing_sessions.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/planted_sessions.hpp"

namespace {

namespace planted = dcel::props::planted;
using dcel::testing::SessionCheckOptions;
using dcel::testing::SessionFactory;

constexpr int kSeeds = 10;

// The number after `label` in a message (0 when absent).
std::size_t number_after(const std::string& message, const std::string& label) {
    const std::size_t at = message.find(label);
    if (at == std::string::npos) return 0;
    return std::strtoull(message.c_str() + at + label.size(), nullptr, 10);
}

// The kind of the first difference a report lists ("wrong-refusal"): the
// line after "N difference(s)", up to its colon.
std::string first_kind(const std::string& message) {
    const std::size_t count = message.find(" difference");
    const std::size_t line = message.find('\n', count);
    if (count == std::string::npos || line == std::string::npos) return "?";
    return message.substr(line + 1, message.find(':', line) - line - 1);
}

struct SeedRuns {
    int caught = 0;
    double seconds = 0;
    std::vector<std::size_t> agreeing;         // sessions before the failure, per caught seed
    std::vector<std::size_t> vertices, steps;  // of the shrunk counterexample, per caught seed
    std::set<std::string> kinds;               // the first difference's kind, over the caught seeds
    std::string unexpected;                    // failures without any of the expected words
};

// expect: words of which a failure message must hold at least one.
SeedRuns run_seeds(const SessionFactory& factory, const std::vector<std::string>& expect) {
    SeedRuns runs;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        const auto start = std::chrono::steady_clock::now();
        const ::testing::AssertionResult result = dcel::testing::session_implementation_agrees(
            factory, SessionCheckOptions{.seed = static_cast<std::uint64_t>(seed)});
        runs.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (result) continue;
        ++runs.caught;
        const std::string message = result.message();
        runs.agreeing.push_back(number_after(message, "failed after "));
        runs.vertices.push_back(number_after(message, "session ("));
        runs.steps.push_back(number_after(message, " edges, "));
        runs.kinds.insert(first_kind(message));
        const bool found = std::any_of(expect.begin(), expect.end(),
                                       [&](const std::string& word) { return message.find(word) != std::string::npos; });
        if (!found) runs.unexpected += "seed " + std::to_string(seed) + ": unexpected failure:\n" + message + "\n";
    }
    return runs;
}

std::string list(const std::vector<std::size_t>& xs) {
    std::string s;
    for (const std::size_t x : xs) s += (s.empty() ? "" : " ") + std::to_string(x);
    return s;
}

void report(const char* what, const SeedRuns& r) {
    std::size_t sum = 0, most = 0;
    for (const std::size_t a : r.agreeing) {
        sum += a;
        most = std::max(most, a);
    }
    const double mean = r.agreeing.empty() ? 0.0 : static_cast<double>(sum) / static_cast<double>(r.agreeing.size());
    std::printf("%-22s caught on %2d of %d seeds in %5.2f s; agreeing sessions before: mean %.1f, max %zu\n", what, r.caught,
                kSeeds, r.seconds, mean, most);
    std::string kinds;
    for (const std::string& k : r.kinds) kinds += (kinds.empty() ? "" : " ") + k;
    std::printf("%-22s   found as %s; counterexamples: vertices [%s], steps [%s]\n", "", kinds.c_str(),
                list(r.vertices).c_str(), list(r.steps).c_str());
}

TEST(CheckTestingSessions, TheDefaultsAreRapidChecks) {
    // What "default settings" means below: nothing in RC_PARAMS.
    EXPECT_EQ(rc::detail::configuration().testParams.maxSuccess, 100);
    EXPECT_EQ(rc::detail::configuration().testParams.maxSize, 100);
}

void expect_caught_every_seed(const char* what, const SessionFactory& factory, const std::vector<std::string>& expect) {
    const SeedRuns r = run_seeds(factory, expect);
    report(what, r);
    EXPECT_EQ(r.caught, kSeeds) << what;
    EXPECT_EQ(r.unexpected, "") << what;
}

TEST(CheckTestingSessions, HolesStayIsCaughtOnEverySeed) {
    expect_caught_every_seed("holes_stay", planted::holes_stay_session, {"wrong-isolated-vertex", "wrong-hole"});
}

TEST(CheckTestingSessions, StaleOuterIsCaughtOnEverySeed) {
    expect_caught_every_seed("stale_outer", planted::stale_outer_session, {"wrong-outer-boundary"});
}

TEST(CheckTestingSessions, LocateVerticalIsCaughtOnEverySeed) {
    expect_caught_every_seed("locate_vertical", planted::locate_vertical_session, {"wrong-query-answer"});
}

TEST(CheckTestingSessions, LocateIgnoresHolesIsCaughtOnEverySeed) {
    expect_caught_every_seed("locate_ignores_holes", planted::locate_ignores_holes_session, {"wrong-query-answer"});
}

TEST(CheckTestingSessions, SplitTwinIsCaughtOnEverySeed) {
    expect_caught_every_seed("split_twin", planted::split_twin_session, {"missing-cycle", "extra-cycle"});
}

TEST(CheckTestingSessions, RefusesCollinearIsCaughtOnEverySeed) {
    expect_caught_every_seed("refuses_collinear", planted::refuses_collinear_session, {"wrong-refusal"});
}

TEST(CheckTestingSessions, RightImplementationPassesEverySeed) {
    const SeedRuns r = run_seeds(planted::right_session, {});
    report("right: failures", r);
    EXPECT_EQ(r.caught, 0) << r.unexpected;
}

// ---- One session, and what a failure says.

// examples/sessions/square.json: three sides of a square around vertex 4,
// the fourth closes it; queries, a refused edit, a split, a stab.
dcel::check::Session square() {
    return dcel::check::read_session(
        R"({"vertices": [[0, 0], [4, 0], [4, 4], [0, 4], [2, 2]], "edges": [[0, 1], [1, 2], [2, 3]],
            "steps": [{"add_edge": {"from": 3, "to": 0}}, {"locate": {"at": [2, 2]}},
                      {"face_boundary": {"at": [1, 1]}}, {"add_edge": {"from": 4, "to": 4}},
                      {"split_edge": {"edge": [0, 1], "at": [2, 0]}}, {"stab": {"from": [-1, 1], "to": [5, 1]}}]})");
}

TEST(CheckTestingSessions, OneSession) {
    EXPECT_TRUE(dcel::testing::agrees_with_reference(square(), planted::right_session));
    // Closing the square leaves vertex 4 in the unbounded face's record.
    const ::testing::AssertionResult stay = dcel::testing::agrees_with_reference(square(), planted::holes_stay_session);
    ASSERT_FALSE(stay);
    const std::string message = stay.message();
    EXPECT_NE(message.find("session (5 vertices, 3 edges, 6 steps; paste into `dcel session -`):\n{\"vertices\": "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("the first step answered wrongly: step 0 (add_edge from 3 to 0)"), std::string::npos) << message;
    EXPECT_NE(message.find("the state before it (the reference's):\n  {\"faces\": [{\"outer\": null"), std::string::npos)
        << message;
    EXPECT_NE(message.find("the reference's answer to it: {\"ok\": true}"), std::string::npos) << message;
    EXPECT_NE(message.find("the state after it, the implementation's:"), std::string::npos) << message;
    EXPECT_NE(message.find("wrong-isolated-vertex: after step 0"), std::string::npos) << message;

    // The vertical edge 1-2 at (4, 1): the right answer is the edge.
    dcel::check::Session on_vertical = square();
    on_vertical.steps = {dcel::check::read_session(R"({"vertices": [], "edges": [],
        "steps": [{"locate": {"at": [4, 1]}}]})")
                             .steps};
    const ::testing::AssertionResult vertical = dcel::testing::agrees_with_reference(on_vertical,
                                                                                     planted::locate_vertical_session);
    ASSERT_FALSE(vertical);
    EXPECT_NE(std::string(vertical.message()).find("the implementation's answer to it: {\"face\": null}"), std::string::npos)
        << vertical.message();
}

// An implementation that throws, or a factory that gives none, fails the
// session like a wrong answer, saying where.
class Throws : public dcel::testing::SessionImplementation {
public:
    dcel::check::StepAnswer apply(const dcel::check::SessionStep& s) override {
        if (s.op == dcel::check::StepOp::Locate) throw std::runtime_error("no locate here");
        return right_->apply(s);
    }
    dcel::check::SessionState state() const override { return right_->state(); }
    explicit Throws(const dcel::PlanarGraph& g) : right_(planted::right_session(g)) {}

private:
    planted::SessionPtr right_;
};

TEST(CheckTestingSessions, ThrowingFails) {
    const ::testing::AssertionResult threw = dcel::testing::agrees_with_reference(
        square(), [](const dcel::PlanarGraph& g) { return std::make_unique<Throws>(g); });
    ASSERT_FALSE(threw);
    const std::string message = threw.message();
    EXPECT_NE(message.find("the step it threw at: step 1 (locate at (2, 2))"), std::string::npos) << message;
    EXPECT_NE(message.find("the implementation threw: no locate here"), std::string::npos) << message;

    const ::testing::AssertionResult none = dcel::testing::agrees_with_reference(
        square(), [](const dcel::PlanarGraph&) { return std::unique_ptr<dcel::testing::SessionImplementation>(); });
    ASSERT_FALSE(none);
    EXPECT_NE(std::string(none.message()).find("the factory gave no implementation"), std::string::npos);
}

// A query the implementation does not have may be skipped: unchecked, and
// counted in the passing result's message; an edit may not.
class Skips : public dcel::testing::SessionImplementation {
public:
    Skips(const dcel::PlanarGraph& g, dcel::check::StepOp op) : right_(planted::right_session(g)), op_(op) {}
    dcel::check::StepAnswer apply(const dcel::check::SessionStep& s) override {
        return s.op == op_ ? dcel::testing::answers::skipped("not in this library") : right_->apply(s);
    }
    dcel::check::SessionState state() const override { return right_->state(); }

private:
    planted::SessionPtr right_;
    dcel::check::StepOp op_;
};

TEST(CheckTestingSessions, SkippedQueriesAreCountedSkippedEditsFail) {
    using dcel::check::StepOp;
    const ::testing::AssertionResult stab = dcel::testing::agrees_with_reference(
        square(), [](const dcel::PlanarGraph& g) { return std::make_unique<Skips>(g, StepOp::Stab); });
    EXPECT_TRUE(stab);
    EXPECT_EQ(std::string(stab.message()), "agrees; skipped (unchecked): 1 stab step");
    const ::testing::AssertionResult generated = dcel::testing::session_implementation_agrees(
        [](const dcel::PlanarGraph& g) { return std::make_unique<Skips>(g, StepOp::Stab); },
        SessionCheckOptions{.seed = 1, .cases = 20});
    EXPECT_TRUE(generated);
    EXPECT_NE(std::string(generated.message()).find("agrees on 20 sessions; skipped (unchecked): "), std::string::npos)
        << generated.message();

    const ::testing::AssertionResult split = dcel::testing::agrees_with_reference(
        square(), [](const dcel::PlanarGraph& g) { return std::make_unique<Skips>(g, StepOp::SplitEdge); });
    ASSERT_FALSE(split);
    EXPECT_NE(std::string(split.message()).find("the answer skips an edit"), std::string::npos) << split.message();
}

TEST(CheckTestingSessions, FailureHoldsTheShrunkSessionAndTheSeed) {
    const ::testing::AssertionResult result = dcel::testing::session_implementation_agrees(
        planted::refuses_collinear_session, SessionCheckOptions{.seed = 7});
    ASSERT_FALSE(result);
    const std::string message = result.message();
    std::cerr << message;
    EXPECT_NE(message.find("replay with SessionCheckOptions{.seed = 7} or RC_PARAMS=\"seed=7 max_success=100"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("smallest failing session found:\nsession ("), std::string::npos) << message;
    // The session as one line of JSON that `dcel session -` reads, read back.
    const std::size_t json = message.find("{\"vertices\": ");
    ASSERT_NE(json, std::string::npos) << message;
    const dcel::check::Session s = dcel::check::read_session(message.substr(json, message.find('\n', json) - json));
    EXPECT_FALSE(dcel::testing::agrees_with_reference(s, planted::refuses_collinear_session));
    EXPECT_TRUE(dcel::testing::agrees_with_reference(s, planted::right_session));
    // An axis-parallel add_edge needs two vertices and one step, no more.
    EXPECT_LE(s.start.vertices.size(), 3U) << message;
    EXPECT_LE(s.steps.size(), 2U) << message;
    EXPECT_NE(message.find("wrong-refusal"), std::string::npos) << message;
}

// The generator's cases print as their session's JSON, and every shrink is
// a session whose start graph the reference accepts.
TEST(CheckTestingSessions, GeneratedSessionsShrinkToValidSessions) {
    dcel::testing::SessionCaseOptions options;
    options.targeted = true;
    const rc::Gen<dcel::testing::SessionCase> cases = dcel::testing::session_cases(options);
    std::size_t shrinks_seen = 0;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const rc::Shrinkable<dcel::testing::SessionCase> drawn = cases(rc::Random(seed), 50);
        const dcel::testing::SessionCase c = drawn.value();
        std::ostringstream shown;
        showValue(c, shown);
        EXPECT_NE(shown.str().find(dcel::check::write_session(c.session)), std::string::npos) << shown.str();
        rc::Seq<rc::Shrinkable<dcel::testing::SessionCase>> shrinks = drawn.shrinks();
        for (int k = 0; k < 30; ++k) {
            const rc::Maybe<rc::Shrinkable<dcel::testing::SessionCase>> next = shrinks.next();
            if (!next) break;
            const dcel::check::Session smaller = next->value().session;
            EXPECT_NO_THROW((void)dcel::check::run_reference_session(smaller)) << dcel::check::write_session(smaller);
            EXPECT_LE(smaller.steps.size() + smaller.start.vertices.size(),
                      c.session.steps.size() + c.session.start.vertices.size())
                << dcel::check::write_session(smaller);
            ++shrinks_seen;
        }
    }
    EXPECT_GT(shrinks_seen, 0U);
}

RC_GTEST_PROP(CheckTestingSessions, prop_right_implementation_in_a_property, ()) {
    dcel::testing::rc_assert_session_agrees(planted::right_session);
}

}  // namespace
