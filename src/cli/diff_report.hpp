// What `dcel diff` reports: the text on stdout (a one-line verdict when every
// case agrees; otherwise each distinct failure with its shrunk
// counterexample, the reference, what the command said, the differences and
// how to replay it, then a summary), the JSON report (--report, schema in
// docs/diff-report.schema.json) and JUnit XML (--junit) for CI systems.
#pragma once

#include <string>
#include <vector>

#include "diff_session.hpp"

namespace dcel::cli {

[[nodiscard]] std::string format_report(const DiffOptions& options, const DiffResult& result);

[[nodiscard]] std::string report_json(const DiffOptions& options, const DiffResult& result);
[[nodiscard]] std::string report_junit(const DiffOptions& options, const DiffResult& result);

// The shell command line that replays a case: dcel diff --case N with every
// option the case depends on.
[[nodiscard]] std::string replay_command(const DiffOptions& options, std::size_t case_number);

// The options that decide the schedule and how answers are read, as
// command-line words (shared by the replay and --print-case lines).
[[nodiscard]] std::string schedule_arguments(const DiffOptions& options);

// A word for the shell: 'text' with every ' written as '\''.
[[nodiscard]] std::string shell_quote(const std::string& text);

}  // namespace dcel::cli
