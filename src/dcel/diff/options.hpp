// What a `dcel diff` run is told: the command, the schedule, the limits and
// how to read answers. Every default is stated once, here: the CLI's options
// and help text, the report's replay line and the engine all read them.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "dcel/check/answer.hpp"
#include "dcel/diff/process.hpp"
#include "dcel/diff/schedule.hpp"

namespace dcel::diff {

namespace defaults {
inline constexpr std::size_t kCases = 200;       // without --time
inline constexpr std::size_t kMaxFailures = 20;  // distinct failures, with --keep-going
inline constexpr std::chrono::milliseconds kShrinkTime{20000};
inline constexpr std::size_t kShrinkAttempts = 5000;  // candidates run per failure, at most
}  // namespace defaults

// How to read another implementation's answer: --answer and the conventions
// (docs/checking.md, "Answer kinds"), shared by `dcel check` and `dcel diff`.
struct AnswerOptions {
    std::optional<check::AnswerKind> kind;  // none: detect it from each answer
    check::Conventions conventions;
};

struct DiffOptions {
    std::string impl;      // the command, run by /bin/sh -c
    bool stream = false;   // run "IMPL --stream" once, a line per case
    ProcessLimits limits;  // per case
    Schedule schedule;
    std::optional<std::size_t> cases;                               // none: until --time runs out
    std::optional<std::size_t> only_case;                           // --case: replay this one
    std::optional<std::chrono::milliseconds> time;                  // bounds the search for failures
    std::chrono::milliseconds shrink_time = defaults::kShrinkTime;  // bounds the shrinking of each failure
    std::size_t shrink_attempts = defaults::kShrinkAttempts;
    AnswerOptions answer;
    bool keep_going = false;  // go on after a failure (the default under --time)
    std::size_t max_failures = defaults::kMaxFailures;
    // Processes of the command run at once (1 .. kMaxJobs). The search runs
    // cases on that many workers; the results are judged in case order, and
    // confirming and shrinking a failure run alone, so the report does not
    // depend on it (session.cpp, "With --jobs").
    std::size_t jobs = 1;
    // --shard K/N: only the cases i with i mod N = K - 1, so that N runs (the
    // jobs of a CI matrix) share one campaign; dcel diff-merge joins their
    // reports into the report one run would have written.
    struct Shard {
        std::size_t index = 1, count = 1;  // K (1 .. N) and N
    };
    std::optional<Shard> shard;
};

}  // namespace dcel::diff
