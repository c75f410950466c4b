// Telling "slow" from "hung": each case's time limit is scaled from the
// implementation's own speed on the cases that passed, so a correct but slow
// program (a topology database answering a star of 2000 edges in 20 s) is
// noted as slow, not reported as a hang, while a real hang is still killed.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>

namespace dcel::diff {

class SpeedModel {
public:
    // A case's time limit is at least --timeout-ms (the base), at most this
    // many times it...
    static constexpr long kMaxFactor = 12;
    // ...and otherwise this many times the time predicted for its size.
    static constexpr long kSlack = 10;

    // Sizes below this are scaled from as if they were this large: a
    // quadratic extrapolation from a graph of 2 elements says nothing.
    static constexpr std::size_t kMinScaleSize = 16;

    // A passing case of `size` (vertices + edges) took `took`.
    void record(std::size_t size, std::chrono::milliseconds took);
    // The predicted time of a case of `size`: the fastest case seen (the
    // program's fixed cost: starting an interpreter, reading), plus the
    // largest of each recorded case's time above that, scaled by
    // (size / its size)^2 (never scaled down): a generous model for
    // implementations up to quadratic. 0 with no record.
    [[nodiscard]] std::chrono::milliseconds predicted(std::size_t size) const;
    // The limit for a case of `size`: clamp(kSlack * predicted, base, kMaxFactor * base).
    [[nodiscard]] std::chrono::milliseconds limit(std::size_t size, std::chrono::milliseconds base) const;

private:
    std::map<std::size_t, std::chrono::milliseconds> slowest_;  // by size: the slowest passing case
    std::chrono::milliseconds fastest_ = std::chrono::milliseconds::max();
};

}  // namespace dcel::diff
