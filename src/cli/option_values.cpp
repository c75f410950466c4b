#include "option_values.hpp"

#include <cmath>

#include "cli_support.hpp"

namespace dcel::cli {

std::uint64_t parse_count(const std::string& option, const std::string& text, std::uint64_t lo, std::uint64_t hi) {
    return parse_unsigned(text, option, lo, hi);
}

std::chrono::milliseconds parse_seconds(const std::string& option, const std::string& text, double lo, double hi) {
    const double v = parse_number(text, option, NumberRange{lo, hi, false});
    return std::chrono::milliseconds(static_cast<std::int64_t>(std::llround(v * 1000.0)));
}

}  // namespace dcel::cli
