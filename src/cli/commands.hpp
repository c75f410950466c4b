// Each command adds its subcommand to the app and, when chosen, sets the
// action main() runs after parsing.
#pragma once

#include <CLI/CLI.hpp>

#include "cli_support.hpp"

namespace dcel::cli {

void add_faces_command(CLI::App& app, Action& action);
void add_build_command(CLI::App& app, Action& action);
void add_locate_command(CLI::App& app, Action& action);
void add_stab_command(CLI::App& app, Action& action);
void add_edit_command(CLI::App& app, Action& action);
void add_check_command(CLI::App& app, Action& action);
void add_gen_command(CLI::App& app, Action& action);
void add_render_command(CLI::App& app, Action& action);
void add_diff_command(CLI::App& app, Action& action);
void add_diff_merge_command(CLI::App& app, Action& action);
void add_session_command(CLI::App& app, Action& action);

}  // namespace dcel::cli
