#include "dcel/diff/session.hpp"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_set>

#include "dcel/build.hpp"
#include "dcel/diff/speed.hpp"
#include "dcel/error.hpp"
#include "dcel/gen/session.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::diff {
namespace {

using std::chrono::milliseconds;

// How many passing graphs a --stream failure may need before it.
constexpr std::size_t kHistory = 8;
// Skip reasons listed one by one; more share the last entry.
constexpr std::size_t kMaxSkipReasons = 20;
// A hang's candidates get this many times the slowest passing run, at least kMinShrinkTimeout.
constexpr long kShrinkTimeoutFactor = 5;
constexpr milliseconds kMinShrinkTimeout{250};

// sh's own statuses for "not found" and "not executable": the command never ran.
bool could_not_run(const Outcome& o) {
    return o.kind == FailureKind::NonZeroExit && (o.run.exit_status == 126 || o.run.exit_status == 127);
}

std::uint64_t text_hash(const std::string& text) { return std::hash<std::string>{}(text); }

class Session {
public:
    Session(const DiffOptions& o, const Progress& progress, const ImplementationFactory& make, const Clock& clock)
        : o_(o), progress_(progress), make_(make), clock_(clock), impl_(make(o.limits)), judging_{o.answer, {}} {}

    DiffResult run() {
        const std::size_t first = o_.only_case.value_or(0);
        const std::size_t end = o_.only_case ? first + 1 : o_.cases.value_or(SIZE_MAX);
        result_.first_case = first;
        result_.stopped_by = StopReason::Cases;
        std::size_t starts = 0;
        if (o_.jobs > 1 && !o_.only_case) {
            starts = run_on_workers(first, end);
        } else {
            for (std::size_t i = in_shard(first); i < end; i = in_shard(i + 1)) {
                if (time_is_up()) break;
                if (!run_case(i, first)) break;
            }
        }
        starts += impl_->starts();
        result_.restarts = starts > 0 ? starts - 1 : 0;
        result_.elapsed = since(start_);
        result_.reference_cpu = clock_.cpu() - cpu_start_;
        result_.agreed_as = judging_.agreed_as;
        return std::move(result_);
    }

private:
    [[nodiscard]] milliseconds since(Clock::time_point t) const {
        return std::chrono::duration_cast<milliseconds>(clock_.now() - t);
    }

    // The first case from i on that belongs to this run's shard (--shard K/N:
    // the cases i with i mod N = K - 1); i itself without --shard or --case.
    [[nodiscard]] std::size_t in_shard(std::size_t i) const {
        if (!o_.shard || o_.only_case) return i;
        const std::size_t n = o_.shard->count, k = o_.shard->index - 1;
        const std::size_t r = i % n;
        return r <= k ? i - r + k : i - r + n + k;
    }

    bool time_is_up() {
        if (!o_.time || o_.only_case || since(start_) < *o_.time) return false;
        result_.stopped_by = StopReason::Time;
        return true;
    }

    // A case as run: its graph (none when the schedule found none), the
    // limit it ran under, what the command did and how long it took.
    struct Ran {
        std::optional<Case> c;
        milliseconds limit{};
        ProcessResult run;
        milliseconds took{};
        std::size_t worker = 0;
        // A worker's failure to run the command at all (ProcessError: no
        // pipe, no /bin/sh), rethrown where the case is settled, as without --jobs.
        std::exception_ptr error;
    };

    [[nodiscard]] milliseconds limit_for(const Case& c) {
        const std::lock_guard<std::mutex> lock(speed_mutex_);
        return speed_.limit(c.graph.vertices.size() + c.graph.edges.size(), o_.limits.timeout);
    }

    // Runs case i on `impl`; does not judge it.
    Ran run_only(std::size_t i, Implementation& impl, std::size_t worker) {
        Ran r;
        r.worker = worker;
        r.c = make_case(o_.schedule, i);
        if (!r.c) return r;
        r.limit = limit_for(*r.c);
        const Clock::time_point t = clock_.now();
        r.run = impl.run(r.c->text, r.limit);
        r.took = since(t);
        return r;
    }

    // Runs case i; false when the run stops here.
    bool run_case(std::size_t i, std::size_t first) { return settle(run_only(i, *impl_, 0), i, first); }

    // ---- With --jobs: the search on workers, the judging in order.
    //
    // Each worker has its own implementation (its own --stream process) and
    // runs the cases it takes, a bounded window ahead of the judging. The
    // cases are judged here one by one in case order, as without --jobs:
    // the grouping, the counting and which case is shrunk depend only on the
    // order, and a new failure is confirmed and shrunk alone (the workers
    // start no case meanwhile). What can differ from --jobs 1 is only what
    // depends on time (a case's limit follows the speed of the cases done
    // so far) or on a --stream process's state (the graphs a worker's
    // process saw before a failure are that worker's, and a reproduction
    // after them uses those).
    std::size_t run_on_workers(std::size_t first, std::size_t end) {
        // How far ahead of the judging the workers may run, in case numbers
        // (a shard's cases are N apart).
        const std::size_t window = 4 * o_.jobs * (o_.shard ? o_.shard->count : 1);
        std::mutex m;
        std::condition_variable changed;
        std::map<std::size_t, Ran> done;
        std::size_t next = in_shard(first), judged = first;
        bool stop = false, paused = false;
        std::vector<char> restart(o_.jobs, 0);
        std::vector<std::unique_ptr<Implementation>> impls;
        for (std::size_t w = 0; w < o_.jobs; ++w) impls.push_back(make_(o_.limits));
        histories_.resize(o_.jobs);
        std::vector<std::thread> workers;
        for (std::size_t w = 0; w < o_.jobs; ++w) {
            workers.emplace_back([&, w] {
                std::unique_lock<std::mutex> lock(m);
                for (;;) {
                    changed.wait(lock, [&] { return stop || (!paused && next < end && next < judged + window); });
                    if (stop) return;
                    const std::size_t i = next;
                    next = in_shard(next + 1);
                    const bool fresh = restart[w] != 0;
                    restart[w] = 0;
                    lock.unlock();
                    Ran r;
                    try {
                        if (fresh) impls[w]->restart();
                        r = run_only(i, *impls[w], w);
                    } catch (...) {
                        r.worker = w;
                        r.error = std::current_exception();
                    }
                    lock.lock();
                    done.emplace(i, std::move(r));
                    changed.notify_all();
                }
            });
        }
        // The workers stop and are joined however this ends (settle throws
        // when the command cannot be run at all).
        const auto stop_workers = [&] {
            {
                const std::lock_guard<std::mutex> lock(m);
                stop = true;
            }
            changed.notify_all();
            for (std::thread& t : workers) t.join();
        };
        try {
            for (std::size_t i = in_shard(first); i < end && !time_is_up(); i = in_shard(i + 1)) {
                std::unique_lock<std::mutex> lock(m);
                changed.wait(lock, [&] { return done.contains(i); });
                Ran r = std::move(done.at(i));
                done.erase(i);
                if (r.error) std::rethrow_exception(r.error);
                judged = i + 1;
                paused = true;  // while settling: a new failure is confirmed and shrunk alone
                changed.notify_all();
                lock.unlock();
                const std::size_t worker = r.worker, failures = result_.failures.size();
                const bool go_on = settle(std::move(r), i, first);
                lock.lock();
                if (result_.failures.size() != failures) restart[worker] = 1;  // the search goes on in a fresh process
                paused = false;
                changed.notify_all();
                if (!go_on) break;
            }
        } catch (...) {
            stop_workers();
            throw;
        }
        stop_workers();
        std::size_t starts = 0;
        for (const auto& impl : impls) starts += impl->starts();
        return starts;
    }

    // Judges a case as run and takes what follows from it; false when the
    // run stops here.
    bool settle(Ran r, std::size_t i, std::size_t first) {
        ++result_.cases_run;
        if (!r.c) {
            ++result_.skipped;
            return true;
        }
        result_.large_cases += r.c->spec.large ? 1 : 0;
        report_progress(i, *r.c);
        const std::size_t size = r.c->graph.vertices.size() + r.c->graph.edges.size();
        const milliseconds limit = r.limit;
        Outcome outcome = judge_case(*r.c, r.run, limit_as(limit));
        const milliseconds took = r.took;
        worker_ = r.worker;
        if (outcome.skipped) {
            count_skip(outcome.skip_reason);
            return true;
        }
        if (outcome.agrees) {
            if (outcome.cycles_only) ++result_.cycles_only;
            for (std::size_t op = 0; op < check::kStepOpCount; ++op) result_.skipped_steps[op] += outcome.skipped_steps[op];
            {
                const std::lock_guard<std::mutex> lock(speed_mutex_);
                speed_.record(size, took);
            }
            slowest_pass_ = std::max(slowest_pass_, took);
            if (took > o_.limits.timeout) note_slow(*r.c, took, limit);
            remember(std::move(*r.c));
            return true;
        }
        if (i == first && could_not_run(outcome)) {
            std::string why = outcome.run.err_tail;
            while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
            throw ProcessError("cannot run --impl '" + o_.impl + "': /bin/sh " + describe_end(outcome.run, o_.limits) +
                               (why.empty() ? "" : ": " + printable(why, 300)));
        }
        on_failure(std::move(*r.c), std::move(outcome), limit);
        if (!o_.keep_going) {
            result_.stopped_by = StopReason::FirstFailure;
            return false;
        }
        if (result_.failures.size() >= o_.max_failures) {
            result_.stopped_by = StopReason::MaxFailures;
            return false;
        }
        return true;
    }

    // The run of a case judged: a graph against its reference DCEL, a
    // session against the reference running it.
    Outcome judge_case(const Case& c, const ProcessResult& r, const ProcessLimits& limits) {
        if (c.session) return judge_session(*c.session, r, limits);
        return judge(build(c.graph), r, limits, judging_);
    }

    // The same for the exact bytes of a case, a candidate or a replay.
    Outcome judge_text(const std::string& text, const ProcessResult& r, const ProcessLimits& limits) {
        if (o_.schedule.sessions) return judge_session(check::read_session(text), r, limits);
        return judge(build(io::read_graph(text)), r, limits, judging_);
    }

    [[nodiscard]] ProcessLimits limit_as(milliseconds limit) const {
        ProcessLimits l = o_.limits;
        l.timeout = limit;
        return l;
    }

    void count_skip(const std::string& reason) {
        ++result_.skipped_by_impl;
        auto& reasons = result_.skip_reasons;
        const auto it = std::find_if(reasons.begin(), reasons.end(), [&](const auto& r) { return r.first == reason; });
        if (it != reasons.end()) {
            ++it->second;
        } else if (reasons.size() < kMaxSkipReasons) {
            reasons.emplace_back(reason, 1);
        } else {
            ++reasons.back().second;  // "... and others" share the last entry
        }
    }

    void note_slow(const Case& c, milliseconds took, milliseconds limit) {
        ++result_.slow_count;
        if (result_.slow.size() >= kMaxListedSlowCases) return;
        result_.slow.push_back(
            {c.spec.number, c.spec.params.family, c.graph.vertices.size(), c.graph.edges.size(), took, limit});
    }

    void report_progress(std::size_t i, const Case& c) {
        if (!progress_) return;
        const std::size_t end = o_.cases.value_or(0);
        std::string line = "case " + std::to_string(i) + (o_.cases ? "/" + std::to_string(end) : "") + ", " +
                           std::to_string(since(start_).count() / 1000) +
                           " s: " + std::string(gen::family_name(c.spec.params.family)) + ", " +
                           std::to_string(c.graph.vertices.size()) + " vertices, " +
                           std::string(gen::coordinate_class_name(c.coordinates));
        if (!result_.failures.empty()) line += "; " + std::to_string(result_.failures.size()) + " distinct failures";
        progress_(line);
    }

    // The passing graphs of the worker that ran the current case.
    void remember(Case c) {
        if (!o_.stream) return;
        std::deque<Case>& history = histories_[worker_];
        history.push_back(std::move(c));
        if (history.size() > kHistory) history.pop_front();
    }

    // A failure: counted against the failure whose key it has (its class,
    // its kinds of difference and its coordinate class: it is most likely
    // the same bug); otherwise confirmed and shrunk, then joined to the
    // failure whose counterexample has the same signature, or kept as a new
    // one (session.hpp, Failure).
    void on_failure(Case c, Outcome outcome, milliseconds limit) {
        const gen::CoordinateClass coordinates = c.coordinates;
        const std::string key = failure_class(outcome) + "|" + difference_kinds(outcome) + "|" +
                                std::string(gen::coordinate_class_name(coordinates));
        for (Failure& f : result_.failures) {
            for (KeySeen& k : f.keys) {
                if (k.key != key) continue;
                count(f, k, c.spec.number);
                return;
            }
        }
        Failure f;
        f.keys.push_back({key, coordinates, 0, {}});
        f.classes.push_back(coordinates);
        f.found_after = since(start_);
        count(f, f.keys.back(), c.spec.number);
        f.example = investigate(std::move(c), std::move(outcome), limit);
        impl_->restart();  // the search goes on in a fresh process
        f.signature = signature(f.example);
        for (Failure& other : result_.failures) {
            if (other.signature != f.signature) continue;
            other.keys.push_back({key, coordinates, 0, {}});
            if (std::find(other.classes.begin(), other.classes.end(), coordinates) == other.classes.end()) {
                other.classes.push_back(coordinates);
            }
            count(other, other.keys.back(), f.cases.front());
            return;
        }
        f.id = result_.failures.size() + 1;
        result_.failures.push_back(std::move(f));
    }

    // What the failure is once shrunk: its class, its kinds of difference,
    // and the size it shrank to. (Not its coordinates: the same bug seen
    // in two coordinate classes shrinks to the same shape in each.) An
    // unreproduced failure keeps its case's key: its graph is not shrunk.
    static std::string signature(const Counterexample& x) {
        std::string size = std::to_string(x.graph.vertices.size()) + "v" + std::to_string(x.graph.edges.size()) + "e";
        if (x.session) size += std::to_string(x.session->steps.size()) + "s";
        return failure_class(x.outcome) + "|" + difference_kinds(x.outcome) + "|" +
               (x.reproduced ? size : "case " + std::to_string(x.original.spec.number));
    }

    static void count(Failure& f, KeySeen& k, std::size_t case_number) {
        ++f.occurrences;
        if (f.cases.size() < kMaxListedCases) f.cases.push_back(case_number);
        ++k.occurrences;
        if (k.cases.size() < kMaxListedCases) k.cases.push_back(case_number);
    }

    Counterexample investigate(Case c, Outcome first, milliseconds limit) {
        Counterexample x;
        x.limit = limit;
        x.first = std::move(first);
        x.original = std::move(c);
        x.graph = x.original.graph;
        x.session = x.original.session;
        x.text = x.original.text;
        x.outcome = x.first;
        reproduce(x);
        if (x.reproduced) shrink(x);
        recheck_hint(x);
        return x;
    }

    // Alone, in a fresh process; then, for a --stream that keeps state,
    // after the last 1, 2, 4 or 8 graphs that passed before it.
    void reproduce(Counterexample& x) {
        impl_->restart();
        x.reproduced = fails_same(*impl_, {}, x.original.text, x.first, x.limit).has_value();
        if (x.reproduced || !o_.stream) return;
        const std::deque<Case>& history = histories_[worker_];
        for (std::size_t k = 1; k <= history.size() && !x.reproduced; k *= 2) {
            std::vector<std::string> prefix;
            for (std::size_t j = history.size() - k; j < history.size(); ++j) prefix.push_back(history[j].text);
            if (fails_same(*impl_, prefix, x.original.text, x.first, x.limit)) {
                x.reproduced = true;
                x.prefix = std::move(prefix);
                prefix_cases_.assign(history.end() - static_cast<std::ptrdiff_t>(k), history.end());
            }
        }
    }

    // A hint that another convention makes the answer agree must hold for the
    // case as found, not only for the shrunk graph (where a bug that reverses
    // every cycle through a vertex of degree 3 reverses them all).
    void recheck_hint(Counterexample& x) const {
        std::vector<std::string>& notes = x.outcome.report.notes;
        std::erase_if(notes, [](const std::string& n) { return n.rfind("the answer agrees", 0) == 0; });
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

    // The outcome when the graph fails like `like` (run in a fresh process
    // after `prefix` when there is one, under `limit`), or nothing.
    std::optional<Outcome> fails_same(Implementation& impl, const std::vector<std::string>& prefix, const std::string& text,
                                      const Outcome& like, milliseconds limit) {
        if (!prefix.empty()) {
            impl.restart();
            for (const std::string& p : prefix) (void)impl.run(p);
        }
        const ProcessResult r = impl.run(text, limit);
        Outcome o = judge_text(text, r, limit_as(limit));
        if (!same_failure(o, like)) return std::nullopt;
        return o;
    }

    // What shrinking one failure needs: its own implementation (a hang's
    // candidates run under a shorter timeout), the candidates known to pass,
    // the budget, and every smaller failing graph (for a hang's confirmation).
    struct Shrinking {
        Counterexample& x;
        ProcessLimits limits;
        std::unique_ptr<Implementation> impl;
        Clock::time_point deadline;
        std::unordered_set<std::uint64_t> passed;
        std::vector<std::string> accepted;  // the exact texts of the smaller failing cases, in order
    };

    void shrink(Counterexample& x) {
        const Clock::time_point begin = clock_.now();
        Clock::time_point deadline = begin + o_.shrink_time;
        if (o_.time && !o_.only_case) deadline = std::min(deadline, start_ + *o_.time);  // --time bounds the whole run
        Shrinking s{x, shrink_limits(x), nullptr, deadline, {}, {}};
        s.impl = make_(s.limits);
        x.minimal = shrink_graph(s);
        drop_prefix_graphs(s);
        shrink_prefix_graphs(s);
        if (x.shrink_timeout) confirm_hang(x, s.accepted);
        x.shrink_elapsed = since(begin);
    }

    // A hang costs a whole timeout per failing candidate: the candidates get
    // a few times what the slowest passing case needed.
    ProcessLimits shrink_limits(Counterexample& x) const {
        ProcessLimits limits = limit_as(x.limit);
        if (x.first.kind != FailureKind::Timeout) return limits;
        const milliseconds derived = std::max(kMinShrinkTimeout, milliseconds(slowest_pass_.count() * kShrinkTimeoutFactor));
        if (derived < limits.timeout) {
            limits.timeout = derived;
            x.shrink_timeout = derived;
        }
        return limits;
    }

    bool out_of_budget(Shrinking& s) const {
        if (clock_.now() < s.deadline && s.x.attempts < o_.shrink_attempts) return false;
        s.x.budget_spent = true;
        return true;
    }

    // Runs one candidate (the graph with the prefix graphs before it); its
    // outcome when it fails the same way as the original.
    std::optional<Outcome> attempt(Shrinking& s, const std::vector<std::string>& prefix, const std::string& text) {
        const std::uint64_t h = text_hash(text) ^ (prefix.size() * 0x9e3779b97f4a7c15ULL);
        if (s.passed.contains(h)) return std::nullopt;
        ++s.x.attempts;
        if (progress_) {
            progress_("shrinking failure " + std::to_string(result_.failures.size() + 1) + ": " +
                      std::to_string(s.x.graph.vertices.size()) + " vertices, " + std::to_string(s.x.graph.edges.size()) +
                      " edges, " + std::to_string(s.x.attempts) + " attempts");
        }
        if (!prefix.empty()) {
            s.impl->restart();
            for (const std::string& p : prefix) (void)s.impl->run(p);
        }
        const ProcessResult r = s.impl->run(text, s.limits.timeout);
        Outcome o = judge_text(text, r, s.limits);
        if (!same_failure(o, s.x.first)) {
            s.passed.insert(h);
            if (o.kind == FailureKind::Timeout || o.kind == FailureKind::Crash) s.impl->restart();
            return std::nullopt;
        }
        return o;
    }

    // The failing graph (or session), the prefix (if any) fixed; true when
    // it ended because no single candidate of the result fails (1-minimal).
    bool shrink_graph(Shrinking& s) {
        Counterexample& x = s.x;
        // A candidate taken: x follows it, and a hang's are kept for its confirmation.
        auto take = [&](std::string text, Outcome o) {
            if (x.shrink_timeout) s.accepted.push_back(text);
            x.text = std::move(text);
            x.outcome = std::move(o);
            ++x.steps;
        };
        if (x.session) {
            return !gen::shrink_session_greedily(
                        *x.session,
                        [&](const check::Session& c) {
                            std::string text = spell(c);
                            std::optional<Outcome> o = attempt(s, x.prefix, text);
                            if (!o) return false;
                            x.session = c;
                            x.graph = c.start;
                            take(std::move(text), std::move(*o));
                            return true;
                        },
                        [&] { return out_of_budget(s); })
                        .stopped;
        }
        return !gen::shrink_greedily(
                    x.graph,
                    [&](const PlanarGraph& c) {
                        std::string text = spell(c, x.original.spec);
                        std::optional<Outcome> o = attempt(s, x.prefix, text);
                        if (!o) return false;
                        x.graph = c;
                        take(std::move(text), std::move(*o));
                        return true;
                    },
                    [&] { return out_of_budget(s); })
                    .stopped;
    }

    // Each graph of the prefix left out where the failure allows.
    void drop_prefix_graphs(Shrinking& s) {
        Counterexample& x = s.x;
        for (std::size_t j = 0; j < x.prefix.size() && !out_of_budget(s);) {
            std::vector<std::string> shorter = x.prefix;
            shorter.erase(shorter.begin() + static_cast<std::ptrdiff_t>(j));
            if (std::optional<Outcome> o = attempt(s, shorter, x.text); o && !shorter.empty()) {
                x.prefix = std::move(shorter);
                prefix_cases_.erase(prefix_cases_.begin() + static_cast<std::ptrdiff_t>(j));
                x.outcome = std::move(*o);
                ++x.steps;
            } else {
                ++j;
            }
        }
    }

    // Then each graph of the prefix shrunk, the others fixed.
    void shrink_prefix_graphs(Shrinking& s) {
        Counterexample& x = s.x;
        if (x.session) return;  // (a session's prefix is other sessions: dropped above, not shrunk)
        for (std::size_t j = 0; j < x.prefix.size() && !out_of_budget(s); ++j) {
            (void)gen::shrink_greedily(
                prefix_cases_[j].graph,
                [&](const PlanarGraph& c) {
                    std::vector<std::string> prefix = x.prefix;
                    prefix[j] = spell(c, prefix_cases_[j].spec);
                    std::optional<Outcome> o = attempt(s, prefix, x.text);
                    if (!o) return false;
                    x.prefix = std::move(prefix);
                    x.outcome = std::move(*o);
                    ++x.steps;
                    return true;
                },
                [&] { return out_of_budget(s); });
        }
    }

    // Candidates ran with a shortened timeout; the counterexample must hang
    // for the case's whole limit. The smallest accepted case that does is it.
    void confirm_hang(Counterexample& x, std::vector<std::string>& accepted) {
        impl_->restart();
        accepted.insert(accepted.begin(), x.original.text);
        while (!accepted.empty()) {
            const std::string text = std::move(accepted.back());
            accepted.pop_back();
            if (std::optional<Outcome> o = fails_same(*impl_, x.prefix, text, x.first, x.limit)) {
                if (x.session) {
                    x.session = check::read_session(text);
                    x.graph = x.session->start;
                } else {
                    x.graph = io::read_graph(text);
                }
                x.text = text;
                x.outcome = std::move(*o);
                return;
            }
            impl_->restart();
        }
    }

    const DiffOptions& o_;
    const Progress& progress_;
    const ImplementationFactory& make_;
    const Clock& clock_;
    Clock::time_point start_ = clock_.now();
    milliseconds cpu_start_ = clock_.cpu();  // this process only, not the command
    std::unique_ptr<Implementation> impl_;
    AnswerJudging judging_;
    DiffResult result_;
    milliseconds slowest_pass_{0};
    SpeedModel speed_;        // the implementation's speed on passing cases, for each case's time limit
    std::mutex speed_mutex_;  // the workers read speed_ (--jobs)
    // --stream: the last graphs that passed, in order, for each worker (one without --jobs)
    std::vector<std::deque<Case>> histories_ = std::vector<std::deque<Case>>(1);
    std::size_t worker_ = 0;          // the worker that ran the case being settled
    std::vector<Case> prefix_cases_;  // the cases behind a failure's prefix
};

}  // namespace

DiffResult run_diff(const DiffOptions& options, const Progress& progress, const ImplementationFactory& implementation,
                    const Clock& clock) {
    return Session(options, progress, implementation, clock).run();
}

DiffResult run_diff(const DiffOptions& options, const Progress& progress) {
    return run_diff(options, progress, command_implementation(options.impl, options.stream), system_clock());
}

}  // namespace dcel::diff
