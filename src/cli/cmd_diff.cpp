// dcel diff --impl CMD: differential fuzzing of a foreign implementation
// against the reference. Options and output here; the case schedule in
// diff_cases, the case loop and the shrinking in diff_session, the report in
// diff_report, the process handling in process.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>

#include "answer_options.hpp"
#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/check/counterexample_svg.hpp"
#include "dcel/check/session.hpp"
#include "dcel/diff/report.hpp"
#include "dcel/diff/report_html.hpp"
#include "dcel/diff/session.hpp"
#include "dcel/format.hpp"
#include "option_values.hpp"

namespace dcel::cli {
namespace {

using diff::Case;
using diff::Counterexample;
using diff::DiffOptions;
using diff::DiffResult;
using diff::Failure;
using diff::Progress;

constexpr const char* kFooter = R"(Protocol (docs/checking.md): CMD runs as /bin/sh -c CMD. It reads one graph,
{"vertices": [[x, y], ...], "edges": [[u, v], ...]} on one line (numbers in any
valid JSON spelling: 3, 3.0, 3e0, -0.0, 5e-324; sometimes the positional form
[[[x, y], ...], [[u, v], ...]]), and prints its answer on stdout, then exits
with status 0. The answer is one of the kinds of --answer (detected from its
shape when not given): every boundary cycle ({"faces": [[v0, v1, ...], ...]}),
a whole DCEL (the `dcel build` format), the bounded faces as polygons with
holes (vertex-id or coordinate rings, or GeoJSON), or one ring per bounded
face. With --stream, "CMD --stream" starts once and reads one graph per line,
and must print each answer on one line; after a crash or a timeout it is
started again.

A failure is a crash (a signal; /bin/sh's exit status 128 + N counts as
signal N), a non-zero exit, a timeout, an answer that cannot be read, or a
wrong answer. Each failing graph is shrunk to a small one that fails the same
way, and reported with the reference answer, what CMD said, the differences
and a command line that replays the case. By default the run stops at the
first failure; with --keep-going (the default under --time) it goes on,
groups failures into distinct bugs and shrinks each once.

Exit status: 0 every case agrees; 1 a failure (the report is on stdout);
2 usage error, an unwritable report file, or a CMD that /bin/sh cannot run at
all (status 126 or 127 on the first case: not found, not executable).)";

// "a,b,c" -> {a, b, c}, each looked up by `parse`; UsageError naming the option.
template <class T, class Parse>
std::vector<T> parse_list(const std::string& option, const std::string& text, Parse parse, const std::string& known) {
    std::vector<T> out;
    std::size_t begin = 0;
    while (begin <= text.size()) {
        const std::size_t end = std::min(text.find(',', begin), text.size());
        const std::string word = text.substr(begin, end - begin);
        const std::optional<T> v = parse(word);
        if (!v) {
            std::string message = option;
            message.append(": unknown name ").append(dcel::quote_for_message(word)).append("; the names are ").append(known);
            throw UsageError(message);
        }
        if (std::find(out.begin(), out.end(), *v) == out.end()) out.push_back(*v);
        begin = end + 1;
    }
    return out;
}

template <class T>
std::vector<T> without(std::span<const T> all, const std::vector<T>& excluded) {
    std::vector<T> out;
    for (const T& x : all) {
        if (std::find(excluded.begin(), excluded.end(), x) == excluded.end()) out.push_back(x);
    }
    return out;
}

std::string names_of_families() {
    std::string s;
    for (const gen::Family f : gen::all_families()) s += (s.empty() ? "" : ", ") + std::string(gen::family_name(f));
    return s;
}

std::string names_of_classes() {
    std::string s;
    for (const gen::CoordinateClass c : gen::all_coordinate_classes()) {
        s += (s.empty() ? "" : ", ") + std::string(gen::coordinate_class_name(c));
    }
    return s;
}

// FILE for failure 1, FILE-2.svg style names for the others.
std::string numbered(const std::string& path, std::size_t id) {
    if (id == 1) return path;
    const std::size_t dot = path.rfind('.');
    const std::size_t slash = path.rfind('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + "-" + std::to_string(id);
    return path.substr(0, dot) + "-" + std::to_string(id) + path.substr(dot);
}

// The counterexample with the reference and the answer side by side, and an
// inset at each vertex where the answer turns differently (docs/pictures.md).
std::string svg_of(const DiffOptions& options, const Failure& f) {
    const Counterexample& c = f.example;
    if (c.session) {
        // The first step answered wrongly over the state before it (the end
        // state when only that differs, or when the run did not get that far).
        const std::size_t k = c.outcome.report.first_wrong_step.value_or(c.session->steps.size());
        return check::render_session_step_svg(*c.session, k,
                                              "dcel diff --sessions: " + diff::failure_label(c.outcome) + ", case " +
                                                  std::to_string(c.original.spec.number) + ", seed " +
                                                  std::to_string(options.schedule.seed));
    }
    const Dcel reference = build(c.graph);
    check::CounterexampleDrawing drawing{&c.graph, &reference};
    drawing.title = "dcel diff: " + diff::failure_label(c.outcome) + ", case " + std::to_string(c.original.spec.number) +
                    ", seed " + std::to_string(options.schedule.seed);
    drawing.answer_name = "the command: " + options.impl;
    drawing.answer_cycles = c.outcome.answer_cycles;
    drawing.answer_polygons = c.outcome.answer_polygons;
    return check::render_counterexample_svg(drawing);
}

// The options as typed; empty: the default, which DiffOptions{} holds.
struct RawOptions {
    std::string cases, seed, time, max_vertices, large_vertices, timeout_ms, shrink_time, only_case, max_failures,
        print_case, jobs, shard, max_steps, large_steps;
    std::string families, exclude_families, coordinates, exclude_coordinates;
    std::string svg, report, junit, html;
    bool keep_going = false, stop_at_first = false;
};

constexpr std::uint64_t kMaxCases = std::uint64_t{1} << 40;

// "K/N" with 1 <= K <= N <= 10000.
DiffOptions::Shard parse_shard(const std::string& text) {
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) {
        throw UsageError("--shard: expected K/N (shard K of N, 1 <= K <= N), found \"" + text + "\"");
    }
    DiffOptions::Shard shard;
    shard.count = parse_count("--shard", text.substr(slash + 1), 1, 10000);
    shard.index = parse_count("--shard", text.substr(0, slash), 1, shard.count);
    return shard;
}

void resolve_counts(const RawOptions& raw, DiffOptions& o) {
    if (!raw.cases.empty()) o.cases = parse_count("--cases", raw.cases, 1, kMaxCases);
    if (!raw.seed.empty()) o.schedule.seed = parse_count("--seed", raw.seed, 0, UINT64_MAX);
    if (!raw.time.empty()) o.time = parse_seconds("--time", raw.time, 0.001, 1e7);
    if (!raw.max_vertices.empty()) o.schedule.max_vertices = parse_count("--max-vertices", raw.max_vertices, 1, 100000);
    if (!raw.large_vertices.empty()) {
        o.schedule.large_vertices = parse_count("--large-vertices", raw.large_vertices, 0, 1000000);
    }
    if (!raw.timeout_ms.empty()) {
        o.limits.timeout = std::chrono::milliseconds(parse_count("--timeout-ms", raw.timeout_ms, 1, 86400000));
    }
    if (!raw.shrink_time.empty()) o.shrink_time = parse_seconds("--shrink-time", raw.shrink_time, 0, 1e6);
    if (!raw.only_case.empty()) o.only_case = parse_count("--case", raw.only_case, 0, kMaxCases);
    if (!raw.max_failures.empty()) o.max_failures = parse_count("--max-failures", raw.max_failures, 1, 1000);
    if (!raw.jobs.empty()) o.jobs = parse_count("--jobs", raw.jobs, 1, diff::kMaxJobs);
    if (!raw.shard.empty()) o.shard = parse_shard(raw.shard);
    if (!raw.max_steps.empty()) o.schedule.max_steps = parse_count("--max-steps", raw.max_steps, 1, 1000000);
    if (!raw.large_steps.empty()) o.schedule.large_steps = parse_count("--large-steps", raw.large_steps, 0, 10000000);
}

void resolve_filters(const RawOptions& raw, DiffOptions& o) {
    if (!raw.families.empty() && !raw.exclude_families.empty()) {
        throw UsageError("--families and --exclude-families: give one of them");
    }
    if (!raw.coordinates.empty() && !raw.exclude_coordinates.empty()) {
        throw UsageError("--coordinates and --exclude-coordinates: give one of them");
    }
    auto family = [](const std::string& w) { return gen::family_from_name(w); };
    auto coordinate = [](const std::string& w) { return gen::coordinate_class_from_name(w); };
    if (!raw.families.empty()) {
        o.schedule.families = parse_list<gen::Family>("--families", raw.families, family, names_of_families());
    }
    if (!raw.exclude_families.empty()) {
        o.schedule.families = without(
            gen::all_families(),
            parse_list<gen::Family>("--exclude-families", raw.exclude_families, family, names_of_families()));
        if (o.schedule.families.empty()) throw UsageError("--exclude-families: no family is left");
    }
    if (!raw.coordinates.empty()) {
        o.schedule.classes = parse_list<gen::CoordinateClass>("--coordinates", raw.coordinates, coordinate,
                                                              names_of_classes());
    }
    if (!raw.exclude_coordinates.empty()) {
        o.schedule.classes = without(gen::all_coordinate_classes(),
                                     parse_list<gen::CoordinateClass>("--exclude-coordinates", raw.exclude_coordinates,
                                                                      coordinate, names_of_classes()));
        if (o.schedule.classes.empty()) throw UsageError("--exclude-coordinates: no class is left");
    }
}

DiffOptions resolve(const RawOptions& raw, DiffOptions o) {
    resolve_counts(raw, o);
    resolve_filters(raw, o);
    if (o.schedule.each_step && !o.schedule.sessions) throw UsageError("--each-step goes with --sessions");
    if ((!raw.max_steps.empty() || !raw.large_steps.empty()) && !o.schedule.sessions) {
        throw UsageError("--max-steps and --large-steps go with --sessions");
    }
    if (!o.time && !o.cases) o.cases = diff::defaults::kCases;  // --time alone: as many as fit
    // A shard keeps going: merged, its failures make the whole run's.
    o.keep_going = (raw.keep_going || o.time.has_value() || o.shard.has_value()) && !raw.stop_at_first;
    if (o.only_case) o.keep_going = false;
    o.schedule.one_line = true;  // one graph per line, in both modes
    return o;
}

// " (default N)" from the defaults, so that the help cannot disagree with them.
template <class T>
std::string default_is(const T& value, const std::string& unit = "") {
    return " (default " + std::to_string(value) + unit + ")";
}

void add_schedule_options(CLI::App& cmd, RawOptions& raw, DiffOptions& options) {
    const DiffOptions d;
    cmd.add_option("--cases", raw.cases,
                   "Number of cases (default " + std::to_string(diff::defaults::kCases) + "; unlimited with --time)")
        ->type_name("N");
    cmd.add_option("--seed", raw.seed, "Seed of the case schedule" + default_is(d.schedule.seed))->type_name("S");
    cmd.add_option("--time", raw.time, "Stop looking for failures after T seconds (implies --keep-going)")->type_name("T");
    cmd.add_option("--max-vertices", raw.max_vertices,
                   "Largest size of the growing cases" + default_is(d.schedule.max_vertices))
        ->type_name("K");
    cmd.add_option(
           "--large-vertices", raw.large_vertices,
           "Size of every 50th case, a large one (default " + std::to_string(d.schedule.large_vertices) + "; 0: none)")
        ->type_name("L");
    cmd.add_option("--families", raw.families, "Only these generator families, comma-separated")->type_name("LIST");
    cmd.add_option("--exclude-families", raw.exclude_families, "Every generator family but these")->type_name("LIST");
    cmd.add_option("--coordinates", raw.coordinates,
                   "Only these coordinate classes: small-integers, normal, huge, tiny, subnormal")
        ->type_name("LIST");
    cmd.add_option("--exclude-coordinates", raw.exclude_coordinates, "Every coordinate class but these")->type_name("LIST");
    cmd.add_flag("--positional", options.schedule.positional,
                 "Also send some graphs in the positional form [[[x, y], ...], [[u, v], ...]] (default: object form only)");
    cmd.add_flag("--sessions", options.schedule.sessions,
                 "Check edits and queries: each case is an edit session (a start graph and steps; docs/checking.md, "
                 "\"Sessions\") answered with each step's answer and the state after the last");
    cmd.add_flag("--each-step", options.schedule.each_step,
                 "With --sessions: ask for the state after every edit too, to pin down the first wrong step");
    cmd.add_option("--max-steps", raw.max_steps,
                   "With --sessions: the most steps of the growing sessions" + default_is(d.schedule.max_steps))
        ->type_name("N");
    cmd.add_option("--large-steps", raw.large_steps,
                   "With --sessions: the steps of every 50th session, a large one" + default_is(d.schedule.large_steps))
        ->type_name("N");
}

void add_run_options(CLI::App& cmd, RawOptions& raw, DiffOptions& options) {
    const DiffOptions d;
    cmd.add_flag("--stream", options.stream, "Start \"CMD --stream\" once; one graph per line in, one answer per line out");
    cmd.add_option("--jobs", raw.jobs,
                   "Run N processes of the command at once (at most " + std::to_string(diff::kMaxJobs) +
                       "); the report is the same for every N" + default_is(d.jobs))
        ->type_name("N");
    cmd.add_option("--shard", raw.shard,
                   "Run shard K of N: the cases i with i mod N = K - 1 (implies --keep-going); "
                   "dcel diff-merge joins the shards' reports")
        ->type_name("K/N");
    cmd.add_option("--timeout-ms", raw.timeout_ms,
                   "Time allowed per case, in milliseconds" + default_is(d.limits.timeout.count()))
        ->type_name("M");
    cmd.add_option("--shrink-time", raw.shrink_time,
                   "Time allowed for shrinking each failure, in seconds" + default_is(d.shrink_time.count() / 1000))
        ->type_name("T");
    cmd.add_flag("--keep-going", raw.keep_going,
                 "Go on after a failure: group failures into distinct bugs, shrink each once, end with a summary");
    cmd.add_flag("--stop-at-first", raw.stop_at_first, "Stop at the first failure, also under --time");
    cmd.add_option("--max-failures", raw.max_failures,
                   "With --keep-going, stop after N distinct failures" + default_is(d.max_failures))
        ->type_name("N");
    cmd.add_option("--case", raw.only_case, "Run only case N of the schedule (to replay a report)")->type_name("N");
    cmd.add_option("--print-case", raw.print_case, "Print case N's graph, its exact bytes, and run nothing")->type_name("N");
}

void add_output_options(CLI::App& cmd, RawOptions& raw) {
    cmd.add_option("--report", raw.report, "Write the report as JSON to FILE (docs/diff-report.schema.json)")
        ->type_name("FILE");
    cmd.add_option("--junit", raw.junit, "Write JUnit XML to FILE: one test case per distinct failure")->type_name("FILE");
    cmd.add_option("--html", raw.html, "Write the report as one self-contained HTML page to FILE, with each picture")
        ->type_name("FILE");
    cmd.add_option("--svg", raw.svg, "Draw each counterexample into FILE (failure k > 1: FILE-k.svg)")->type_name("FILE");
}

// Progress on stderr: a status line on a terminal; otherwise (a CI log) a
// line every few seconds, so a long run is not silent.
Progress progress_on_stderr(bool tty) {
    auto last = std::make_shared<std::chrono::steady_clock::time_point>(std::chrono::steady_clock::now());
    return [tty, last](const std::string& line) {
        if (tty) {
            std::fprintf(stderr, "\r\x1b[K%s", line.c_str());
            return;
        }
        const auto now = std::chrono::steady_clock::now();
        if (now - *last < std::chrono::seconds(5)) return;
        *last = now;
        std::fprintf(stderr, "dcel diff: %s\n", line.c_str());
    };
}

// The report on stdout, then the files: a report file that cannot be
// written loses nothing that stdout already has.
void write_outputs(const RawOptions& raw, const DiffOptions& o, const DiffResult& result) {
    write_stdout(diff::format_report(o, result));
    if (!raw.report.empty()) write_file(raw.report, diff::report_json(o, result));
    if (!raw.junit.empty()) write_file(raw.junit, diff::report_junit(o, result));
    if (!raw.html.empty()) write_file(raw.html, diff::render_html_report(diff::report_json(o, result)));
    if (!raw.svg.empty()) {
        for (const Failure& f : result.failures) {
            const std::string path = numbered(raw.svg, f.id);
            write_file(path, svg_of(o, f));
            write_stdout("failure " + std::to_string(f.id) + " drawn in " + path + "\n");
        }
    }
}

// The whole command once its options are parsed: usage errors first (with
// the shape CLI11 gives the other commands), then --print-case or the run.
int run_diff_command(const RawOptions& raw, DiffOptions o, bool impl_given) {
    try {
        o = resolve(raw, std::move(o));
        if (!raw.print_case.empty()) {
            const std::size_t n = parse_count("--print-case", raw.print_case, 0, kMaxCases);
            const std::optional<Case> c = diff::make_case(o.schedule, n);
            if (!c) throw UsageError("case " + std::to_string(n) + " has no graph in the allowed coordinate classes");
            write_stdout(c->text);
            return kExitOk;
        }
        if (!impl_given) throw UsageError("--impl CMD is required (the program to check)");
        if (o.impl.find_first_not_of(" \t\n") == std::string::npos) {
            throw UsageError("--impl: the command is empty; give the program to check, e.g. --impl 'python3 mine.py'");
        }
    } catch (const UsageError& e) {
        throw UsageError(std::string("diff: ") + e.what() + " (dcel diff --help)");
    }
    const bool tty = ::isatty(STDERR_FILENO) != 0;
    DiffResult result;
    try {
        result = diff::run_diff(o, progress_on_stderr(tty));
    } catch (const diff::ProcessError& e) {
        throw UsageError(e.what());  // the command cannot be run at all: exit 2
    }
    if (tty) std::fprintf(stderr, "\r\x1b[K");
    write_outputs(raw, o, result);
    return diff::run_passes(result) ? kExitOk : kExitInvalid;
}

}  // namespace

void add_diff_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("diff",
                                   "Differential fuzzing: run CMD on generated graphs, compare its answers with the "
                                   "reference, shrink each failure");
    cmd->footer(kFooter);
    auto options = std::make_shared<DiffOptions>();
    auto raw = std::make_shared<RawOptions>();
    auto answer = std::make_shared<AnswerOptions>();
    auto* impl = cmd->add_option("--impl", options->impl, "The implementation: a shell command (run by /bin/sh -c)")
                     ->type_name("CMD");
    add_schedule_options(*cmd, *raw, *options);
    add_answer_options(*cmd, answer);
    add_run_options(*cmd, *raw, *options);
    add_output_options(*cmd, *raw);
    cmd->callback([&action, options, raw, answer, impl] {
        action = [options, raw, answer, impl] {
            DiffOptions o = *options;
            o.answer = *answer;
            return run_diff_command(*raw, std::move(o), impl->count() != 0);
        };
    });
}

}  // namespace dcel::cli
