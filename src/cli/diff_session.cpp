#include "diff_session.hpp"

#include <memory>
#include <unordered_set>

#include "cli_support.hpp"
#include "dcel/build.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::cli {
namespace {

using Clock = std::chrono::steady_clock;

std::chrono::milliseconds since(Clock::time_point t) {
    return std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - t);
}

// The command, run once per graph or kept running as a stream.
class Impl {
public:
    explicit Impl(const DiffOptions& o) : options_(o) {
        if (o.stream) stream_ = std::make_unique<StreamProcess>(o.impl + " --stream", o.limits);
    }

    // graph_json is one line ending in '\n' (write_graph's form).
    ProcessResult run(const std::string& graph_json) {
        if (!stream_) return run_command(options_.impl, graph_json, options_.limits);
        StreamProcess::Reply reply = stream_->exchange(std::string_view(graph_json).substr(0, graph_json.size() - 1));
        if (!reply.answered) return std::move(reply.failure);
        ProcessResult r;
        r.out = std::move(reply.line);
        return r;
    }
    // The next run starts from a fresh process (nothing to do per graph).
    void restart() {
        if (stream_) stream_->stop();
    }
    [[nodiscard]] std::size_t restarts() const { return stream_ && stream_->starts() > 0 ? stream_->starts() - 1 : 0; }

private:
    const DiffOptions& options_;
    std::unique_ptr<StreamProcess> stream_;
};

Outcome try_graph(Impl& impl, const PlanarGraph& g, const ProcessLimits& limits) {
    const Dcel reference = build(g);
    return judge(reference, impl.run(io::write_graph(g)), limits);
}

// sh's own statuses for "not found" and "not executable": the command never ran.
bool could_not_run(const Outcome& o) {
    return o.kind == FailureKind::NonZeroExit && (o.run.exit_status == 126 || o.run.exit_status == 127);
}

void shrink_counterexample(Impl& impl, const DiffOptions& options, Counterexample& c, const Progress& progress) {
    const Clock::time_point start = Clock::now();
    const Clock::time_point deadline = start + options.shrink_time;
    c.graph = c.original;
    c.outcome = c.first;
    // The greedy shrinker offers some candidates again after every step (the
    // empty graph first of all); the command is deterministic, so a graph
    // that did not fail the same way once is not run again.
    std::unordered_set<std::string> passed;
    auto still_fails = [&](const PlanarGraph& candidate) {
        if (Clock::now() >= deadline) {
            c.budget_spent = true;
            return false;
        }
        const std::string text = io::write_graph(candidate);
        if (passed.contains(text)) return false;
        ++c.attempts;
        if (progress) {
            progress("shrinking: " + std::to_string(c.graph.vertices.size()) + " vertices, " +
                     std::to_string(c.graph.edges.size()) + " edges, " + std::to_string(c.attempts) + " attempts");
        }
        Outcome o = judge(build(candidate), impl.run(text), options.limits);
        if (!same_failure(o, c.first)) {
            passed.insert(text);
            return false;
        }
        ++c.steps;
        c.outcome = std::move(o);
        return true;
    };
    c.graph = gen::shrink(c.original, still_fails, options.shrink_attempts);
    if (c.attempts >= options.shrink_attempts) c.budget_spent = true;
    c.shrink_elapsed = since(start);
}

}  // namespace

DiffResult run_diff(const DiffOptions& options, const Progress& progress) {
    const Clock::time_point start = Clock::now();
    Impl impl(options);
    DiffResult result;
    const std::size_t first = options.only_case.value_or(0);
    const std::size_t end = options.only_case ? first + 1 : options.cases.value_or(SIZE_MAX);
    result.first_case = first;
    for (std::size_t i = first; i < end; ++i) {
        if (options.time && !options.only_case && since(start) >= *options.time) {
            result.stopped_by_time = true;
            break;
        }
        const CaseSpec spec = case_spec(options.seed, i, options.max_vertices);
        const PlanarGraph g = gen::generate(spec.params);
        if (progress) {
            progress("case " + std::to_string(i) + (options.cases ? "/" + std::to_string(end) : "") + ": " +
                     std::string(gen::family_name(spec.params.family)) + ", " + std::to_string(g.vertices.size()) +
                     " vertices");
        }
        Outcome o = try_graph(impl, g, options.limits);
        ++result.cases_run;
        if (o.agrees) continue;
        if (i == first && could_not_run(o)) {
            std::string why = o.run.err_tail;
            while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
            throw UsageError("cannot run --impl '" + options.impl + "': /bin/sh " + describe_end(o.run, options.limits) +
                             (why.empty() ? "" : ": " + printable(why, 300)));
        }
        result.found_after = since(start);
        Counterexample c;
        c.spec = spec;
        c.original = g;
        c.first = std::move(o);
        // Alone, in a fresh process: a failure that needs the cases before it
        // (a stream's state, a flaky program) cannot be shrunk.
        impl.restart();
        c.reproduced = same_failure(try_graph(impl, g, options.limits), c.first);
        if (c.reproduced) {
            shrink_counterexample(impl, options, c, progress);
        } else {
            c.graph = c.original;
            c.outcome = c.first;
        }
        result.failure = std::move(c);
        break;
    }
    result.restarts = impl.restarts();
    result.elapsed = since(start);
    return result;
}

}  // namespace dcel::cli
