// Shared plumbing for the dcel commands: reading FILE or - (stdin), writing
// stdout, strict parsing of numbers typed on the command line, and the
// errors that map to exit codes (0 ok, 1 invalid input or a difference
// found, 2 usage error or unreadable file).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include "dcel/graph.hpp"

namespace dcel::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInvalid = 1;  // invalid input, or a difference found
inline constexpr int kExitUsage = 2;    // bad arguments, unreadable file

// A command's work, run after the arguments parsed; returns the exit code.
using Action = std::function<int()>;

// Thrown for usage errors and unreadable files (exit 2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The name used in messages: "<stdin>" for "-", otherwise the path escaped
// for a one-line message (dcel/format.hpp).
[[nodiscard]] std::string display_name(const std::string& path);

// The whole content of a file, or of stdin for "-". Throws UsageError.
[[nodiscard]] std::string read_input(const std::string& path);

// Reads and parses a graph; InvalidInput messages get the file name in front.
[[nodiscard]] PlanarGraph load_graph(const std::string& path);

// Writes all of text to stdout (one write call for large outputs).
void write_stdout(std::string_view text);

// Runs f, prefixing the message of any InvalidInput with "<name>: ".
template <class F>
auto with_source(const std::string& path, F&& f) -> decltype(f());

// ---- Numbers typed on the command line, parsed strictly: the whole word,
// nothing around it, in range. A refused word is quoted as typed (escaped):
//   --vertices: expected an integer from 0 to 10000, found "-1"
// The parse_* functions throw UsageError with `what` in front; the
// validators give CLI11 the same check for ->check() (CLI11 then puts the
// option's name in front) and rewrite the word in its canonical form, so
// that CLI11's own conversion into the option's variable cannot disagree.

// A decimal integer from min to max: digits only (no sign, no spaces, no
// exponent); a leading '-' or a value past max is refused, never wrapped.
[[nodiscard]] std::uint64_t parse_unsigned(std::string_view word, std::string_view what, std::uint64_t min = 0,
                                           std::uint64_t max = std::numeric_limits<std::uint64_t>::max());

// Bounds of a real-valued option; min_exclusive makes the lower bound open
// ("greater than 0").
struct NumberRange {
    double min = -std::numeric_limits<double>::max();
    double max = std::numeric_limits<double>::max();
    bool min_exclusive = false;
};

// A number written as JSON writes it (-1.5, 2e-3; no '+', no leading '.',
// no nan or inf), read correctly rounded exactly as the JSON reader reads
// the same literal: 1e-400 is 0, 1e400 is refused. Then checked against
// the range.
[[nodiscard]] double parse_number(std::string_view word, std::string_view what, NumberRange range = {});

// A coordinate: parse_number over all finite doubles.
[[nodiscard]] double parse_coordinate(std::string_view word, std::string_view what);

// Validators for CLI::Option::check(): the same rules and messages.
[[nodiscard]] CLI::Validator unsigned_in(std::uint64_t min = 0,
                                         std::uint64_t max = std::numeric_limits<std::uint64_t>::max());
[[nodiscard]] CLI::Validator number_in(NumberRange range);

}  // namespace dcel::cli

#include "cli_support_inl.hpp"
