// The work of `dcel diff`: run the implementation on the scheduled cases; on
// a failure confirm it, shrink it and keep what the report needs; with
// --keep-going, go on, grouping failures into distinct bugs and shrinking each
// once. No printing here except through the progress callback.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dcel/diff/clock.hpp"
#include "dcel/diff/implementation.hpp"
#include "dcel/diff/options.hpp"
#include "dcel/diff/outcome.hpp"
#include "dcel/diff/schedule.hpp"
#include "dcel/graph.hpp"

namespace dcel::diff {

struct Counterexample {
    Case original;            // the case as generated: spec, graph, class, exact text
    Outcome first;            // on the original graph
    bool reproduced = false;  // failed the same way again in a fresh process (after `prefix`)
    // --stream state: the graphs (exact text) that had to go first in the same
    // process for the failure to show; empty when it fails alone.
    std::vector<std::string> prefix;
    PlanarGraph graph;                      // the shrunk graph (the original when not reproduced); a session's start
    std::optional<check::Session> session;  // --sessions: the shrunk session
    std::string text;                       // its exact bytes, in the case's spelling
    Outcome outcome;                        // on graph
    std::size_t attempts = 0;               // shrink candidates run
    std::size_t steps = 0;                  // of which kept (each a smaller failing graph)
    bool budget_spent = false;              // shrinking stopped by --shrink-time or the attempt cap
    std::chrono::milliseconds shrink_elapsed{};
    // A hang: candidates ran with this shorter timeout (derived from the
    // passing cases' times), and the result was confirmed with the case's
    // own limit.
    std::optional<std::chrono::milliseconds> shrink_timeout;
    std::chrono::milliseconds limit{};  // the time limit of the original case (a hang's)
    // Shrinking ended because no single candidate of the counterexample
    // fails the same way: it is 1-minimal for what the shrinker tries.
    bool minimal = false;
};

// One distinct bug: the first case of each kind that showed it, shrunk, and
// every case that failed so. Failures are grouped by what they are once
// shrunk (docs/checking.md, "Grouping"): a failing case is shrunk when its
// key (its failure class, its kinds of difference and its coordinate class)
// is new; then its counterexample's signature (the class, the kinds of
// difference and the size it shrank to) joins it to a failure with the same
// signature, or makes a new one. So one bug seen in two coordinate classes
// is one failure that lists both.
// The cases of one key (a failure's class, kinds of difference and
// coordinate class) counted as a failure: what `dcel diff-merge` needs to
// group the failures of several shards exactly as one run would.
struct KeySeen {
    std::string key;
    gen::CoordinateClass coordinates = gen::CoordinateClass::SmallIntegers;
    std::size_t occurrences = 0;
    std::vector<std::size_t> cases;  // the first kMaxListedCases, in order
};

struct Failure {
    std::size_t id = 0;                         // 1, 2, ... in the order found
    std::vector<KeySeen> keys;                  // the case keys counted as this failure, in the order first seen
    std::vector<gen::CoordinateClass> classes;  // the coordinate classes it failed in, as seen
    std::string signature;                      // of the counterexample, after shrinking
    std::vector<std::size_t> cases;             // the cases that failed this way (the first kMaxListedCases)
    std::size_t occurrences = 0;
    std::chrono::milliseconds found_after{};  // from the start of the run
    Counterexample example;
};

inline constexpr std::size_t kMaxListedCases = 100;

enum class StopReason : std::uint8_t { Cases, Time, FirstFailure, MaxFailures };

// A case slower than --timeout-ms that finished within the limit scaled from
// the implementation's speed (speed.hpp): a performance note, not a failure.
struct SlowCase {
    std::size_t number = 0;
    gen::Family family = gen::Family::RandomSegments;
    std::size_t vertices = 0, edges = 0;
    std::chrono::milliseconds took{}, limit{};
};
inline constexpr std::size_t kMaxListedSlowCases = 20;

struct DiffResult {
    std::size_t cases_run = 0;  // cases run, agreeing or not
    std::size_t first_case = 0;
    std::size_t skipped = 0;  // cases no graph of an allowed coordinate class was found for
    // Cases the implementation answered with {"skip": reason}: never a
    // failure, never a pass; counted by reason, in the order first seen.
    std::size_t skipped_by_impl = 0;
    std::vector<std::pair<std::string, std::size_t>> skip_reasons;
    std::vector<SlowCase> slow;  // the first kMaxListedSlowCases
    std::size_t slow_count = 0;
    StopReason stopped_by = StopReason::Cases;
    std::chrono::milliseconds elapsed{};
    std::size_t restarts = 0;  // --stream: starts of the command after the first
    std::vector<Failure> failures;
    std::array<std::size_t, check::kAnswerKindCount> agreed_as{};  // answers that agreed, by the kind they were read as
    std::size_t large_cases = 0;                                   // large cases run
    // CPU time of dcel itself (generating, writing, building the reference,
    // judging), without the command's: what the reference side costs.
    std::chrono::milliseconds reference_cpu{};
    // Sessions whose answer gave the state as boundary cycles only: where
    // holes and isolated vertices lie went unchecked.
    std::size_t cycles_only = 0;
    // Query steps the answers of agreeing sessions skipped ({"skip": ...}),
    // by operation: unchecked.
    std::array<std::size_t, check::kStepOpCount> skipped_steps{};
    // Cases compared with the reference: run, with a graph, and not skipped by the implementation.
    [[nodiscard]] std::size_t checked() const { return cases_run - skipped - skipped_by_impl; }
};

// Called with a short status line while working.
using Progress = std::function<void(const std::string&)>;

// Throws ProcessError when the command cannot be run at all (no /bin/sh, or
// /bin/sh's exit status 126 or 127 on the first case: not found, not
// executable). `implementation` makes the implementation under test (by
// default the command of options.impl); `clock` is the time the budgets read.
[[nodiscard]] DiffResult run_diff(const DiffOptions& options, const Progress& progress);
[[nodiscard]] DiffResult run_diff(const DiffOptions& options, const Progress& progress,
                                  const ImplementationFactory& implementation, const Clock& clock);

}  // namespace dcel::diff
