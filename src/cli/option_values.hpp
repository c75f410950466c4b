// Strict readers of numeric option values for `dcel diff`: the whole word must
// be a number of the right kind and range, with the value the user typed in
// the message otherwise (no wrap-around of -1 into 2^64 - 1, no NaN, no silent
// clamping of 1e300).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace dcel::cli {

// An unsigned integer in [lo, hi], decimal digits only. UsageError otherwise.
[[nodiscard]] std::uint64_t parse_count(const std::string& option, const std::string& text, std::uint64_t lo,
                                        std::uint64_t hi);

// A duration in seconds (a finite decimal number) in [lo, hi] seconds,
// as milliseconds. UsageError otherwise.
[[nodiscard]] std::chrono::milliseconds parse_seconds(const std::string& option, const std::string& text, double lo,
                                                      double hi);

}  // namespace dcel::cli
