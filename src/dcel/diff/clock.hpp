// Time, as the engine sees it: the wall clock that --time, --shrink-time and
// the "found after" figures read, and the CPU time of dcel itself (the
// reference side's cost). The unit tests use a clock they move by hand.
#pragma once

#include <chrono>

namespace dcel::diff {

class Clock {
public:
    using time_point = std::chrono::steady_clock::time_point;
    Clock() = default;
    Clock(const Clock&) = delete;
    Clock& operator=(const Clock&) = delete;
    virtual ~Clock() = default;
    [[nodiscard]] virtual time_point now() const = 0;
    // CPU time of this process (not its children).
    [[nodiscard]] virtual std::chrono::milliseconds cpu() const = 0;
};

// std::chrono::steady_clock and std::clock().
[[nodiscard]] const Clock& system_clock();

}  // namespace dcel::diff
