// Shared plumbing for the dcel commands: reading FILE or - (stdin), writing
// stdout, and the errors that map to exit codes (0 ok, 1 invalid input or a
// difference found, 2 usage error or unreadable file).
#pragma once

#include <functional>
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

// The name used in messages: "<stdin>" for "-".
[[nodiscard]] std::string display_name(const std::string& path);

// The whole content of a file, or of stdin for "-". Throws UsageError.
[[nodiscard]] std::string read_input(const std::string& path);

// Reads and parses a graph; InvalidInput messages get the file name in front.
[[nodiscard]] PlanarGraph load_graph(const std::string& path);

// A coordinate given on the command line: a finite number, read correctly
// rounded. UsageError naming `what` otherwise.
[[nodiscard]] double parse_coordinate(const std::string& text, const std::string& what);

// Writes all of text to stdout (one write call for large outputs).
void write_stdout(std::string_view text);

// Runs f, prefixing the message of any InvalidInput with "<name>: ".
template <class F>
auto with_source(const std::string& path, F&& f) -> decltype(f());

}  // namespace dcel::cli

#include "cli_support_inl.hpp"
