// The JSON report of `dcel diff --report` (docs/diff-report.schema.json):
// the run, then each distinct failure with its case, counterexample,
// shrinking, outcome, reference answer and replay line. Every string goes
// through JsonWriter, so the document is valid UTF-8 whatever bytes the
// implementation printed.
#include "dcel/build.hpp"
#include "dcel/check/answer.hpp"
#include "dcel/check/session.hpp"
#include "dcel/diff/report.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/json_writer.hpp"

namespace dcel::diff {
namespace {

using io::JsonWriter;
using Layout = JsonWriter::Layout;

std::uint64_t ms(std::chrono::milliseconds t) { return static_cast<std::uint64_t>(t.count()); }

void write_case_numbers(JsonWriter& w, const std::vector<std::size_t>& cases) {
    w.begin_array();
    for (const std::size_t n : cases) {
        w.item();
        w.count(n);
    }
    w.end_array();
}

void write_slow(JsonWriter& w, const DiffResult& result) {
    w.begin_object();
    w.key("count");
    w.count(result.slow_count);
    w.key("cases");
    w.begin_array();
    for (const SlowCase& c : result.slow) {
        w.item();
        w.begin_object();
        w.key("number");
        w.count(c.number);
        w.key("family");
        w.string(gen::family_name(c.family));
        w.key("vertices");
        w.count(c.vertices);
        w.key("edges");
        w.count(c.edges);
        w.key("ms");
        w.count(ms(c.took));
        w.key("limit_ms");
        w.count(ms(c.limit));
        w.end_object();
    }
    w.end_array();
    w.end_object();
}

// How answers were read: the HTML page reads the answer in the report again
// to draw it, and needs the conventions the run read it under.
void write_conventions(JsonWriter& w, const check::Conventions& c) {
    w.begin_object();
    w.key("face_on_right");
    w.boolean(c.face_on_right);
    w.key("one_based");
    w.boolean(c.one_based);
    w.key("unoriented");
    w.boolean(c.unoriented);
    w.key("isolated_cycles");
    w.boolean(c.isolated_cycles);
    w.key("holes_unattached");
    w.boolean(c.holes_unattached);
    w.end_object();
}

void write_run(JsonWriter& w, const DiffOptions& options, const DiffResult& result) {
    static constexpr const char* kStops[] = {"cases", "time", "first-failure", "max-failures"};
    w.key("format");
    w.string("dcel diff report 1");
    w.key("command");
    w.string(run_command_line(options));
    w.key("impl");
    w.string(options.impl);
    w.key("seed");
    w.count(options.schedule.seed);
    if (options.schedule.sessions) {
        w.key("sessions");
        w.boolean(true);
        w.key("cycles_only_sessions");
        w.count(result.cycles_only);
        w.key("skipped_steps");
        w.begin_object();
        for (std::size_t op = 0; op < check::kStepOpCount; ++op) {
            if (result.skipped_steps[op] == 0) continue;
            w.key(check::step_op_name(static_cast<check::StepOp>(op)));
            w.count(result.skipped_steps[op]);
        }
        w.end_object();
    }
    w.key("shard");
    if (options.shard) {
        w.string(std::to_string(options.shard->index) + "/" + std::to_string(options.shard->count));
    } else {
        w.null();
    }
    w.key("answer_kind");
    if (options.answer.kind) {
        w.string(check::answer_kind_name(*options.answer.kind));
    } else {
        w.null();
    }
    w.key("conventions");
    write_conventions(w, options.answer.conventions);
    w.key("cases_run");
    w.count(result.cases_run);
    w.key("first_case");
    w.count(result.first_case);
    w.key("skipped");
    w.count(result.skipped);
    w.key("skipped_by_impl");
    w.count(result.skipped_by_impl);
    w.key("skip_reasons");
    w.begin_array();
    for (const auto& [reason, n] : result.skip_reasons) {
        w.item();
        w.begin_object();
        w.key("reason");
        w.string(reason);
        w.key("cases");
        w.count(n);
        w.end_object();
    }
    w.end_array();
    w.key("checked");
    w.count(result.checked());
    w.key("slow");
    write_slow(w, result);
    w.key("large_cases");
    w.count(result.large_cases);
    w.key("stopped_by");
    w.string(kStops[static_cast<std::size_t>(result.stopped_by)]);
    w.key("elapsed_ms");
    w.count(ms(result.elapsed));
    w.key("reference_cpu_ms");
    w.count(ms(result.reference_cpu));
    w.key("agrees");
    w.boolean(run_passes(result));
}

void write_case(JsonWriter& w, const Case& c) {
    w.begin_object();
    w.key("number");
    w.count(c.spec.number);
    w.key("family");
    w.string(gen::family_name(c.spec.params.family));
    w.key("coordinates");
    w.string(gen::coordinate_class_name(c.coordinates));
    w.key("spelling");
    w.string(c.spec.spelling.describe());
    w.key("vertices");
    w.count(c.graph.vertices.size());
    w.key("edges");
    w.count(c.graph.edges.size());
    w.end_object();
}

void write_counterexample(JsonWriter& w, const Counterexample& c) {
    w.begin_object();
    w.key("vertices");
    w.count(c.graph.vertices.size());
    w.key("edges");
    w.count(c.graph.edges.size());
    w.key("text");
    w.string(c.text);
    w.key("graph");  // a session's start graph
    w.raw(without_newline(io::write_graph(c.graph)));
    if (c.session) {
        w.key("steps");
        w.count(c.session->steps.size());
    }
    w.end_object();
}

void write_shrinking(JsonWriter& w, const Counterexample& c) {
    w.begin_object();
    w.key("attempts");
    w.count(c.attempts);
    w.key("steps");
    w.count(c.steps);
    w.key("elapsed_ms");
    w.count(ms(c.shrink_elapsed));
    w.key("budget_spent");
    w.boolean(c.budget_spent);
    w.key("minimal");
    w.boolean(c.minimal);
    w.end_object();
}

void write_outcome(JsonWriter& w, const Outcome& o) {
    w.begin_object();
    w.key("label");
    w.string(failure_label(o));
    w.key("what");
    w.string(o.what);
    w.key("answer_kind");
    w.string(check::answer_kind_name(o.answer_kind));
    w.key("stdout");
    w.string(std::string_view(o.run.out).substr(0, kShownBytes));
    w.key("stderr_tail");
    w.string(o.run.err_tail);
    if (o.report.first_wrong_step) {
        w.key("first_wrong_step");
        w.count(*o.report.first_wrong_step);
    }
    w.key("differences");
    w.begin_array(Layout::Lines);
    for (const check::Difference& d : o.report.differences) {
        w.item();
        w.begin_object();
        w.key("kind");
        w.string(check::kind_name(d.kind));
        w.key("message");
        w.string(d.message);
        w.key("vertices");
        w.begin_array();
        for (const Index v : d.vertices) {
            w.item();
            w.index(v);
        }
        w.end_array();
        w.end_object();
    }
    w.end_array();
    w.key("notes");
    w.begin_array();
    for (const std::string& note : o.report.notes) {
        w.item();
        w.string(note);
    }
    w.end_array();
    w.end_object();
}

void write_failure(JsonWriter& w, const DiffOptions& options, const Failure& f) {
    const Counterexample& c = f.example;
    w.begin_object(Layout::Lines);
    w.key("id");
    w.count(f.id);
    w.key("label");
    w.string(failure_label(c.first));
    w.key("kind");
    w.string(failure_name(c.first.kind));
    w.key("signature");
    w.string(f.signature);
    w.key("classes");
    w.begin_array();
    for (const gen::CoordinateClass k : f.classes) {
        w.item();
        w.string(gen::coordinate_class_name(k));
    }
    w.end_array();
    w.key("occurrences");
    w.count(f.occurrences);
    w.key("cases");
    write_case_numbers(w, f.cases);
    w.key("keys");
    w.begin_array(Layout::Lines);
    for (const KeySeen& k : f.keys) {
        w.item();
        w.begin_object();
        w.key("key");
        w.string(k.key);
        w.key("coordinates");
        w.string(gen::coordinate_class_name(k.coordinates));
        w.key("occurrences");
        w.count(k.occurrences);
        w.key("cases");
        write_case_numbers(w, k.cases);
        w.end_object();
    }
    w.end_array();
    w.key("found_after_ms");
    w.count(ms(f.found_after));
    w.key("case");
    write_case(w, c.original);
    w.key("reproduced");
    w.boolean(c.reproduced);
    w.key("prefix");
    w.begin_array();
    for (const std::string& p : c.prefix) {
        w.item();
        w.string(p);
    }
    w.end_array();
    w.key("counterexample");
    write_counterexample(w, c);
    w.key("shrinking");
    write_shrinking(w, c);
    w.key("outcome");
    write_outcome(w, c.outcome);
    w.key("reference");
    w.string(without_newline(c.session ? check::reference_session_answer(*c.session, c.session->each_step)
                                       : check::reference_answer(build(c.graph), c.outcome.answer_kind)));
    w.key("replay");
    w.string(replay_command(options, c.original.spec.number));
    w.end_object();
}

}  // namespace

std::string report_json(const DiffOptions& options, const DiffResult& result) {
    std::string out;
    JsonWriter w(out);
    w.begin_object(Layout::Lines);
    write_run(w, options, result);
    w.key("failures");
    w.begin_array(Layout::Lines);
    for (const Failure& f : result.failures) {
        w.item();
        write_failure(w, options, f);
    }
    w.end_array();
    w.end_object();
    w.raw('\n');
    w.flush();
    return out;
}

}  // namespace dcel::diff
