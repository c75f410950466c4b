// The work of `dcel diff`: run the foreign command on the scheduled cases,
// and on the first failure confirm it, shrink it and keep what the report
// needs. No printing here except through the progress callback.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "dcel/graph.hpp"
#include "diff_cases.hpp"
#include "diff_outcome.hpp"
#include "process.hpp"

namespace dcel::cli {

struct DiffOptions {
    std::string impl;      // the command, run by /bin/sh -c
    bool stream = false;   // run "IMPL --stream" once, a line per case
    ProcessLimits limits;  // per case
    std::uint64_t seed = 1;
    std::optional<std::size_t> cases;      // none: until --time runs out
    std::optional<std::size_t> only_case;  // --case: replay this one
    std::size_t max_vertices = 60;
    std::optional<std::chrono::milliseconds> time;  // bounds the search for a failure
    std::chrono::milliseconds shrink_time{20000};   // bounds the shrinking
    std::size_t shrink_attempts = 5000;
};

struct Counterexample {
    CaseSpec spec;
    PlanarGraph original;
    Outcome first;              // on the original graph
    bool reproduced = false;    // failed the same way again, alone, in a fresh process
    PlanarGraph graph;          // the shrunk graph (the original when not reproduced)
    Outcome outcome;            // on graph
    std::size_t attempts = 0;   // shrink candidates run
    std::size_t steps = 0;      // of which kept (each a smaller failing graph)
    bool budget_spent = false;  // shrinking stopped by --shrink-time or the attempt cap
    std::chrono::milliseconds shrink_elapsed{};
};

struct DiffResult {
    std::size_t cases_run = 0;  // cases that agreed, plus the failing one
    std::size_t first_case = 0;
    bool stopped_by_time = false;
    std::chrono::milliseconds elapsed{};
    std::chrono::milliseconds found_after{};  // from the start to the first failure
    std::size_t restarts = 0;                 // --stream: starts of the command after the first
    std::optional<Counterexample> failure;
};

// Called with a short status line while working (for a terminal).
using Progress = std::function<void(const std::string&)>;

// Throws UsageError when /bin/sh cannot run the command at all (exit status
// 126 or 127 on the first case).
[[nodiscard]] DiffResult run_diff(const DiffOptions& options, const Progress& progress);

}  // namespace dcel::cli
