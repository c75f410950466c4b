// dcel diff --impl CMD: differential fuzzing of a foreign implementation
// against the reference. Options and output here; the case loop and the
// shrinking in diff_session, the report text in diff_report, the process
// handling in process.
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "commands.hpp"
#include "dcel/build.hpp"
#include "dcel/check/counterexample_svg.hpp"
#include "dcel/io/dcel_json.hpp"
#include "diff_report.hpp"
#include "diff_session.hpp"

namespace dcel::cli {
namespace {

constexpr const char* kFooter = R"(Protocol (docs/checking.md): CMD runs as /bin/sh -c CMD. It reads one graph,
{"vertices": [[x, y], ...], "edges": [[u, v], ...]}, on stdin and prints
{"faces": [[v0, v1, ...], ...]} on stdout (every boundary cycle, as the origins
of its half-edges; isolated vertices are not listed), then exits with status 0.
With --stream, "CMD --stream" starts once and reads one graph per line, and
must print each answer on one line; after a crash or a timeout it is started
again.

A failure is a crash (a signal; /bin/sh's exit status 128 + N counts as
signal N), a non-zero exit, a timeout, an answer that is not a faces answer,
or a wrong answer. The failing graph is shrunk to a small
one that fails the same way, and reported with the reference answer, what CMD
said, the first difference and a command line that replays the case.

Exit status: 0 every case agrees; 1 a failure (the report is on stdout);
2 usage error, including a CMD that /bin/sh cannot run at all (status 126 or
127 on the first case: not found, not executable).)";

std::string svg_title(const DiffOptions& options, const Counterexample& c) {
    return "dcel diff: " + failure_label(c.outcome) + ", case " + std::to_string(c.spec.number) + ", seed " +
           std::to_string(options.seed);
}

void write_svg(const std::string& path, const DiffOptions& options, const Counterexample& c) {
    const Dcel reference = build(c.graph);
    check::CounterexampleDrawing drawing{&c.graph, &reference};
    drawing.title = svg_title(options, c);
    drawing.answer_name = "the command: " + options.impl;
    if (c.outcome.kind == FailureKind::WrongAnswer) drawing.answer_cycles = io::read_faces_answer(c.outcome.run.out);
    std::ofstream out(path, std::ios::binary);
    out << check::render_counterexample_svg(drawing);
    if (!out.flush()) throw UsageError("cannot write " + path);
}

}  // namespace

void add_diff_command(CLI::App& app, Action& action) {
    auto* cmd = app.add_subcommand("diff",
                                   "Differential fuzzing: run CMD on generated graphs, compare with the "
                                   "reference, shrink the first failure");
    cmd->footer(kFooter);
    auto options = std::make_shared<DiffOptions>();
    auto cases = std::make_shared<std::size_t>(200);
    auto time_s = std::make_shared<double>(0);
    auto timeout_ms = std::make_shared<long>(5000);
    auto shrink_s = std::make_shared<double>(20);
    auto only_case = std::make_shared<std::size_t>(0);
    auto svg = std::make_shared<std::string>();
    cmd->add_option("--impl", options->impl, "The implementation: a shell command (run by /bin/sh -c)")
        ->required()
        ->type_name("CMD");
    auto* cases_opt =
        cmd->add_option("--cases", *cases, "Number of cases (default 200; unlimited with --time)")->type_name("N");
    cmd->add_option("--seed", options->seed, "Seed of the case schedule (default 1)")->type_name("S");
    auto* time_opt = cmd->add_option("--time", *time_s, "Stop looking for a failure after T seconds")
                         ->check(CLI::PositiveNumber)
                         ->type_name("T");
    cmd->add_option("--max-vertices", options->max_vertices, "Largest graph size asked of the generators (default 60)")
        ->check(CLI::Range(std::size_t{1}, std::size_t{100000}))
        ->type_name("K");
    cmd->add_flag("--stream", options->stream,
                  "Start \"CMD --stream\" once; one graph per line in, one answer per line out");
    cmd->add_option("--timeout-ms", *timeout_ms, "Time allowed per case, in milliseconds (default 5000)")
        ->check(CLI::Range(1L, 86400000L))
        ->type_name("M");
    cmd->add_option("--shrink-time", *shrink_s, "Time allowed for shrinking a failure, in seconds (default 20)")
        ->check(CLI::NonNegativeNumber)
        ->type_name("T");
    auto* case_opt =
        cmd->add_option("--case", *only_case, "Run only case N of the schedule (to replay a report)")->type_name("N");
    cmd->add_option("--svg", *svg, "On a failure, draw the counterexample into FILE (SVG)")->type_name("FILE");
    cmd->callback([&action, options, cases, cases_opt, time_s, time_opt, timeout_ms, shrink_s, only_case, case_opt, svg] {
        action = [=] {
            DiffOptions o = *options;
            o.limits.timeout = std::chrono::milliseconds(*timeout_ms);
            o.shrink_time = std::chrono::milliseconds(static_cast<long>(*shrink_s * 1000));
            if (*time_opt) o.time = std::chrono::milliseconds(static_cast<long>(*time_s * 1000));
            if (*cases_opt || !*time_opt) o.cases = *cases;  // --time alone: as many as fit
            if (*case_opt) o.only_case = *only_case;
            Progress progress;
            if (::isatty(STDERR_FILENO) != 0) {
                progress = [](const std::string& line) { std::fprintf(stderr, "\r\x1b[K%s", line.c_str()); };
            }
            const DiffResult result = run_diff(o, progress);
            if (progress) std::fprintf(stderr, "\r\x1b[K");
            std::string report = format_report(o, result);
            if (result.failure && !svg->empty()) {
                write_svg(*svg, o, *result.failure);
                report += "drawn in " + *svg + "\n";
            }
            write_stdout(report);
            return result.failure ? kExitInvalid : kExitOk;
        };
    });
}

}  // namespace dcel::cli
