// Numeric option values for `dcel diff`, which reads them after parsing (the
// schedule options depend on each other): cli_support's strict parsers, so
// the messages are every command's ("--cases: expected an integer from 1 to
// ..., found \"0\"").
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
