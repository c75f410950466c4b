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

std::string read_input(const std::string& path) {
    std::FILE* f = path == "-" ? stdin : std::fopen(path.c_str(), "rb");
    if (f == nullptr) throw UsageError("cannot open " + display_name(path) + ": " + std::strerror(errno));
    std::string text;
    // Reserve a regular file's size up front: no regrowth copies of a large input.
    if (f != stdin && std::fseek(f, 0, SEEK_END) == 0) {
        const long size = std::ftell(f);
        if (size > 0) text.reserve(static_cast<std::size_t>(size));
        std::rewind(f);
    }
    char buffer[1 << 16];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    const bool failed = std::ferror(f) != 0;
    if (f != stdin) std::fclose(f);
    if (failed) throw UsageError("cannot read " + display_name(path));
    return text;
}

PlanarGraph load_graph(const std::string& path) {
    const std::string text = read_input(path);
    return with_source(path, [&] { return io::read_graph(text); });
}

void write_stdout(std::string_view text) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fflush(stdout);
}

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

}  // namespace

std::uint64_t parse_unsigned(std::string_view word, std::string_view what, std::uint64_t min, std::uint64_t max) {
    std::uint64_t value = 0;
    if (std::string message = check_unsigned(word, min, max, value); !message.empty()) {
        throw UsageError(std::string(what) + ": " + message);
    }
    return value;
}

double parse_number(std::string_view word, std::string_view what, NumberRange range) {
    double value = 0;
    if (std::string message = check_number(word, range, value); !message.empty()) {
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
