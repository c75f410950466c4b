// What `dcel diff` reports: the text on stdout (a one-line verdict when every
// case agrees; otherwise each distinct failure with its shrunk
// counterexample, the reference, what the command said, the differences and
// how to replay it, then a summary), the JSON report (--report, schema in
// docs/diff-report.schema.json) and JUnit XML (--junit) for CI systems.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "dcel/diff/session.hpp"

namespace dcel::diff {

// At most this many bytes of an answer or of stderr are shown.
inline constexpr std::size_t kShownBytes = 2000;

[[nodiscard]] std::string format_report(const DiffOptions& options, const DiffResult& result);

// Whether the run passes (exit 0): no failure, and something was checked
// (a run whose every case the implementation skipped is no pass).
[[nodiscard]] bool run_passes(const DiffResult& result);

[[nodiscard]] std::string report_json(const DiffOptions& options, const DiffResult& result);   // report_json.cpp
[[nodiscard]] std::string report_junit(const DiffOptions& options, const DiffResult& result);  // report_junit.cpp

// The body of one failure in the text report: how it shrank, the graph, the
// reference, the answer, the differences, how to replay it (JUnit's failure
// text too).
void failure_body(std::ostream& s, const DiffOptions& options, const Failure& f);

// "12.3 s"; "3 cases", "1 case".
[[nodiscard]] std::string seconds(std::chrono::milliseconds ms);
[[nodiscard]] std::string count(std::size_t n, const std::string& noun);
// "5 vertices, 4 edges".
[[nodiscard]] std::string size_of(const PlanarGraph& g);
[[nodiscard]] std::string size_of(std::size_t vertices, std::size_t edges);
// With a session's steps: "5 vertices, 4 edges, 3 steps".
[[nodiscard]] std::string size_of(const PlanarGraph& g, const std::optional<check::Session>& session);
// The text without its trailing newlines.
[[nodiscard]] std::string without_newline(std::string text);
// The command line of the whole run (the report's "command").
[[nodiscard]] std::string run_command_line(const DiffOptions& options);

// The shell command line that replays a case: dcel diff --case N with every
// option the case depends on.
[[nodiscard]] std::string replay_command(const DiffOptions& options, std::size_t case_number);

// The options that decide the schedule and how answers are read, as
// command-line words (shared by the replay and --print-case lines).
[[nodiscard]] std::string schedule_arguments(const DiffOptions& options);

// Text as XML character data and attribute values, well-formed whatever the
// bytes (report_junit.cpp).
[[nodiscard]] std::string xml_text(std::string_view text);

// A word for the shell: 'text' with every ' written as '\''.
[[nodiscard]] std::string shell_quote(const std::string& text);

}  // namespace dcel::diff
