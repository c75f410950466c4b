#include "diff_report.hpp"

#include <sstream>

#include "dcel/build.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::cli {
namespace {

constexpr std::size_t kShownBytes = 2000;  // of an answer or of stderr
constexpr std::size_t kShownDifferences = 8;

std::string seconds(std::chrono::milliseconds ms) {
    std::ostringstream s;
    s.precision(1);
    s << std::fixed << static_cast<double>(ms.count()) / 1000.0 << " s";
    return s.str();
}

std::string count(std::size_t n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

std::string size_of(const PlanarGraph& g) {
    return std::to_string(g.vertices.size()) + (g.vertices.size() == 1 ? " vertex, " : " vertices, ") +
           std::to_string(g.edges.size()) + (g.edges.size() == 1 ? " edge" : " edges");
}

std::string without_newline(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
}

// What the command did with the graph: its answer, or how it ended and the
// end of its stderr.
void describe_answer(std::ostream& s, const Outcome& o) {
    const ProcessResult& r = o.run;
    const bool printed_answer = o.kind == FailureKind::WrongAnswer ||
                                (o.kind == FailureKind::Unparsable && r.end == ProcessEnd::Exited && !r.out.empty());
    if (printed_answer) {
        s << "  " << printable(without_newline(r.out), kShownBytes) << "\n";
    } else {
        s << "  " << o.what << "\n";
        if (!r.out.empty()) s << "  stdout: " << printable(r.out, 200) << "\n";
    }
    if (o.kind != FailureKind::WrongAnswer && !r.err_tail.empty()) {
        s << "  stderr (the end):\n";
        std::istringstream lines(without_newline(r.err_tail));
        for (std::string line; std::getline(lines, line);) s << "    " << printable(line, 300) << "\n";
    }
    if (printed_answer && o.kind == FailureKind::Unparsable) s << "what is wrong: " << o.what << "\n";
}

}  // namespace

std::string shell_quote(const std::string& text) {
    std::string out = "'";
    for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string replay_command(const DiffOptions& options, std::size_t case_number) {
    std::string cmd = "dcel diff --impl " + shell_quote(options.impl) + " --seed " + std::to_string(options.seed) +
                      " --case " + std::to_string(case_number);
    if (options.max_vertices != DiffOptions{}.max_vertices) cmd += " --max-vertices " + std::to_string(options.max_vertices);
    if (options.stream) cmd += " --stream";
    cmd += " --timeout-ms " + std::to_string(options.limits.timeout.count());
    return cmd;
}

std::string format_report(const DiffOptions& options, const DiffResult& result) {
    std::ostringstream s;
    if (!result.failure) {
        s << "dcel diff: agrees on " << count(result.cases_run, "case");
        if (result.cases_run > 0) {
            s << " (" << result.first_case << " to " << result.first_case + result.cases_run - 1 << ", seed " << options.seed
              << ")";
        }
        s << " in " << seconds(result.elapsed);
        if (result.stopped_by_time) s << "; stopped by --time";
        s << "\n";
        return s.str();
    }
    const Counterexample& c = *result.failure;
    const Outcome& o = c.outcome;
    s << "dcel diff: " << failure_label(c.first) << " on case " << c.spec.number << " (family "
      << gen::family_name(c.spec.params.family) << ", " << size_of(c.original) << ", seed " << options.seed << "), found in "
      << seconds(result.found_after) << " after " << count(c.spec.number - result.first_case, "agreeing case") << "\n";
    if (!c.reproduced) {
        s << "not shrunk: run alone in a fresh process, the case did not fail the same way again, so it depends "
             "on the cases before it (--stream state) or the command is not deterministic\n";
    } else if (c.steps == 0) {
        s << "no smaller graph fails the same way (" << count(c.attempts, "attempt") << " in " << seconds(c.shrink_elapsed)
          << (c.budget_spent ? ", stopped by the shrink budget" : "") << ")\n";
    } else {
        s << "shrunk in " << seconds(c.shrink_elapsed) << " (" << count(c.attempts, "attempt") << ", "
          << count(c.steps, "smaller failing graph") << " kept" << (c.budget_spent ? ", stopped by the shrink budget" : "")
          << ") to a graph that fails the same way\n";
    }
    s << "counterexample: " << size_of(c.graph) << "\n\n";

    s << "graph (dcel faces -, or the command's stdin):\n  " << without_newline(io::write_graph(c.graph)) << "\n";
    s << "reference (dcel faces):\n  " << without_newline(io::write_faces_of(build(c.graph))) << "\n";
    s << "the command says (" << failure_label(o) << "):\n";
    describe_answer(s, o);
    if (o.kind == FailureKind::WrongAnswer) {
        const auto& diffs = o.report.differences;
        s << "first difference: [" << check::kind_name(diffs.front().kind) << "] " << diffs.front().message << "\n";
        if (diffs.size() > 1) {
            s << "all " << diffs.size() << " differences:\n";
            for (std::size_t i = 0; i < diffs.size() && i < kShownDifferences; ++i) {
                s << "  [" << check::kind_name(diffs[i].kind) << "] " << diffs[i].message << "\n";
            }
            if (diffs.size() > kShownDifferences) s << "  ...\n";
        }
    }
    if (options.stream && result.restarts > 0) {
        s << "--stream: \"CMD --stream\" was started " << result.restarts + 1
          << " times: for the run, then afresh to replay the failing case alone and after each crash or timeout\n";
    }
    s << "\nreplay the case (it is shrunk again):\n  " << replay_command(options, c.spec.number) << "\n";
    s << "the original graph: dcel gen --family " << gen::family_name(c.spec.params.family) << " --seed "
      << c.spec.params.seed << " --vertices " << c.spec.params.vertices << "\n";
    s << "run the command on the counterexample:\n  printf '%s\\n' "
      << shell_quote(without_newline(io::write_graph(c.graph))) << " | " << options.impl << "\n";
    return s.str();
}

}  // namespace dcel::cli
