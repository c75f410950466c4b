// Checking a C++ DCEL's edits and queries against the reference inside its
// own tests: the in-process form of `dcel diff --sessions` (docs/checking.md,
// "Sessions"). Each case is an edit session, a start graph and a list of
// steps (split_edge, add_vertex, add_edge, add_edge_to_point, remove_edge,
// remove_isolated_vertex, merge_collinear_edges; locate, face_boundary,
// neighbours, stab), drawn by session_cases.hpp; your DCEL answers each
// step and gives its state after every edit, which the reference's run of
// the same session judges (check::compare_session), so the first wrong step
// is pinned down.
//
// What you write: a SessionImplementation around your DCEL, made from the
// start graph by a SessionFactory (session_implementation.hpp, which needs
// neither GoogleTest nor RapidCheck). It speaks the protocol's names, never
// your ids: vertex k of the start graph is protocol id k, each vertex a step
// creates takes the next id (an accepted split_edge, add_vertex or
// add_edge_to_point), a removed vertex's id is never used again; a face is
// named by a half-edge [u, v] with the face on its left (face_left_of) or
// the unbounded face (unbounded_face()). A step the reference refuses (an
// edge that crosses, a point off its edge, ...) must be refused with
// refused("why") and change nothing. A query your DCEL does not have may be
// answered skipped("why"): it goes unchecked, and a passing result's
// message counts the skipped steps. For instance, around a DCEL class
// MyDcel with vertex handles MyVertex:
//
//   class MySession : public dcel::testing::SessionImplementation {
//   public:
//       explicit MySession(const dcel::PlanarGraph& start) { /* build, fill ids_ */ }
//       dcel::check::StepAnswer apply(const dcel::check::SessionStep& s) override {
//           namespace answers = dcel::testing::answers;
//           switch (s.op) {
//               case dcel::check::StepOp::AddEdge:
//                   if (!dcel_.can_connect(ids_.at(s.u), ids_.at(s.v))) return answers::refused("crossing");
//                   dcel_.connect(ids_.at(s.u), ids_.at(s.v));
//                   return answers::ok();
//               case dcel::check::StepOp::Locate: ...  // answers::at_vertex(k), on_edge(u, v), in_face(...)
//               ...
//           }
//       }
//       dcel::check::SessionState state() const override { ... }  // every face's outer cycle, holes, isolated
//   private:
//       MyDcel dcel_;
//       std::vector<MyVertex> ids_;  // protocol id -> your vertex
//   };
//
//   auto factory = [](const dcel::PlanarGraph& g) { return std::make_unique<MySession>(g); };
//   EXPECT_TRUE(dcel::testing::session_implementation_agrees(factory));   // runs RapidCheck
//   RC_GTEST_PROP(Mine, sessions, ()) { dcel::testing::rc_assert_session_agrees(factory); }
//   EXPECT_TRUE(dcel::testing::agrees_with_reference(session, factory));  // one session
//
// The state is every face's record: its outer cycle (none for the unbounded
// face), its holes and its isolated vertices, each cycle as protocol ids in
// `next` order with the face on its left (any rotation), and optionally the
// points by protocol id (compared when given). An implementation that throws
// (its factory, a step or a state) fails the case like a wrong answer. On
// failure the message holds the (shrunk) session as one line of JSON, which
// pastes into `dcel session -` (the reference's answer) or
// `dcel diff --sessions`, the first wrong step, the reference's state before
// it, both answers to it (and both states after an edit), the report, and
// the seed that replays the run.
//
// Header-only, like check_testing.hpp: link dcel::testing, GTest::gtest and
// rapidcheck.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <array>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "dcel/check/report.hpp"
#include "dcel/check/session.hpp"
#include "dcel/error.hpp"
#include "dcel/testing/check_testing.hpp"
#include "dcel/testing/session_cases.hpp"
#include "dcel/testing/session_implementation.hpp"

namespace dcel::testing {

struct SessionCheckOptions {
    std::optional<std::uint64_t> seed = std::nullopt;  // unset: RC_PARAMS's, else a random one
    std::optional<int> cases = std::nullopt;           // successful cases needed to pass (RapidCheck's 100)
    std::optional<int> max_size = std::nullopt;        // RapidCheck's 100
    SessionCaseOptions sessions = {.families = {}, .vertices_per_size = 1, .steps_per_size = 2, .targeted = true};
};

namespace testing_detail {

// What the implementation said: its answers and states, as far as it got.
struct ImplementationRun {
    check::SessionAnswer answer;
    std::optional<std::size_t> threw_at;  // the step it threw at (the number of steps: at the end)
    std::string what;                     // what it threw
};

inline std::string what_of(const std::exception_ptr& e) {
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& x) {
        return std::string("threw: ") + x.what();
    } catch (...) {
        return "threw something that is not a std::exception";
    }
}

inline ImplementationRun run_implementation(const check::Session& s, const SessionFactory& factory) {
    ImplementationRun run;
    std::unique_ptr<SessionImplementation> impl;
    try {
        impl = factory(s.start);
    } catch (...) {
        run.threw_at = 0;
        run.what = "the factory " + what_of(std::current_exception());
        return run;
    }
    if (!impl) {
        run.threw_at = 0;
        run.what = "the factory gave no implementation (nullptr)";
        return run;
    }
    std::size_t i = 0;
    try {
        for (; i < s.steps.size(); ++i) {
            run.answer.steps.push_back(impl->apply(s.steps[i]));
            // After every edit, refused ones included: the first wrong state
            // is then pinned to its step.
            if (check::is_query(s.steps[i].op)) {
                run.answer.states.emplace_back();
            } else {
                run.answer.states.emplace_back(impl->state());
            }
        }
        run.answer.state = impl->state();
    } catch (...) {
        run.threw_at = i;
        run.what = "the implementation " + what_of(std::current_exception());
        // The answers before it are kept (they may be wrong already); the
        // step it threw at has none.
        if (run.answer.steps.size() > i) run.answer.steps.resize(i);
        run.answer.states.resize(i);
    }
    return run;
}

inline std::string state_text(const check::SessionState& s) { return check::write_session_state(s); }

// Query steps answered {"skip": ...}, by operation (StepOp order).
using SkipCounts = std::array<std::size_t, check::kStepOpCount>;

inline void count_skips(const check::Session& s, const check::SessionAnswer& a, SkipCounts& counts) {
    for (std::size_t i = 0; i < a.steps.size() && i < s.steps.size(); ++i) {
        if (a.steps[i].kind == check::StepAnswer::Kind::Skip && check::is_query(s.steps[i].op)) {
            ++counts[static_cast<std::size_t>(s.steps[i].op)];
        }
    }
}

// "; skipped (unchecked): 12 stab steps, 3 locate steps", or "".
inline std::string skips_text(const SkipCounts& counts) {
    std::string out;
    for (std::size_t op = 0; op < counts.size(); ++op) {
        if (counts[op] == 0) continue;
        out += (out.empty() ? "; skipped (unchecked): " : ", ") + std::to_string(counts[op]) + " " +
               std::string(check::step_op_name(static_cast<check::StepOp>(op))) + (counts[op] == 1 ? " step" : " steps");
    }
    return out;
}

// The message for a session the implementation fails, or "" when it agrees.
// Compares its answers up to where it stopped: a wrong step before a throw is
// the first wrong step.
inline std::string session_failure(const check::Session& s, const SessionFactory& factory, SkipCounts* skips = nullptr) {
    const ImplementationRun run = run_implementation(s, factory);
    if (skips != nullptr) count_skips(s, run.answer, *skips);
    check::Session answered = s;  // the steps it answered
    if (run.threw_at) answered.steps.resize(*run.threw_at);
    check::Report report = check::compare_session(answered, run.answer);
    const bool wrong = !report.agrees();
    if (!wrong && !run.threw_at) return "";

    const std::size_t k = wrong ? report.first_wrong_step.value_or(answered.steps.size()) : *run.threw_at;
    const check::ReferenceRun ref = check::run_reference_session(s, true);
    std::ostringstream os;
    os << "session (" << s.start.vertices.size() << " vertices, " << s.start.edges.size() << " edges, " << s.steps.size()
       << " steps; paste into `dcel session -`):\n"
       << check::write_session(s);
    const check::SessionState& before = k == 0 ? check::run_reference_session(check::Session{s.start, {}, false}).state
                                               : ref.states[k - 1];
    if (k < s.steps.size()) {
        const check::SessionStep& step = s.steps[k];
        os << (wrong ? "the first step answered wrongly: step " : "the step it threw at: step ") << k << " ("
           << check::describe_step(step) << ")\n"
           << "the state before it (the reference's):\n  " << state_text(before) << "\n"
           << "the reference's answer to it: " << check::write_step_answer(ref.steps[k]) << "\n";
        if (!wrong) {
            os << run.what << "\n";
            return os.str();
        }
        os << "the implementation's answer to it: " << check::write_step_answer(run.answer.steps[k]) << "\n";
        if (!check::is_query(step.op) && k < run.answer.states.size() && run.answer.states[k]) {
            os << "the state after it, the reference's:\n  " << state_text(ref.states[k]) << "\n"
               << "the state after it, the implementation's:\n  " << state_text(*run.answer.states[k]) << "\n";
        }
    } else if (wrong) {
        os << "every step answered right; the state at the end differs\n"
           << "the reference's:\n  " << state_text(ref.state) << "\n"
           << "the implementation's:\n  " << (run.answer.state ? state_text(*run.answer.state) : "none") << "\n";
    } else {
        os << run.what << " (asked for the state at the end)\n";
        return os.str();
    }
    os << check::report_text(report);
    if (run.threw_at) os << "then, at step " << *run.threw_at << ", " << run.what << "\n";
    return os.str();
}

inline rc::detail::TestParams session_params(const SessionCheckOptions& options) {
    return params(CheckOptions{.seed = options.seed, .cases = options.cases, .max_size = options.max_size});
}

}  // namespace testing_detail

// One session: success, or a failure whose message is the session, the first
// wrong step and the report. The start graph must be valid (the reference
// refuses it otherwise, and so does this).
[[nodiscard]] inline ::testing::AssertionResult agrees_with_reference(const check::Session& session,
                                                                      const SessionFactory& factory) {
    try {
        testing_detail::SkipCounts skips{};
        const std::string failure = testing_detail::session_failure(session, factory, &skips);
        if (failure.empty()) return ::testing::AssertionSuccess() << "agrees" << testing_detail::skips_text(skips);
        return ::testing::AssertionFailure() << failure;
    } catch (const InvalidInput& e) {
        return ::testing::AssertionFailure() << "the reference refuses the start graph: " << e.what();
    }
}

// Inside a RapidCheck property (RC_GTEST_PROP): draws one session and fails
// with the first wrong step (RC_FAIL), so RapidCheck shrinks the session and
// prints it. RC_PARAMS sets the seed and the number of cases.
inline void rc_assert_session_agrees(const SessionFactory& factory,
                                     const SessionCaseOptions& sessions = SessionCheckOptions{}.sessions) {
    const SessionCase c = *session_cases(sessions);
    const std::string failure = testing_detail::session_failure(c.session, factory);
    if (!failure.empty()) RC_FAIL(failure);
}

namespace testing_detail {
inline void rc_assert_session_agrees_counting(const SessionFactory& factory, const SessionCaseOptions& sessions,
                                              SkipCounts& skips) {
    const SessionCase c = *session_cases(sessions);
    const std::string failure = session_failure(c.session, factory, &skips);
    if (!failure.empty()) RC_FAIL(failure);
}
}  // namespace testing_detail

// Runs the property itself: success (whose message says how many query
// steps were skipped, if any), or a failure holding the shrunk session, its
// first wrong step, the report and the seed.
[[nodiscard]] inline ::testing::AssertionResult session_implementation_agrees(const SessionFactory& factory,
                                                                              const SessionCheckOptions& options = {}) {
    const rc::detail::TestParams p = testing_detail::session_params(options);
    rc::detail::TestMetadata metadata;
    metadata.id = metadata.description = "agrees with the reference DCEL on edit sessions from dcel::gen";
    testing_detail::SkipCounts skips{};
    const rc::detail::TestResult result = rc::detail::checkProperty(
        rc::detail::toProperty([&] { testing_detail::rc_assert_session_agrees_counting(factory, options.sessions, skips); }),
        metadata, p);
    if (result.template is<rc::detail::SuccessResult>()) {
        return ::testing::AssertionSuccess() << "agrees on " << result.template get<rc::detail::SuccessResult>().numSuccess
                                             << " sessions" << testing_detail::skips_text(skips);
    }
    std::ostringstream os;
    if (result.template is<rc::detail::FailureResult>()) {
        const auto& failure = result.template get<rc::detail::FailureResult>();
        // RapidCheck's description starts with where RC_FAIL stands (this
        // header), which tells the reader nothing.
        const std::string& text = failure.description;
        const std::size_t ours = text.find("session (");
        os << "failed after " << failure.numSuccess
           << " agreeing sessions; replay with SessionCheckOptions{.seed = " << p.seed << "} or RC_PARAMS=\"seed=" << p.seed
           << " max_success=" << p.maxSuccess << " max_size=" << p.maxSize << "\"; smallest failing session found:\n"
           << (ours == std::string::npos ? text : text.substr(ours));
    } else {
        rc::detail::printResultMessage(result, os);
    }
    return ::testing::AssertionFailure() << os.str();
}

}  // namespace dcel::testing
