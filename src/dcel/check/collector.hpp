// Internal to dcel::check: gathers differences kind by kind, caps each kind
// at kMaxListedPerKind, and hands back a Report in the documented order.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "dcel/check/compare.hpp"

namespace dcel::check::detail {

inline constexpr std::size_t kKindCount = 18;

class Collector {
public:
    // False once this kind is full, and then the difference is counted as
    // unlisted: call it once per difference, and skip building the message.
    [[nodiscard]] bool wants(DifferenceKind k);
    void add(DifferenceKind k, std::string message, std::vector<Index> vertices = {});
    // Differences found so far, listed or not.
    [[nodiscard]] std::size_t count() const;
    [[nodiscard]] Report finish() &&;

private:
    std::array<std::vector<Difference>, kKindCount> by_kind_;
    std::size_t unlisted_ = 0;
};

}  // namespace dcel::check::detail
