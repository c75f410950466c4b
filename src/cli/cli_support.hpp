// Shared plumbing for the dcel commands: reading FILE or - (stdin), writing
// stdout, strict parsing of numbers typed on the command line, and the
// errors that map to exit codes (0 ok, 1 invalid input or a difference
// found, 2 usage error or unreadable file).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "dcel/dcel.hpp"
#include "dcel/graph.hpp"
#include "dcel/io/text_sink.hpp"

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

// ---- Reading (input_output.cpp) and writing (output.cpp). Every failure is
// a UsageError (exit 2) with the OS's reason: "cannot read graph.json: Is a
// directory".

// The input size limit: no file or stdin larger than this is read (a
// UsageError naming --max-input-bytes). The default keeps the heaviest
// command within the memory of a 24 GiB machine: `dcel faces` and `dcel
// build` peak at 4 to 10 times their input, holding the DCEL but never
// their output (docs/formats.md).
inline constexpr std::uint64_t kDefaultMaxInputBytes = std::uint64_t{512} << 20;
void set_max_input_bytes(std::uint64_t bytes);
[[nodiscard]] std::uint64_t max_input_bytes();

// The whole content of a file, or of stdin for "-", at most
// max_input_bytes(). Directories, unreadable files and devices, and
// inputs over the limit are UsageErrors. Peak memory: the input's size
// for a regular file, twice that for a pipe or device.
[[nodiscard]] std::string read_input(const std::string& path);

// Refuses a command line that gives "-" (stdin) for two inputs, before
// anything is read: "GRAPH and --points cannot both be - (stdin)". Each
// entry is the input's name in messages and the path given.
void require_one_stdin(std::initializer_list<std::pair<std::string_view, const std::string*>> inputs);

// Reads and parses a graph; InvalidInput messages get the file name in front.
[[nodiscard]] PlanarGraph load_graph(const std::string& path);

// Builds the DCEL of a graph read from `path` (InvalidInput messages get
// the file name in front), showing the stage on the status line.
[[nodiscard]] Dcel build_dcel(const std::string& path, const PlanarGraph& g);

// Writes all of text to stdout; UsageError when it cannot ("cannot write
// to stdout: No space left on device").
void write_stdout(std::string_view text);

// Creates or truncates the file and writes all of text to it; UsageError
// when it cannot.
void write_file(const std::string& path, std::string_view text);

// A writer that hands its text to a sink a piece at a time (the library's
// streaming writers, dcel/io/text_sink.hpp), e.g.
//   stream_stdout([&](const io::TextSink& sink) { io::write_faces_of(d, sink); });
using Producer = std::function<void(const io::TextSink&)>;

// What `produce` writes, to stdout or to the file as it comes, in writes
// of 256 KiB, so that a large output is never held whole; the failures of
// write_stdout and write_file. A failure once output has begun (a write
// that fails, or `produce` throwing) cannot take back what was written:
// stdout or the file then holds the output's first part, cut anywhere,
// and the command reports the error and fails (docs/formats.md, "Limits
// and errors").
void stream_stdout(const Producer& produce);
void stream_file(const std::string& path, const Producer& produce);

// Flushes what the C and C++ streams hold for stdout (CLI11 prints help
// through std::cout); the OS's reason when that fails, empty otherwise.
[[nodiscard]] std::string flush_stdout();

// Runs f, prefixing the message of any InvalidInput with "<name>: ".
template <class F>
auto with_source(const std::string& path, F&& f) -> decltype(f());

// ---- Numbers typed on the command line, parsed strictly: the whole word,
// nothing around it, in range. A refused word is quoted as typed (escaped):
//   --vertices: expected an integer from 0 to 10000, found "-1"
// The parse_* functions throw UsageError with `what` in front. The
// validators give CLI11 the same check: pass them to ->transform() (not
// ->check(), which makes CLI11 discard the rewrite), and CLI11 puts the
// option's name in front. They rewrite the word in canonical form (1e-400
// becomes 0, 0010 becomes 10), so that CLI11's own conversion into the
// option's variable cannot disagree with the check.

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
[[nodiscard]] double parse_number(std::string_view word, std::string_view what, const NumberRange& range = {});

// A coordinate: parse_number over all finite doubles.
[[nodiscard]] double parse_coordinate(std::string_view word, std::string_view what);

// A size in bytes as typed for --max-input-bytes: digits, optionally
// followed by K, M, G or T (powers of 1024). UsageError naming `what`.
[[nodiscard]] std::uint64_t parse_byte_size(std::string_view word, std::string_view what);

// Validators for CLI::Option::transform(): the same rules and messages.
[[nodiscard]] CLI::Validator unsigned_in(std::uint64_t min = 0,
                                         std::uint64_t max = std::numeric_limits<std::uint64_t>::max());
[[nodiscard]] CLI::Validator number_in(NumberRange range);
[[nodiscard]] CLI::Validator byte_size();

}  // namespace dcel::cli

#include "cli_support_inl.hpp"
