#include "cli_support.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "dcel/format.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/json_reader.hpp"

namespace dcel::cli {

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : escape_for_message(path); }

// ---------------------------------------------------------------- numbers

namespace {

std::string found(std::string_view word) { return ", found " + quote_for_message(word); }

std::string unsigned_expectation(std::uint64_t min, std::uint64_t max) {
    if (max == std::numeric_limits<std::uint64_t>::max()) {
        return min == 0 ? "a non-negative integer (at most 18446744073709551615)"
                        : "an integer from " + std::to_string(min) + " to 18446744073709551615";
    }
    return "an integer from " + std::to_string(min) + " to " + std::to_string(max);
}

std::string number_expectation(const NumberRange& r) {
    constexpr double kMax = std::numeric_limits<double>::max();
    const bool low = r.min > -kMax || r.min_exclusive;
    const bool high = r.max < kMax;
    std::string s = "a finite number";
    if (low) s += (r.min_exclusive ? " greater than " : " at least ") + format_double(r.min);
    if (low && high) s += " and";
    if (high) s += " at most " + format_double(r.max);
    return s;
}

// The message for a refused word (without `what`), or "" when it is fine.
std::string check_unsigned(std::string_view word, std::uint64_t min, std::uint64_t max, std::uint64_t& value) {
    const char* const end = word.data() + word.size();
    const bool digits_only = !word.empty() &&
                             std::all_of(word.begin(), word.end(), [](char c) { return c >= '0' && c <= '9'; });
    const auto [ptr, ec] = std::from_chars(word.data(), end, value);
    if (!digits_only || ec != std::errc() || ptr != end || value < min || value > max) {
        return "expected " + unsigned_expectation(min, max) + found(word);
    }
    return {};
}

std::string check_number(std::string_view word, const NumberRange& r, double& value) {
    bool read = false;
    try {
        io::JsonReader reader(word);
        if (reader.peek() == io::JsonType::Number) {
            value = reader.read_double();
            reader.end_document();
            read = true;
        }
    } catch (const InvalidInput&) {
        read = false;  // not a JSON number, or beyond the range of a double
    }
    // The reader would skip whitespace and a BOM around the number; a word on
    // the command line is taken as typed.
    const bool bare = !word.empty() && word.find_first_not_of("0123456789+-.eE") == std::string_view::npos;
    if (!read || !bare || !(r.min_exclusive ? value > r.min : value >= r.min) || !(value <= r.max)) {
        return "expected " + number_expectation(r) + found(word);
    }
    return {};
}

// Digits and an optional K, M, G or T (powers of 1024).
std::string check_byte_size(std::string_view word, std::uint64_t& value) {
    int shift = 0;
    std::string_view digits = word;
    if (!digits.empty()) {
        const std::string_view units = "KMGT";
        if (const std::size_t k = units.find(digits.back()); k != std::string_view::npos) {
            shift = 10 * static_cast<int>(k + 1);
            digits.remove_suffix(1);
        }
    }
    const std::uint64_t max = std::numeric_limits<std::uint64_t>::max() >> shift;
    if (!check_unsigned(digits, 0, max, value).empty()) {
        return "expected a size in bytes below 2^64: digits, optionally followed by K, M, G or T (powers of 1024)" +
               found(word);
    }
    value <<= shift;
    return {};
}

}  // namespace

std::uint64_t parse_unsigned(std::string_view word, std::string_view what, std::uint64_t min, std::uint64_t max) {
    std::uint64_t value = 0;
    if (std::string message = check_unsigned(word, min, max, value); !message.empty()) {
        throw UsageError(std::string(what) + ": " + message);
    }
    return value;
}

double parse_number(std::string_view word, std::string_view what, const NumberRange& range) {
    double value = 0;
    if (std::string message = check_number(word, range, value); !message.empty()) {
        throw UsageError(std::string(what) + ": " + message);
    }
    return value;
}

std::uint64_t parse_byte_size(std::string_view word, std::string_view what) {
    std::uint64_t value = 0;
    if (std::string message = check_byte_size(word, value); !message.empty()) {
        throw UsageError(std::string(what) + ": " + message);
    }
    return value;
}

double parse_coordinate(std::string_view word, std::string_view what) { return parse_number(word, what, {}); }

CLI::Validator unsigned_in(std::uint64_t min, std::uint64_t max) {
    return {[min, max](std::string& word) {
                std::uint64_t value = 0;
                std::string message = check_unsigned(word, min, max, value);
                if (message.empty()) word = std::to_string(value);
                return message;
            },
            ""};
}

CLI::Validator byte_size() {
    return {[](std::string& word) {
                std::uint64_t value = 0;
                std::string message = check_byte_size(word, value);
                if (message.empty()) word = std::to_string(value);
                return message;
            },
            ""};
}

CLI::Validator number_in(NumberRange range) {
    return {[range](std::string& word) {
                double value = 0;
                std::string message = check_number(word, range, value);
                if (message.empty()) word = format_double(value);
                return message;
            },
            ""};
}

}  // namespace dcel::cli
