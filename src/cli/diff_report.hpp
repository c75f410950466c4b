// The text `dcel diff` prints: a one-line verdict when every case agrees, or
// the counterexample report (graph, reference, what the command said, the
// first difference, how to replay).
#pragma once

#include <string>

#include "diff_session.hpp"

namespace dcel::cli {

[[nodiscard]] std::string format_report(const DiffOptions& options, const DiffResult& result);

// The shell command line that replays the failing case: dcel diff --case ...
[[nodiscard]] std::string replay_command(const DiffOptions& options, std::size_t case_number);

// A word for the shell: 'text' with every ' written as '\''.
[[nodiscard]] std::string shell_quote(const std::string& text);

}  // namespace dcel::cli
