// dcel::check on the reference's own answers, spelled every way
// docs/checking.md allows (tests/support/answer_spellings.hpp): each kind,
// detected or given, under every convention, in every form. A respelling
// always agrees; a corruption differs exactly when the independent oracle
// (tests/oracles/answer_meaning.hpp) says it changed the meaning. The fuzz
// harness fuzz/answer.cpp makes the same trials from its bytes (mode B).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdint>
#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/testing/graph_cases.hpp"
#include "oracles/answer_meaning.hpp"
#include "support/answer_spellings.hpp"

namespace dcel::props {
namespace {

using test_support::Choices;
using test_support::Trial;
using test_support::TrialSetup;

// Graphs of 0 to size + 3 vertices (a hundred at RapidCheck's largest
// size): every shape the families make, and small enough that a case costs
// about a millisecond.
rc::Gen<testing::GraphCase> small_graphs() { return testing::graph_cases({.vertices_per_size = 3, .targeted = true}); }

// RapidCheck scales its draws by the size, which starts at 0 (always the
// first kind, no convention): every kind and convention from the first case.
template <class T>
rc::Gen<T> unscaled(rc::Gen<T> g) {
    return rc::gen::resize(100, std::move(g));
}

TrialSetup any_setup(bool corrupt) {
    TrialSetup s;
    s.kind = static_cast<check::AnswerKind>(*unscaled(rc::gen::inRange(0, 4)));
    s.give_kind = *unscaled(rc::gen::arbitrary<bool>());
    s.conventions.face_on_right = *unscaled(rc::gen::arbitrary<bool>());
    s.conventions.one_based = *unscaled(rc::gen::arbitrary<bool>());
    s.conventions.unoriented = *unscaled(rc::gen::arbitrary<bool>());
    s.corrupt = corrupt;
    return s;
}

// The trial's decisions are bytes, which RapidCheck shrinks towards none at
// all (every decision its plainest) and smaller values. As many as the size
// says, each of any value.
Trial any_trial(const Dcel& d, const oracle::AnswerJudge& judge, bool corrupt) {
    const TrialSetup setup = any_setup(corrupt);
    const auto bytes = *rc::gen::container<std::vector<std::uint8_t>>(unscaled(rc::gen::arbitrary<std::uint8_t>()));
    Choices choices(bytes);
    return test_support::make_trial(d, judge, setup, choices);
}

RC_GTEST_PROP(AnswerSpellings, prop_answer_spellings_of_the_reference_agree, ()) {
    const testing::GraphCase c = *small_graphs();
    const Dcel d = build(c.graph);
    const oracle::AnswerJudge judge(c.graph);
    const Trial t = any_trial(d, judge, false);
    RC_CLASSIFY(true, check::answer_kind_name(t.setup.kind));
    // The oracle first: the reference's own answer, respelled, is right by
    // its independent reckoning too (a check of reference_regions and of
    // the respelling).
    RC_LOG() << "text: " << t.text << "\n" << t.story;
    RC_ASSERT(t.expected.right);
    const std::string failure = test_support::judge_trial(d, t);
    RC_LOG() << failure;
    RC_ASSERT(failure.empty());
}

RC_GTEST_PROP(AnswerSpellings, prop_answer_corruptions_differ_exactly_when_the_meaning_changes, ()) {
    const testing::GraphCase c = *small_graphs();
    const Dcel d = build(c.graph);
    const oracle::AnswerJudge judge(c.graph);
    const Trial t = any_trial(d, judge, true);
    RC_CLASSIFY(true, check::answer_kind_name(t.setup.kind));
    RC_CLASSIFY(t.expected.right, "the corruption kept the meaning");
    const std::string failure = test_support::judge_trial(d, t);
    RC_LOG() << failure;
    RC_ASSERT(failure.empty());
}

}  // namespace
}  // namespace dcel::props
