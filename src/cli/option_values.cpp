#include "option_values.hpp"

#include <charconv>
#include <cmath>

#include "cli_support.hpp"
#include "dcel/format.hpp"
#include "dcel/io/decimal.hpp"

namespace dcel::cli {

namespace {

// The word as typed, quoted and cut short, for messages.
std::string typed(const std::string& text) {
    constexpr std::size_t kShown = 40;
    std::string s;
    for (const char c : text.substr(0, kShown)) {
        const auto b = static_cast<unsigned char>(c);
        s += b >= 0x20 && b < 0x7f ? std::string(1, c) : "?";
    }
    return "\"" + s + (text.size() > kShown ? "...\"" : "\"");
}

// 0.001, 20, 10000000: no exponent for the bounds we print.
std::string plain(double v) {
    if (v == std::trunc(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<std::int64_t>(v));
    return format_double(v);
}

}  // namespace

std::uint64_t parse_count(const std::string& option, const std::string& text, std::uint64_t lo, std::uint64_t hi) {
    const std::string range = "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
    std::uint64_t v = 0;
    const char* end = text.data() + text.size();
    const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    const auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (!digits || ec != std::errc() || ptr != end || v < lo || v > hi) {
        throw UsageError(option + ": expected " + range + ", found " + typed(text));
    }
    return v;
}

std::chrono::milliseconds parse_seconds(const std::string& option, const std::string& text, double lo, double hi) {
    double v = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = io::parse_double(text.data(), end, v);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v) || v < lo || v > hi) {
        throw UsageError(option + ": expected a number of seconds from " + plain(lo) + " to " + plain(hi) + ", found " +
                         typed(text));
    }
    return std::chrono::milliseconds(static_cast<std::int64_t>(std::llround(v * 1000.0)));
}

}  // namespace dcel::cli
