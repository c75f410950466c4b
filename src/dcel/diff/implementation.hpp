// The implementation under test, as the engine sees it: something that takes
// one graph (a line of JSON) and gives back what a process would (its stdout,
// or how it ended). The real one runs the user's command, once per graph or
// as a --stream; the unit tests give the engine fakes (tests/diff/), so that
// the schedule, the judging, the grouping and the shrinking are tested
// without processes.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "dcel/diff/process.hpp"

namespace dcel::diff {

class Implementation {
public:
    Implementation() = default;
    Implementation(const Implementation&) = delete;
    Implementation& operator=(const Implementation&) = delete;
    virtual ~Implementation() = default;

    // text is one line ending in '\n'; the run is killed (TimedOut) after
    // `timeout`.
    [[nodiscard]] virtual ProcessResult run(const std::string& text, std::chrono::milliseconds timeout) = 0;
    // With the limits' own timeout.
    [[nodiscard]] virtual ProcessResult run(const std::string& text) = 0;
    // The next run starts from a fresh process (a stream's state is gone).
    virtual void restart() = 0;
    // How many times a process was started (a stream: 1 + the restarts;
    // one process per graph: 0, since every run is a start).
    [[nodiscard]] virtual std::size_t starts() const = 0;
};

// Makes an implementation with the given limits (the shrinker runs a hang's
// candidates under a shorter timeout than the search).
using ImplementationFactory = std::function<std::unique_ptr<Implementation>(const ProcessLimits&)>;

// The user's command: /bin/sh -c COMMAND per graph, or "COMMAND --stream"
// kept running when `stream`.
[[nodiscard]] ImplementationFactory command_implementation(std::string command, bool stream);

}  // namespace dcel::diff
