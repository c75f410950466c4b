// The options that say how to read another implementation's answer, shared
// by `dcel check` and `dcel diff`: --answer KIND, --face-on left|right,
// --one-based, --unoriented (docs/checking.md, "Answer kinds").
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>

#include "dcel/diff/options.hpp"

namespace dcel::cli {

using diff::AnswerOptions;

// Adds the options to cmd; `out` is filled as CLI11 parses.
void add_answer_options(CLI::App& cmd, const std::shared_ptr<AnswerOptions>& out);

}  // namespace dcel::cli
