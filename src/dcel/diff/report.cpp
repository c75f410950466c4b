#include "dcel/diff/report.hpp"
#include "dcel/check/session.hpp"
#include "dcel/diff/failure_class.hpp"
#include "dcel/error.hpp"

#include <algorithm>
#include <sstream>

#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/json_writer.hpp"

namespace dcel::diff {

std::string seconds(std::chrono::milliseconds ms) {
    std::ostringstream s;
    s.precision(1);
    s << std::fixed << static_cast<double>(ms.count()) / 1000.0 << " s";
    return s.str();
}

std::string count(std::size_t n, const std::string& noun) { return std::to_string(n) + " " + noun + (n == 1 ? "" : "s"); }

std::string size_of(std::size_t vertices, std::size_t edges) {
    return std::to_string(vertices) + (vertices == 1 ? " vertex, " : " vertices, ") + count(edges, "edge");
}

std::string size_of(const PlanarGraph& g) { return size_of(g.vertices.size(), g.edges.size()); }
std::string size_of(const PlanarGraph& g, const std::optional<check::Session>& session) {
    std::string s = size_of(g);
    if (session) s += ", " + count(session->steps.size(), "step");
    return s;
}

std::string without_newline(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
}

namespace {

constexpr std::size_t kShownDifferences = 8;
constexpr std::size_t kShownCases = 10;

std::string kind_of(const Outcome& o) { return std::string(check::answer_kind_name(o.answer_kind)); }

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

std::string case_text(const Case& c) {
    return "family " + std::string(gen::family_name(c.spec.params.family)) + ", " + size_of(c.graph, c.session) + ", " +
           std::string(gen::coordinate_class_name(c.coordinates)) + " coordinates";
}

std::string cases_list(const Failure& f) {
    std::string s;
    for (std::size_t i = 0; i < f.cases.size() && i < kShownCases; ++i)
        s += (i == 0 ? "" : ", ") + std::to_string(f.cases[i]);
    if (f.occurrences > kShownCases) s += ", ...";
    return s;
}

// A session counterexample: the session, and where it goes wrong first: the
// state before that step (the reference's), the step, and both answers to it.
void session_text(std::ostream& s, const Counterexample& c) {
    const check::Session& session = *c.session;
    s << "session (the command's stdin: the start graph and " << count(session.steps.size(), "step") << "):\n  "
      << without_newline(c.text) << "\n";
    const std::optional<std::size_t> k = c.outcome.report.first_wrong_step;
    if (!k || c.outcome.kind != FailureKind::WrongAnswer) return;
    if (*k >= session.steps.size()) {
        s << "every step is answered right; the state at the end is not"
          << (session.each_step ? "" : " (--each-step asks for the state after every edit, to find the first wrong one)")
          << "\n";
        return;
    }
    check::Session before = session;
    before.steps.resize(*k);
    s << "the first step answered wrongly: step " << *k << " (" << check::describe_step(session.steps[*k]) << ")\n";
    s << "the state before it (the reference's):\n  "
      << check::write_session_state(check::run_reference_session(before).state) << "\n";
    const check::ReferenceRun reference = check::run_reference_session(session, session.each_step);
    s << "the reference's answer to it: " << check::write_step_answer(reference.steps[*k]) << "\n";
    try {
        const check::SessionAnswer a = check::read_session_answer(c.outcome.run.out);
        if (*k < a.steps.size()) s << "the command's answer to it:   " << check::write_step_answer(a.steps[*k]) << "\n";
        // With --each-step, the states after it too: an edit answered {"ok": true}
        // on both sides shows its mistake there.
        if (*k < reference.states.size() && *k < a.states.size() && a.states[*k]) {
            s << "the reference's state after it:\n  " << check::write_session_state(reference.states[*k]) << "\n";
            s << "the command's state after it:\n  " << check::write_session_state(*a.states[*k]) << "\n";
        }
    } catch (const InvalidInput&) {
        // judged as a wrong answer, so it was read; nothing to add otherwise
    }
}

// How shrinking went: 1-minimal, or stopped by its budget; the kind the
// counterexample ended with when it is not the first case's.
void shrink_text(std::ostream& s, const DiffOptions& options, const Counterexample& c) {
    const std::string budget = c.budget_spent ? ", stopped by the shrink budget" : "";
    if (!c.reproduced) {
        s << "not shrunk: run again in a fresh process" << (options.stream ? ", alone or after the graphs before it," : ",")
          << " the case did not fail the same way, so the command is not deterministic"
          << (options.stream ? " or depends on more than the last 8 graphs" : "") << "\n";
    } else if (c.steps == 0) {
        s << "no smaller " << (c.session ? "session" : "graph") << " fails the same way (" << count(c.attempts, "attempt")
          << " in " << seconds(c.shrink_elapsed) << budget << ")\n";
    } else if (c.session) {
        s << "shrunk in " << seconds(c.shrink_elapsed) << " (" << count(c.attempts, "attempt") << ", "
          << count(c.steps, "smaller failing session") << " kept" << budget << ") to a session that fails the same way"
          << (c.minimal ? "; no single step, start vertex, edge or coordinate simplification of it does (1-minimal)" : "")
          << "\n";
    } else {
        s << "shrunk in " << seconds(c.shrink_elapsed) << " (" << count(c.attempts, "attempt") << ", "
          << count(c.steps, "smaller failing graph") << " kept" << budget << ") to a graph that fails the same way"
          << (c.minimal ? "; no single vertex, edge or coordinate simplification of it does (1-minimal)" : "") << "\n";
        if (failure_label(c.outcome) != failure_label(c.first)) {
            s << "(the case failed as " << failure_label(c.first) << "; the counterexample as " << failure_label(c.outcome)
              << ": the same class of failure)\n";
        }
    }
    if (c.shrink_timeout) {
        s << "(a hang: candidates ran with a " << c.shrink_timeout->count()
          << " ms timeout, 5 times the slowest passing case; the counterexample hangs for the case's full limit of "
          << c.limit.count() << " ms)\n";
    }
}

}  // namespace

void failure_body(std::ostream& s, const DiffOptions& options, const Failure& f) {
    const Counterexample& c = f.example;
    const Outcome& o = c.outcome;
    shrink_text(s, options, c);
    s << "counterexample: " << size_of(c.graph, c.session) << "\n\n";
    if (!c.prefix.empty()) {
        s << "it fails only after " << count(c.prefix.size(), "other graph")
          << " in the same --stream process (state kept between graphs); first send:\n";
        for (const std::string& p : c.prefix) s << "  " << without_newline(p) << "\n";
        s << "then ";
    }
    if (c.session) {
        session_text(s, c);
    } else {
        s << "graph (the command's stdin; dcel faces - reads it too):\n  " << without_newline(c.text) << "\n";
    }
    // (A session is always written plainly: its spelling is the case's graph's.)
    if (!c.session &&
        !(c.original.spec.spelling.numbers == gen::Spelling::Numbers::Shortest && !c.original.spec.spelling.positional &&
          !c.original.spec.spelling.edges_first && !c.original.spec.spelling.compact)) {
        s << "  (written with " << c.original.spec.spelling.describe()
          << "; plainly: " << without_newline(io::write_graph(c.graph)) << ")\n";
    }
    const check::AnswerKind kind = o.answer_kind;
    if (c.session) {
        s << "reference (the whole answer):\n  "
          << without_newline(check::reference_session_answer(*c.session, c.session->each_step)) << "\n";
    } else {
        s << "reference ("
          << (kind == check::AnswerKind::Faces ? "dcel faces" : kind_of(o) + ", as dcel check compares them") << "):\n  "
          << without_newline(check::reference_answer(build(c.graph), kind)) << "\n";
    }
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
        for (const std::string& note : o.report.notes) s << "note: " << note << "\n";
    }
    s << "\nreplay the case (it is shrunk again):\n  " << replay_command(options, c.original.spec.number) << "\n";
    s << "the original " << (c.session ? "session" : "graph") << " (its exact bytes): dcel diff --print-case "
      << c.original.spec.number << schedule_arguments(options) << "\n";
    s << "run the command on the counterexample:\n  printf '%s\\n' " << shell_quote(without_newline(c.text)) << " | "
      << options.impl << "\n";
}

namespace {

std::string stop_text(const DiffResult& r) {
    switch (r.stopped_by) {
        case StopReason::Time: return "; stopped by --time";
        case StopReason::MaxFailures: return "; stopped at --max-failures";
        case StopReason::Cases:
        case StopReason::FirstFailure: break;
    }
    return "";
}

std::string range_text(const DiffOptions& options, const DiffResult& result) {
    if (result.cases_run == 0) return "";
    return " (" + std::to_string(result.first_case) + " to " + std::to_string(result.first_case + result.cases_run - 1) +
           ", seed " + std::to_string(options.schedule.seed) + ")";
}

}  // namespace

std::string shell_quote(const std::string& text) {
    std::string out = "'";
    for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string schedule_arguments(const DiffOptions& options) {
    const Schedule defaults;
    const Schedule& s = options.schedule;
    std::string a = " --seed " + std::to_string(s.seed);
    if (s.max_vertices != defaults.max_vertices) a += " --max-vertices " + std::to_string(s.max_vertices);
    if (s.large_vertices != defaults.large_vertices) a += " --large-vertices " + std::to_string(s.large_vertices);
    if (s.positional) a += " --positional";
    if (s.sessions) a += " --sessions";
    if (s.each_step) a += " --each-step";
    if (s.sessions && s.max_steps != defaults.max_steps) a += " --max-steps " + std::to_string(s.max_steps);
    if (s.sessions && s.large_steps != defaults.large_steps) a += " --large-steps " + std::to_string(s.large_steps);
    if (!s.families.empty()) {
        a += " --families ";
        for (std::size_t i = 0; i < s.families.size(); ++i)
            a += (i == 0 ? "" : ",") + std::string(gen::family_name(s.families[i]));
    }
    if (!s.classes.empty()) {
        a += " --coordinates ";
        for (std::size_t i = 0; i < s.classes.size(); ++i) {
            a += (i == 0 ? "" : ",") + std::string(gen::coordinate_class_name(s.classes[i]));
        }
    }
    return a;
}

namespace {

// --stream and how answers are read: what a replay needs besides the schedule.
std::string run_arguments(const DiffOptions& options) {
    std::string a;
    if (options.stream) a += " --stream";
    if (options.answer.kind) a += " --answer " + std::string(check::answer_kind_name(*options.answer.kind));
    if (options.answer.conventions.face_on_right) a += " --face-on right";
    if (options.answer.conventions.one_based) a += " --one-based";
    if (options.answer.conventions.unoriented) a += " --unoriented";
    if (options.answer.conventions.isolated_cycles) a += " --isolated-as-cycles";
    if (options.answer.conventions.holes_unattached) a += " --holes-unattached";
    return a;
}

}  // namespace

std::string run_command_line(const DiffOptions& options) {
    std::string command = "dcel diff --impl " + shell_quote(options.impl) + schedule_arguments(options) +
                          run_arguments(options) + " --timeout-ms " + std::to_string(options.limits.timeout.count());
    if (options.cases) command += " --cases " + std::to_string(*options.cases);
    if (options.time) command += " --time " + seconds(*options.time).substr(0, seconds(*options.time).size() - 2);
    if (options.keep_going) command += " --keep-going";
    if (options.shard) {
        command += " --shard " + std::to_string(options.shard->index) + "/" + std::to_string(options.shard->count);
    }
    if (options.jobs > 1) command += " --jobs " + std::to_string(options.jobs);
    return command;
}

std::string replay_command(const DiffOptions& options, std::size_t case_number) {
    return "dcel diff --impl " + shell_quote(options.impl) + schedule_arguments(options) + " --case " +
           std::to_string(case_number) + run_arguments(options) + " --timeout-ms " +
           std::to_string(options.limits.timeout.count());
}

namespace {

// The classes a failure was seen in: "tiny and huge coordinates".
std::string classes_text(const Failure& f) {
    std::string s;
    for (std::size_t i = 0; i < f.classes.size(); ++i) {
        s += i == 0 ? "" : (i + 1 == f.classes.size() ? " and " : ", ");
        s += gen::coordinate_class_name(f.classes[i]);
    }
    return s + " coordinates";
}

// Cases the implementation skipped, by reason; said prominently when they are
// most of the run, since a skip is never a pass.
void skips_text(std::ostream& s, const DiffResult& result) {
    if (result.skipped_by_impl == 0) return;
    const bool most = result.skipped_by_impl * 2 > result.cases_run - result.skipped;
    s << (most ? "warning: the implementation skipped most cases: " : "the implementation skipped ")
      << count(result.skipped_by_impl, "case") << " of " << count(result.cases_run - result.skipped, "case")
      << " ({\"skip\": reason}); only " << result.checked() << " were checked:\n";
    for (const auto& [reason, n] : result.skip_reasons) s << "  " << n << " x " << reason << "\n";
}

void cycles_only_text(std::ostream& s, const DiffResult& result) {
    if (result.cycles_only == 0) return;
    s << "warning: " << count(result.cycles_only, "session")
      << " gave the state as boundary cycles only: where holes and isolated vertices lie went unchecked (give face "
         "records {\"outer\", \"holes\", \"isolated\"})\n";
}

// Query steps skipped by the answers of agreeing sessions: unchecked, so said.
void skipped_steps_text(std::ostream& s, const DiffResult& result) {
    std::string ops;
    std::size_t total = 0;
    for (std::size_t op = 0; op < check::kStepOpCount; ++op) {
        if (result.skipped_steps[op] == 0) continue;
        total += result.skipped_steps[op];
        ops += std::string(ops.empty() ? "" : ", ") + std::to_string(result.skipped_steps[op]) + " " +
               std::string(check::step_op_name(static_cast<check::StepOp>(op)));
    }
    if (total == 0) return;
    s << "warning: the answers skipped " << count(total, "query step") << " ({\"skip\": ...}): " << ops
      << "; they went unchecked\n";
}

void slow_text(std::ostream& s, const DiffOptions& options, const DiffResult& result) {
    if (result.slow_count == 0) return;
    s << "performance: " << count(result.slow_count, "case") << " took longer than --timeout-ms "
      << options.limits.timeout.count()
      << " but finished within the limit scaled from this program's speed on smaller cases (not failures):\n";
    for (const SlowCase& c : result.slow) {
        s << "  case " << c.number << " (" << gen::family_name(c.family) << ", " << c.vertices << " vertices, " << c.edges
          << " edges): " << seconds(c.took) << " (limit " << seconds(c.limit) << ")\n";
    }
    if (result.slow_count > result.slow.size()) s << "  ...\n";
}

void agreement_text(std::ostream& s, const DiffOptions& options, const DiffResult& result) {
    if (result.checked() == 0 && result.cases_run > 0) {
        s << "dcel diff: no case was checked in " << count(result.cases_run, "case") << range_text(options, result)
          << ": a run that checks nothing is not a pass\n";
    } else {
        s << "dcel diff: agrees on " << count(result.checked(), "case") << range_text(options, result) << " in "
          << seconds(result.elapsed) << stop_text(result) << "\n";
    }
    if (result.skipped != 0) {
        s << "(" << count(result.skipped, "case") << " skipped: no graph in the allowed coordinate classes)\n";
    }
}

// The failure's one-line label with the error line of its stderr, when it
// has one (the implementation's own message, not its banner or trace).
std::string label_with_error_line(const Outcome& o) {
    std::string label = failure_label(o);
    if (o.kind == FailureKind::NonZeroExit || o.kind == FailureKind::Crash) {
        const std::string line = meaningful_line(o.run.err_tail);
        if (!line.empty()) label += ": " + printable(line, 120);
    }
    return label;
}

}  // namespace

bool run_passes(const DiffResult& result) {
    return result.failures.empty() && (result.checked() > 0 || result.cases_run == 0);
}

std::string format_report(const DiffOptions& options, const DiffResult& result) {
    std::ostringstream s;
    if (result.failures.empty()) {
        agreement_text(s, options, result);
        cycles_only_text(s, result);
        skipped_steps_text(s, result);
        skips_text(s, result);
        slow_text(s, options, result);
        return s.str();
    }
    const bool several = options.keep_going;
    if (several) {
        s << "dcel diff: " << count(result.failures.size(), "distinct failure") << " in " << count(result.cases_run, "case")
          << range_text(options, result) << " in " << seconds(result.elapsed) << stop_text(result) << "\n";
    }
    for (const Failure& f : result.failures) {
        const Counterexample& c = f.example;
        if (several) {
            s << "\nfailure " << f.id << " of " << result.failures.size() << ": " << label_with_error_line(c.first)
              << " on case " << c.original.spec.number << " (" << case_text(c.original) << "), found after "
              << seconds(f.found_after) << "; " << count(f.occurrences, "case") << " failed this way (" << cases_list(f)
              << "), in " << classes_text(f) << "\n";
        } else {
            s << "dcel diff: " << label_with_error_line(c.first) << " on case " << c.original.spec.number << " ("
              << case_text(c.original) << ", seed " << options.schedule.seed << "), found in " << seconds(f.found_after)
              << " after " << count(c.original.spec.number - result.first_case, "agreeing case") << "\n";
        }
        failure_body(s, options, f);
    }
    if (options.stream && result.restarts > 0) {
        s << "\n--stream: \"CMD --stream\" was started " << result.restarts + 1
          << " times: for the run, then afresh to replay failing cases and after each crash or timeout\n";
    }
    const bool steps_skipped = std::any_of(result.skipped_steps.begin(), result.skipped_steps.end(),
                                           [](std::size_t n) { return n > 0; });
    if (result.skipped_by_impl > 0 || result.slow_count > 0 || result.cycles_only > 0 || steps_skipped) s << "\n";
    cycles_only_text(s, result);
    skipped_steps_text(s, result);
    skips_text(s, result);
    slow_text(s, options, result);
    if (several) {
        s << "\nsummary: " << count(result.failures.size(), "distinct failure") << " in " << count(result.cases_run, "case")
          << "\n";
        for (const Failure& f : result.failures) {
            s << "  " << f.id << ". " << label_with_error_line(f.example.outcome) << ": " << count(f.occurrences, "case")
              << " in " << classes_text(f) << ", shrunk to " << size_of(f.example.graph, f.example.session) << " ("
              << gen::coordinate_class_name(gen::classify(f.example.graph)) << " coordinates)\n";
        }
    }
    return s.str();
}

}  // namespace dcel::diff
