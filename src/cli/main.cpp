// dcel: the command-line face of the exact reference DCEL.
// Exit codes: 0 success, 1 invalid input or a difference found, 2 usage error.
#include <cstdio>
#include <new>
#include <string>
#include <string_view>
#include <utility>

#include "commands.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"

namespace {

using namespace dcel::cli;

// The longest CLI11 message shown; the rest is in --help.
constexpr std::size_t kMaxUsageBytes = 300;

// Every message is one line: pieces the user controls are escaped where
// the message is made; this catches any that were not.
void print_error(std::string_view message) {
    const std::string line = dcel::needs_escaping(message) ? dcel::escape_for_message(message, 4096) : std::string(message);
    std::fprintf(stderr, "dcel: %s\n", line.c_str());
}

std::string command_list(const CLI::App& app) {
    std::string names;
    for (const CLI::App* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
    return names;
}

// A usage error found by CLI11, in the form of every other message:
// "dcel: gen: --vertices: expected ..., found "-1" (dcel gen --help)".
// CLI11's words are kept; what it echoes from argv is escaped.
std::string usage_message(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    if (parsed.empty()) {
        // No command recognised: name the word that is in the way.
        for (int i = 1; i < argc; ++i) {
            const std::string_view word = argv[i];
            if (word == "--") break;
            if (word.size() > 1 && word[0] == '-' &&
                app.get_option_no_throw(std::string(word.substr(0, word.find('=')))) == nullptr) {
                return "unknown option " + dcel::quote_for_message(word) + "; options go after the command (dcel --help)";
            }
        }
        if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr) {
            return "no command given; the commands are " + command_list(app) + " (dcel --help)";
        }
    }
    std::string text = e.what();
    if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
        // CLI11 lists them last first; each is quoted here, escaped.
        std::vector<std::string> extras = parsed.empty() ? app.remaining() : parsed.front()->remaining();
        if (!extras.empty()) {
            text = extras.size() == 1 ? "unexpected argument" : "unexpected arguments";
            for (const std::string& word : extras) text += " " + dcel::quote_for_message(word, 60);
        }
    }
    if (dcel::needs_escaping(text) || text.size() > kMaxUsageBytes) text = dcel::escape_for_message(text, kMaxUsageBytes);
    const std::string name = parsed.empty() ? "" : parsed.front()->get_name();
    return (name.empty() ? "" : name + ": ") + text + " (dcel " + (name.empty() ? "" : name + " ") + "--help)";
}

}  // namespace

// Setting up the parser can throw only std::bad_alloc, and terminating is right then.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    CLI::App app{
        "dcel: exact reference DCEL (half-edge structure) for planar straight-line graphs.\n"
        "Input graphs are JSON: {\"vertices\": [[x, y], ...], \"edges\": [[u, v], ...]}.",
        "dcel"};
    app.set_version_flag("--version", std::string("dcel ") + DCEL_VERSION + " (commit " + DCEL_COMMIT + ")");
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
        bool known = false;
        for (const CLI::App* sub : std::as_const(app).get_subcommands({})) known = known || sub->get_name() == word;
        if (!known) {
            print_error("unknown command " + dcel::quote_for_message(word) + "; the commands are " +
                        command_list(std::as_const(app)) + " (dcel --help)");
            return kExitUsage;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e) == 0 ? kExitOk : kExitUsage;  // the help, on stdout
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e) == 0 ? kExitOk : kExitUsage;
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e) == 0 ? kExitOk : kExitUsage;
    } catch (const CLI::ParseError& e) {
        print_error(usage_message(app, e, argc, argv));
        return kExitUsage;
    } catch (const UsageError& e) {
        print_error(e.what());
        return kExitUsage;
    }
    try {
        return action();
    } catch (const dcel::InvalidInput& e) {
        print_error(e.what());
        return kExitInvalid;
    } catch (const dcel::TopologyError& e) {  // an edit refused
        print_error(e.what());
        return kExitInvalid;
    } catch (const UsageError& e) {
        print_error(e.what());
        return kExitUsage;
    } catch (const std::bad_alloc&) {
        print_error("out of memory: the input is too large for this machine");
        return kExitInvalid;
    }
}
