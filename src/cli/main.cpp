// dcel: the command-line face of the exact reference DCEL.
// Exit codes: 0 success, 1 invalid input or a difference found, 2 usage error.
#include <cstdio>
#include <new>
#include <string>
#include <string_view>
#include <utility>

#include "commands.hpp"
#include "dcel/error.hpp"

// Setting up the parser can throw only std::bad_alloc, and terminating is right then.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    using namespace dcel::cli;
    CLI::App app{
        "dcel: exact reference DCEL (half-edge structure) for planar straight-line graphs.\n"
        "Input graphs are JSON: {\"vertices\": [[x, y], ...], \"edges\": [[u, v], ...]}.",
        "dcel"};
    app.set_version_flag("--version", DCEL_VERSION);
    app.require_subcommand(1);
    app.fallthrough(false);
    Action action;
    add_faces_command(app, action);
    add_build_command(app, action);
    add_locate_command(app, action);
    add_stab_command(app, action);
    add_edit_command(app, action);
    add_check_command(app, action);
    add_gen_command(app, action);
    add_render_command(app, action);
    add_diff_command(app, action);

    // CLI11 answers "A subcommand is required" to a misspelt command; name it
    // and list the commands instead.
    if (argc > 1 && argv[1][0] != '-') {
        const std::string_view word = argv[1];
        std::string names;
        bool known = false;
        for (const CLI::App* sub : std::as_const(app).get_subcommands({})) {
            known = known || sub->get_name() == word;
            names += (names.empty() ? "" : ", ") + sub->get_name();
        }
        if (!known) {
            std::fprintf(stderr, "dcel: unknown command \"%s\"; the commands are %s (dcel --help)\n", argv[1],
                         names.c_str());
            return kExitUsage;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);  // prints help (stdout) or the error (stderr)
        return code == 0 ? kExitOk : kExitUsage;
    }
    try {
        return action();
    } catch (const dcel::InvalidInput& e) {
        std::fprintf(stderr, "dcel: %s\n", e.what());
        return kExitInvalid;
    } catch (const dcel::TopologyError& e) {  // an edit refused
        std::fprintf(stderr, "dcel: %s\n", e.what());
        return kExitInvalid;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "dcel: %s\n", e.what());
        return kExitUsage;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "dcel: out of memory: the input is too large for this machine\n");
        return kExitInvalid;
    }
}
