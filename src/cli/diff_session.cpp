#include "diff_session.hpp"

#include <algorithm>
#include <ctime>
#include <deque>
#include <memory>
#include <unordered_set>

#include "cli_support.hpp"
#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::cli {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

milliseconds since(Clock::time_point t) { return std::chrono::duration_cast<milliseconds>(Clock::now() - t); }

// How many passing graphs a --stream failure may need before it.
constexpr std::size_t kHistory = 8;
// A hang's candidates get this many times the slowest passing run, at least kMinShrinkTimeout.
constexpr long kShrinkTimeoutFactor = 5;
constexpr milliseconds kMinShrinkTimeout{250};

// The command, run once per graph or kept running as a stream.
class Impl {
public:
    Impl(const DiffOptions& o, const ProcessLimits& limits) : options_(o), limits_(limits) {}

    // text is one line ending in '\n'.
    ProcessResult run(const std::string& text) {
        if (!options_.stream) return run_command(options_.impl, text, limits_);
        if (!stream_) stream_ = std::make_unique<StreamProcess>(options_.impl + " --stream", limits_);
        StreamProcess::Reply reply = stream_->exchange(std::string_view(text).substr(0, text.size() - 1));
        if (!reply.answered) return std::move(reply.failure);
        ProcessResult r;
        r.out = std::move(reply.line);
        return r;
    }
    // In a fresh process: the prefix graphs (their answers unread), then text.
    ProcessResult run_after(const std::vector<std::string>& prefix, const std::string& text) {
        restart();
        for (const std::string& p : prefix) (void)run(p);
        return run(text);
    }
    // The next run starts from a fresh process (nothing to do per graph).
    void restart() {
        if (stream_) stream_->stop();
    }
    [[nodiscard]] std::size_t starts() const { return stream_ ? stream_->starts() : 0; }

private:
    const DiffOptions& options_;
    ProcessLimits limits_;
    std::unique_ptr<StreamProcess> stream_;
};

// sh's own statuses for "not found" and "not executable": the command never ran.
bool could_not_run(const Outcome& o) {
    return o.kind == FailureKind::NonZeroExit && (o.run.exit_status == 126 || o.run.exit_status == 127);
}

std::uint64_t text_hash(const std::string& text) { return std::hash<std::string>{}(text); }

class Session {
public:
    Session(const DiffOptions& o, const Progress& progress)
        : o_(o), progress_(progress), impl_(o, o.limits), judging_{o.answer, {}} {}

    DiffResult run() {
        const std::size_t first = o_.only_case.value_or(0);
        const std::size_t end = o_.only_case ? first + 1 : o_.cases.value_or(SIZE_MAX);
        result_.first_case = first;
        result_.stopped_by = StopReason::Cases;
        for (std::size_t i = first; i < end; ++i) {
            if (o_.time && !o_.only_case && since(start_) >= *o_.time) {
                result_.stopped_by = StopReason::Time;
                break;
            }
            std::optional<Case> c = make_case(o_.schedule, i);
            ++result_.cases_run;
            if (!c) {
                ++result_.skipped;
                continue;
            }
            result_.large_cases += c->spec.large ? 1 : 0;
            report_progress(i, end, *c);
            const Clock::time_point t = Clock::now();
            Outcome outcome = judge(build(c->graph), impl_.run(c->text), o_.limits, judging_);
            if (outcome.agrees) {
                slowest_pass_ = std::max(slowest_pass_, since(t));
                remember(std::move(*c));
                continue;
            }
            if (i == first && could_not_run(outcome)) {
                std::string why = outcome.run.err_tail;
                while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
                throw UsageError("cannot run --impl '" + o_.impl + "': /bin/sh " + describe_end(outcome.run, o_.limits) +
                                 (why.empty() ? "" : ": " + printable(why, 300)));
            }
            on_failure(std::move(*c), std::move(outcome));
            if (!o_.keep_going) {
                result_.stopped_by = StopReason::FirstFailure;
                break;
            }
            if (result_.failures.size() >= o_.max_failures) {
                result_.stopped_by = StopReason::MaxFailures;
                break;
            }
        }
        result_.restarts = impl_.starts() > 0 ? impl_.starts() - 1 : 0;
        result_.elapsed = since(start_);
        result_.reference_cpu = milliseconds(
            static_cast<std::int64_t>(static_cast<double>(std::clock() - cpu_start_) * 1000.0 / CLOCKS_PER_SEC));
        result_.agreed_as = judging_.agreed_as;
        return std::move(result_);
    }

private:
    void report_progress(std::size_t i, std::size_t end, const Case& c) {
        if (!progress_) return;
        std::string line = "case " + std::to_string(i) + (o_.cases ? "/" + std::to_string(end) : "") + ", " +
                           std::to_string(since(start_).count() / 1000) +
                           " s: " + std::string(gen::family_name(c.spec.params.family)) + ", " +
                           std::to_string(c.graph.vertices.size()) + " vertices, " +
                           std::string(gen::coordinate_class_name(c.coordinates));
        if (!result_.failures.empty()) line += "; " + std::to_string(result_.failures.size()) + " distinct failures";
        progress_(line);
    }

    void remember(Case c) {
        if (!o_.stream) return;
        history_.push_back(std::move(c));
        if (history_.size() > kHistory) history_.pop_front();
    }

    // A failure: counted against a failure already found when it fails the
    // same way on the same coordinate class; otherwise confirmed, shrunk, and
    // kept as a new one (or merged into one that shrank to the same graph).
    void on_failure(Case c, Outcome outcome) {
        const std::string key = failure_key(outcome) + "/" + std::string(gen::coordinate_class_name(c.coordinates));
        for (Failure& f : result_.failures) {
            if (std::find(f.keys.begin(), f.keys.end(), key) != f.keys.end()) {
                count(f, c.spec.number);
                return;
            }
        }
        Failure f;
        f.key = key;
        f.keys.push_back(key);
        f.found_after = since(start_);
        count(f, c.spec.number);
        f.example = investigate(std::move(c), std::move(outcome));
        impl_.restart();  // the search goes on in a fresh process
        // The same bug found again from another coordinate class shrinks to
        // the same kind of failure on a graph of the same size and class (the
        // shrinker snaps coordinates to small integers where the failure
        // allows: a failure that needs subnormals keeps them, and stays apart).
        f.signature = signature(f.example);
        for (Failure& other : result_.failures) {
            if (other.signature == f.signature) {
                other.keys.push_back(f.key);
                count(other, f.cases.front());
                return;
            }
        }
        f.id = result_.failures.size() + 1;
        result_.failures.push_back(std::move(f));
    }

    static std::string signature(const Counterexample& x) {
        return failure_key(x.outcome) + "/" + std::string(gen::coordinate_class_name(gen::classify(x.graph))) + "/" +
               std::to_string(x.graph.vertices.size()) + "v" + std::to_string(x.graph.edges.size()) + "e";
    }

    static void count(Failure& f, std::size_t case_number) {
        ++f.occurrences;
        if (f.cases.size() < kMaxListedCases) f.cases.push_back(case_number);
    }

    Counterexample investigate(Case c, Outcome first) {
        Counterexample x;
        x.first = std::move(first);
        x.original = std::move(c);
        x.graph = x.original.graph;
        x.text = x.original.text;
        x.outcome = x.first;
        // Alone, in a fresh process: a failure that needs the cases before it
        // (a stream's state, a flaky program) is looked at with them.
        impl_.restart();
        x.reproduced = fails_same(impl_, {}, x.original.text, x.first);
        if (!x.reproduced && o_.stream) {
            for (std::size_t k = 1; k <= history_.size() && !x.reproduced; k *= 2) {
                std::vector<std::string> prefix;
                for (std::size_t j = history_.size() - k; j < history_.size(); ++j) prefix.push_back(history_[j].text);
                if (fails_same(impl_, prefix, x.original.text, x.first)) {
                    x.reproduced = true;
                    x.prefix = std::move(prefix);
                    prefix_cases_.assign(history_.end() - static_cast<std::ptrdiff_t>(k), history_.end());
                }
            }
        }
        if (x.reproduced) shrink(x);
        recheck_hint(x);
        return x;
    }

    // A hint that another convention makes the answer agree must hold for the
    // case as found, not only for the shrunk graph (where a bug that reverses
    // every cycle through a vertex of degree 3 reverses them all).
    void recheck_hint(Counterexample& x) const {
        std::vector<std::string>& notes = x.outcome.report.notes;
        std::erase_if(notes, [](const std::string& n) { return n.rfind("the answer agrees with", 0) == 0; });
        if (x.first.kind != FailureKind::WrongAnswer) return;
        try {
            const check::Answer a = check::read_answer(x.first.run.out, x.first.answer_kind);
            if (std::optional<std::string> hint = check::convention_hint(build(x.original.graph), a,
                                                                         o_.answer.conventions)) {
                notes.push_back(std::move(*hint));
            }
        } catch (const InvalidInput&) {
            // read before as this kind; nothing to add
        }
    }

    bool fails_same(Impl& impl, const std::vector<std::string>& prefix, const std::string& text, const Outcome& like) {
        return fails_same_outcome(impl, prefix, text, like).has_value();
    }

    // The outcome when the graph fails like `like` (run in a fresh process
    // after `prefix` when there is one), or nothing.
    std::optional<Outcome> fails_same_outcome(Impl& impl, const std::vector<std::string>& prefix, const std::string& text,
                                              const Outcome& like) {
        const PlanarGraph g = io::read_graph(text);
        ProcessResult r = prefix.empty() ? impl.run(text) : impl.run_after(prefix, text);
        Outcome o = judge(build(g), r, o_.limits, judging_);
        if (!same_failure(o, like)) return std::nullopt;
        return o;
    }

    void shrink(Counterexample& x) {
        const Clock::time_point begin = Clock::now();
        const Clock::time_point deadline = begin + o_.shrink_time;
        ProcessLimits limits = o_.limits;
        if (x.first.kind == FailureKind::Timeout) {
            // A hang costs a whole timeout per failing candidate: give the
            // candidates a few times what the slowest passing case needed.
            const milliseconds derived = std::max(kMinShrinkTimeout,
                                                  milliseconds(slowest_pass_.count() * kShrinkTimeoutFactor));
            if (derived < limits.timeout) {
                limits.timeout = derived;
                x.shrink_timeout = derived;
            }
        }
        Impl impl(o_, limits);
        std::unordered_set<std::uint64_t> passed;
        std::vector<PlanarGraph> accepted;  // every smaller failing graph, for a hang's confirmation
        auto attempt = [&](const PlanarGraph& candidate, const std::vector<std::string>& prefix,
                           const std::string& text) -> std::optional<Outcome> {
            const std::uint64_t h = text_hash(text) ^ (prefix.size() * 0x9e3779b97f4a7c15ULL);
            if (passed.contains(h)) return std::nullopt;
            ++x.attempts;
            if (progress_) {
                progress_("shrinking failure " + std::to_string(result_.failures.size() + 1) + ": " +
                          std::to_string(x.graph.vertices.size()) + " vertices, " + std::to_string(x.graph.edges.size()) +
                          " edges, " + std::to_string(x.attempts) + " attempts");
            }
            if (!prefix.empty()) impl.restart();
            ProcessResult r = prefix.empty() ? impl.run(text) : impl.run_after(prefix, text);
            Outcome o = judge(build(candidate), r, limits, judging_);
            if (!same_failure(o, x.first)) {
                passed.insert(h);
                if (o.kind == FailureKind::Timeout || o.kind == FailureKind::Crash) impl.restart();
                return std::nullopt;
            }
            return o;
        };
        auto out_of_budget = [&] {
            if (Clock::now() < deadline && x.attempts < o_.shrink_attempts) return false;
            x.budget_spent = true;
            return true;
        };
        // The failing graph, with the prefix (if any) fixed. Each pass
        // starts where the last move came from (gen::ShrinkCandidates::Position).
        gen::ShrinkCandidates::Position resume;
        bool progress = true;
        while (!out_of_budget()) {
            progress = false;
            gen::ShrinkCandidates candidates(x.graph, resume);
            while (std::optional<PlanarGraph> c = candidates.next()) {
                if (out_of_budget()) break;
                const std::string text = spell(*c, x.original.spec);
                if (std::optional<Outcome> o = attempt(*c, x.prefix, text)) {
                    x.graph = std::move(*c);
                    x.text = text;
                    x.outcome = std::move(*o);
                    ++x.steps;
                    if (x.shrink_timeout) accepted.push_back(x.graph);
                    resume = candidates.position();
                    progress = true;
                    break;
                }
            }
            if (progress) continue;
            if (resume.stage == gen::ShrinkCandidates::Stage::Empty) break;  // a whole pass found nothing
            resume = {};
        }
        // Then each graph of the prefix, the others fixed.
        // Then the prefix: each graph left out where the failure allows,
        // then each shrunk, the others fixed.
        for (std::size_t j = 0; j < x.prefix.size() && !out_of_budget();) {
            std::vector<std::string> shorter = x.prefix;
            shorter.erase(shorter.begin() + static_cast<std::ptrdiff_t>(j));
            if (std::optional<Outcome> o = attempt(x.graph, shorter, x.text); o && !shorter.empty()) {
                x.prefix = std::move(shorter);
                prefix_cases_.erase(prefix_cases_.begin() + static_cast<std::ptrdiff_t>(j));
                x.outcome = std::move(*o);
                ++x.steps;
            } else {
                ++j;
            }
        }
        for (std::size_t j = 0; j < x.prefix.size() && !out_of_budget(); ++j) {
            PlanarGraph p = prefix_cases_[j].graph;
            progress = true;  // (the prefix graphs: plain greedy passes)
            while (progress && !out_of_budget()) {
                progress = false;
                gen::ShrinkCandidates candidates(p);
                while (std::optional<PlanarGraph> c = candidates.next()) {
                    if (out_of_budget()) break;
                    std::vector<std::string> prefix = x.prefix;
                    prefix[j] = spell(*c, prefix_cases_[j].spec);
                    if (std::optional<Outcome> o = attempt(x.graph, prefix, x.text)) {
                        p = std::move(*c);
                        x.prefix = std::move(prefix);
                        x.outcome = std::move(*o);
                        ++x.steps;
                        progress = true;
                        break;
                    }
                }
            }
        }
        if (x.shrink_timeout) confirm_hang(x, accepted);
        x.shrink_elapsed = since(begin);
    }

    // Candidates ran with a shortened timeout; the counterexample must hang
    // for the whole --timeout-ms. The smallest accepted graph that does is it.
    void confirm_hang(Counterexample& x, std::vector<PlanarGraph>& accepted) {
        impl_.restart();
        accepted.insert(accepted.begin(), x.original.graph);
        while (!accepted.empty()) {
            const PlanarGraph g = std::move(accepted.back());
            accepted.pop_back();
            const std::string text = spell(g, x.original.spec);
            if (std::optional<Outcome> o = fails_same_outcome(impl_, x.prefix, text, x.first)) {
                x.graph = g;
                x.text = text;
                x.outcome = std::move(*o);
                return;
            }
            impl_.restart();
        }
    }

    const DiffOptions& o_;
    const Progress& progress_;
    Clock::time_point start_ = Clock::now();
    std::clock_t cpu_start_ = std::clock();  // this process only, not the command
    Impl impl_;
    AnswerJudging judging_;
    DiffResult result_;
    milliseconds slowest_pass_{0};
    std::deque<Case> history_;        // --stream: the last graphs that passed, in order
    std::vector<Case> prefix_cases_;  // the cases behind a failure's prefix
};

}  // namespace

DiffResult run_diff(const DiffOptions& options, const Progress& progress) { return Session(options, progress).run(); }

}  // namespace dcel::cli
