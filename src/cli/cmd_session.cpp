// dcel session [SESSION|-]: an edit session (docs/checking.md, "Sessions")
// run on the reference: each step's answer and the state after the last, on
// one line, as a right implementation answers it. This is what
// `dcel diff --sessions` compares another program's answer with.
#include "commands.hpp"
#include "dcel/check/session.hpp"

namespace dcel::cli {

void add_session_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("session",
                                   "Run an edit session (a start graph and steps) on the reference and print its answer");
    auto path = std::make_shared<std::string>("-");
    auto each_step = std::make_shared<bool>(false);
    cmd->add_option("SESSION", *path, "Session JSON file (docs/checking.md, \"Sessions\"), or - for stdin (the default)");
    cmd->add_flag("--each-step", *each_step,
                  "Also give the state after every edit, in its answer (as \"each_step\": true in the session asks)");
    cmd->callback([&action, path, each_step] {
        action = [path, each_step] {
            const std::string text = read_input(*path);
            write_stdout(with_source(*path, [&] {
                const check::Session s = check::read_session(text);
                return check::reference_session_answer(s, *each_step || s.each_step);
            }));
            return kExitOk;
        };
    });
}

}  // namespace dcel::cli
