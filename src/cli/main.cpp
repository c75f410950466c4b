// dcel: the command-line face of the exact reference DCEL.
// Exit codes: 0 success, 1 invalid input or a difference found, 2 usage error.
#include <fcntl.h>

#include <cerrno>
#include <cstdio>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "commands.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "status_line.hpp"

namespace {

using namespace dcel::cli;

// The longest CLI11 message shown; the rest is in --help.
constexpr std::size_t kMaxUsageBytes = 300;

// Every message is one line: pieces the user controls are escaped where
// the message is made; this catches any that were not.
void print_error(std::string_view message) {
    StatusLine::stop();
    const std::string line = dcel::needs_escaping(message) ? dcel::escape_for_message(message, 4096) : std::string(message);
    std::fprintf(stderr, "dcel: %s\n", line.c_str());
}

// A closed stdin, stdout or stderr (`dcel faces >&-`) would hand its number
// to the next file opened, and output meant for stdout would land in it.
// Each closed one gets /dev/null opened the wrong way round instead, so that
// reading stdin or writing stdout fails (EBADF) and is reported.
// open() returns the lowest free descriptor, which is fd itself: the ones
// below it are open or were filled on earlier turns of the loop.
void guard_standard_descriptors() {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        (void)::open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY);
    }
}

// The exit code, after making sure that what went to stdout got there.
int finish(int code) {
    StatusLine::stop();
    if (const std::string reason = flush_stdout(); !reason.empty()) {
        std::fprintf(stderr, "dcel: cannot write to stdout: %s\n", reason.c_str());
        return kExitUsage;
    }
    return code;
}

// --help and --version: CLI11's text, written to stdout with the same
// checks as every other output.
int print_help(CLI::App& app, const CLI::ParseError& e) {
    std::ostringstream out;
    std::ostringstream err;
    const int code = app.exit(e, out, err);
    try {
        write_stdout(out.str());
    } catch (const UsageError& failed) {
        print_error(failed.what());
        return kExitUsage;
    }
    return finish(code == 0 ? kExitOk : kExitUsage);
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
        const std::vector<std::string> extras = app.remaining(true);
        if (!extras.empty()) {
            text = extras.size() == 1 ? "unexpected argument" : "unexpected arguments";
            for (const std::string& word : extras) text += " " + dcel::quote_for_message(word, 60);
        }
    }
    if (dcel::needs_escaping(text) || text.size() > kMaxUsageBytes) text = dcel::escape_for_message(text, kMaxUsageBytes);
    const std::string name = parsed.empty() ? "" : parsed.front()->get_name();
    return (name.empty() ? "" : name + ": ") + text + " (dcel " + (name.empty() ? "" : name + " ") + "--help)";
}

// The program's options and commands; the command parsed sets `action`,
// and --max-input-bytes `max_input`.
void add_options_and_commands(CLI::App& app, Action& action, std::uint64_t& max_input) {
    app.set_version_flag("--version", std::string("dcel ") + DCEL_VERSION + " (commit " + DCEL_COMMIT + ")");
    app.require_subcommand(1);
    // Global options may also come after the command: `dcel faces --max-input-bytes 1G big.json`.
    app.fallthrough(true);
    app.add_option("--max-input-bytes", max_input,
                   "Refuse a file or stdin larger than this many bytes (K, M, G, T: powers of 1024; default 512M)")
        ->type_name("BYTES")
        ->transform(byte_size());
    add_faces_command(app, action);
    add_build_command(app, action);
    add_locate_command(app, action);
    add_stab_command(app, action);
    add_edit_command(app, action);
    add_session_command(app, action);
    add_check_command(app, action);
    add_gen_command(app, action);
    add_render_command(app, action);
    add_diff_command(app, action);
    add_diff_merge_command(app, action);
}

// CLI11 answers "A subcommand is required" to a misspelt command; this
// names it and lists the commands instead. False when argv[1] is one.
bool refuse_unknown_command(const CLI::App& app, int argc, char** argv) {
    if (argc <= 1 || argv[1][0] == '-') return false;
    const std::string_view word = argv[1];
    for (const CLI::App* sub : app.get_subcommands({})) {
        if (sub->get_name() == word) return false;
    }
    print_error("unknown command " + dcel::quote_for_message(word) + "; the commands are " + command_list(app) +
                " (dcel --help)");
    return true;
}

// Parses the command line: nothing when the command is to run, else the
// exit code (after --help or --version, or a usage error).
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return print_help(app, e);
    } catch (const CLI::CallForAllHelp& e) {
        return print_help(app, e);
    } catch (const CLI::CallForVersion& e) {
        return print_help(app, e);
    } catch (const CLI::ParseError& e) {
        print_error(usage_message(app, e, argc, argv));
        return kExitUsage;
    } catch (const UsageError& e) {
        print_error(e.what());
        return kExitUsage;
    }
    return std::nullopt;
}

// Runs the command; every failure it reports becomes one line and its exit code.
int run_command(const Action& action) {
    try {
        return finish(action());
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

}  // namespace

// Setting up the parser can throw only std::bad_alloc, and terminating is right then.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    guard_standard_descriptors();
    CLI::App app{
        "dcel: exact reference DCEL (half-edge structure) for planar straight-line graphs.\n"
        "Input graphs are JSON: {\"vertices\": [[x, y], ...], \"edges\": [[u, v], ...]}.",
        "dcel"};
    Action action;
    std::uint64_t max_input = kDefaultMaxInputBytes;
    add_options_and_commands(app, action, max_input);
    if (refuse_unknown_command(std::as_const(app), argc, argv)) return kExitUsage;
    if (const std::optional<int> code = parse_command_line(app, argc, argv)) return *code;
    set_max_input_bytes(max_input);
    if (const std::vector<CLI::App*> parsed = app.get_subcommands(); !parsed.empty()) {
        StatusLine::start(parsed.front()->get_name());
    }
    return run_command(action);
}
