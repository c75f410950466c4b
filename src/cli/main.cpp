// dcel: the command-line face of the exact reference DCEL.
// Exit codes: 0 success, 1 invalid input or a difference found, 2 usage error.
#include <fcntl.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <new>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>

#include "commands.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/io/decimal.hpp"
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
void guard_standard_descriptors() {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        const int opened = ::open("/dev/null", fd == 0 ? O_WRONLY : O_RDONLY);
        if (opened >= 0 && opened != fd) {
            ::dup2(opened, fd);
            ::close(opened);
        }
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

// CLI11 writes range bounds in full ("not in range 0.000000 to 179769...",
// 309 digits for the largest double): such a number, more than 24 digits
// long, is shown in its shortest form instead (1.7976931348623157e+308).
std::string shorten_numbers(const std::string& text) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        std::size_t end = i;
        while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])) != 0) ++end;
        if (end < text.size() && text[end] == '.') {
            std::size_t frac = end + 1;
            while (frac < text.size() && std::isdigit(static_cast<unsigned char>(text[frac])) != 0) ++frac;
            if (frac > end + 1) end = frac;
        }
        if (end - i > 24) {
            double value = 0;
            const std::string digits = text.substr(i, end - i);
            const auto [ptr, ec] = dcel::io::parse_double(digits.data(), digits.data() + digits.size(), value);
            out += ec == std::errc() && ptr == digits.data() + digits.size() ? dcel::format_double(value) : digits;
            i = end;
        } else if (end > i) {
            out.append(text, i, end - i);
            i = end;
        } else {
            out += text[i++];
        }
    }
    return out;
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
    std::string text = shorten_numbers(e.what());
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

}  // namespace

// Setting up the parser can throw only std::bad_alloc, and terminating is right then.
int main(int argc, char** argv) {  // NOLINT(bugprone-exception-escape)
    guard_standard_descriptors();
    CLI::App app{
        "dcel: exact reference DCEL (half-edge structure) for planar straight-line graphs.\n"
        "Input graphs are JSON: {\"vertices\": [[x, y], ...], \"edges\": [[u, v], ...]}.",
        "dcel"};
    app.set_version_flag("--version", std::string("dcel ") + DCEL_VERSION + " (commit " + DCEL_COMMIT + ")");
    app.require_subcommand(1);
    // Global options may also come after the command: `dcel faces --max-input-bytes 1G big.json`.
    app.fallthrough(true);
    std::uint64_t max_input = kDefaultMaxInputBytes;
    app.add_option("--max-input-bytes", max_input,
                   "Refuse a file or stdin larger than this many bytes (K, M, G, T: powers of 1024; default 512M)")
        ->type_name("BYTES")
        ->transform(byte_size());
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
    set_max_input_bytes(max_input);
    if (const std::vector<CLI::App*> parsed = app.get_subcommands(); !parsed.empty()) {
        StatusLine::start(parsed.front()->get_name());
    }
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
