// The diff engine (src/dcel/diff/) with fake implementations and a fake
// clock (fakes.hpp): what it runs, how it judges, groups and shrinks, and
// that every budget is kept, without a process or a real second passing.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <string>

#include "dcel/diff/report.hpp"
#include "dcel/diff/session.hpp"
#include "dcel/io/json_reader.hpp"
#include "dcel/queries.hpp"
#include "fakes.hpp"

namespace dcel::diff {
namespace {

using fake::Call;
using fake::Reply;
using std::chrono::milliseconds;

struct Harness {
    fake::FakeClock clock;
    fake::Counters counters;
    DiffOptions options;

    Harness() {
        options.impl = "fake";
        options.cases = 60;
        options.schedule.large_vertices = 0;  // small graphs: fast tests
    }
    DiffResult run(const fake::Behaviour& b) { return run_diff(options, {}, fake::factory(b, clock, counters), clock); }
};

std::size_t degree(const PlanarGraph& g, std::size_t v) {
    return static_cast<std::size_t>(std::count_if(g.edges.begin(), g.edges.end(),
                                                  [&](const GraphEdge& e) { return e.u.index() == v || e.v.index() == v; }));
}
bool has_isolated_vertex(const PlanarGraph& g) {
    for (std::size_t v = 0; v < g.vertices.size(); ++v) {
        if (degree(g, v) == 0) return true;
    }
    return false;
}
std::size_t max_degree(const PlanarGraph& g) {
    std::size_t m = 0;
    for (std::size_t v = 0; v < g.vertices.size(); ++v) m = std::max(m, degree(g, v));
    return m;
}

Reply right(const Call& r) { return fake::answer(fake::right_faces(r.graph)); }

// Every cycle reversed once the graph has three edges or more.
Reply reverses_cycles(const Call& r) {
    if (r.graph.edges.size() < 3) return right(r);
    std::vector<std::vector<VertexId>> cycles = boundary_cycles(build(r.graph));
    for (auto& c : cycles) std::reverse(c.begin() + 1, c.end());
    return fake::answer(io::write_faces(cycles));
}

TEST(DiffEngine, ARightImplementationAgreesOnEveryCase) {
    Harness h;
    const DiffResult r = h.run(right);
    EXPECT_TRUE(r.failures.empty());
    EXPECT_EQ(r.cases_run, 60U);
    EXPECT_EQ(r.stopped_by, StopReason::Cases);
    EXPECT_EQ(h.counters.runs, 60U);
}

TEST(DiffEngine, AWrongAnswerIsShrunkToTheSmallestGraphThatFailsTheSameWay) {
    Harness h;
    const DiffResult r = h.run(reverses_cycles);
    ASSERT_EQ(r.failures.size(), 1U);
    const Counterexample& c = r.failures[0].example;
    EXPECT_EQ(c.first.kind, FailureKind::WrongAnswer);
    EXPECT_TRUE(c.reproduced);
    EXPECT_EQ(c.graph.edges.size(), 3U);  // the bug needs three edges, and nothing else
    EXPECT_GT(c.steps, 0U);
    EXPECT_EQ(r.stopped_by, StopReason::FirstFailure);
}

TEST(DiffEngine, ACrashIsShrunkToOneIsolatedVertex) {
    Harness h;
    const DiffResult r = h.run(
        [](const Call& run) { return has_isolated_vertex(run.graph) ? fake::signalled(11) : right(run); });
    ASSERT_EQ(r.failures.size(), 1U);
    const Counterexample& c = r.failures[0].example;
    EXPECT_EQ(c.outcome.kind, FailureKind::Crash);
    EXPECT_EQ(c.outcome.run.signal, 11);
    EXPECT_EQ(c.graph.vertices.size(), 1U);
    EXPECT_EQ(c.graph.edges.size(), 0U);
}

TEST(DiffEngine, ShellExitStatusAboveOneTwentyEightIsASignal) {
    Harness h;
    const DiffResult r = h.run([](const Call& run) { return run.graph.edges.size() >= 2 ? fake::exited(139) : right(run); });
    ASSERT_EQ(r.failures.size(), 1U);
    EXPECT_EQ(r.failures[0].example.first.kind, FailureKind::Crash);
    EXPECT_EQ(r.failures[0].example.first.run.signal, 11);
}

TEST(DiffEngine, AHangShrinksUnderADerivedTimeoutAndIsConfirmedWithTheFullOne) {
    Harness h;
    h.options.limits.timeout = milliseconds(5000);
    const DiffResult r = h.run([](const Call& run) { return max_degree(run.graph) >= 3 ? fake::hangs() : right(run); });
    ASSERT_EQ(r.failures.size(), 1U);
    const Counterexample& c = r.failures[0].example;
    EXPECT_EQ(c.outcome.kind, FailureKind::Timeout);
    ASSERT_TRUE(c.shrink_timeout.has_value());
    EXPECT_LT(*c.shrink_timeout, milliseconds(5000));
    EXPECT_EQ(c.graph.edges.size(), 3U);  // a star of three: the smallest vertex of degree 3
    EXPECT_EQ(c.graph.vertices.size(), 4U);
}

TEST(DiffEngine, TimeBoundsTheSearchOnTheEnginesClock) {
    Harness h;
    h.options.cases.reset();
    h.options.time = milliseconds(1000);
    const DiffResult r = h.run([](const Call& run) {
        Reply reply = right(run);
        reply.cost = milliseconds(100);
        return reply;
    });
    EXPECT_EQ(r.stopped_by, StopReason::Time);
    EXPECT_EQ(r.cases_run, 10U);  // 10 runs of 100 ms fill the second
    EXPECT_EQ(r.elapsed, milliseconds(1000));
}

TEST(DiffEngine, ShrinkingStopsAtItsBudgetAndSaysSo) {
    Harness h;
    h.options.shrink_attempts = 3;
    const DiffResult r = h.run(reverses_cycles);
    ASSERT_EQ(r.failures.size(), 1U);
    EXPECT_TRUE(r.failures[0].example.budget_spent);
    EXPECT_EQ(r.failures[0].example.attempts, 3U);
}

TEST(DiffEngine, KeepGoingGroupsTwoBugsIntoTwoFailures) {
    Harness h;
    h.options.keep_going = true;
    h.options.cases = 120;
    const DiffResult r = h.run([](const Call& run) {
        if (has_isolated_vertex(run.graph)) return fake::exited(3, "isolated vertices are not supported\n");
        return reverses_cycles(run);
    });
    std::vector<FailureKind> kinds;
    for (const Failure& f : r.failures) kinds.push_back(f.example.first.kind);
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), FailureKind::NonZeroExit), kinds.end());
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), FailureKind::WrongAnswer), kinds.end());
    std::size_t occurrences = 0;
    for (const Failure& f : r.failures) occurrences += f.occurrences;
    EXPECT_GT(occurrences, r.failures.size());  // later cases are counted, not shrunk again
}

TEST(DiffEngine, AStreamThatKeepsStateIsReportedWithTheGraphsBeforeIt) {
    Harness h;
    h.options.stream = true;
    // Fails on any graph that follows one of five vertices or more in the
    // same process: alone, every graph passes.
    const DiffResult r = h.run([](const Call& run) {
        const bool after_big = std::any_of(run.before.begin(), run.before.end(),
                                           [](const std::string& t) { return io::read_graph(t).vertices.size() >= 5; });
        return after_big ? fake::exited(5) : right(run);
    });
    ASSERT_EQ(r.failures.size(), 1U);
    const Counterexample& c = r.failures[0].example;
    EXPECT_TRUE(c.reproduced);
    ASSERT_EQ(c.prefix.size(), 1U);
    EXPECT_EQ(io::read_graph(c.prefix[0]).vertices.size(), 5U);  // shrunk too
}

TEST(DiffEngine, AFlakyImplementationIsReportedUnshrunk) {
    Harness h;
    std::size_t calls = 0;
    const DiffResult r = h.run([&calls](const Call& run) {
        ++calls;
        return run.graph.vertices.size() >= 5 && calls % 7 == 0 ? fake::exited(2) : right(run);
    });
    ASSERT_EQ(r.failures.size(), 1U);
    EXPECT_FALSE(r.failures[0].example.reproduced);
    EXPECT_EQ(r.failures[0].example.attempts, 0U);
}

TEST(DiffEngine, ACommandShCannotRunIsAProcessError) {
    Harness h;
    EXPECT_THROW((void)h.run([](const Call&) { return fake::exited(127, "sh: 1: nope: not found\n"); }), ProcessError);
}

// A command that cannot be run at all from one case on (no pipe left, no
// /bin/sh: a ProcessError from the process layer). With --jobs the error
// rises in a worker's thread; it must end the run as it does without workers,
// out of run_diff, the workers stopped and joined (escaping its thread it
// would abort the program). Each worker's implementation here is its own, and
// only an atomic counter is shared, so the workers race on nothing.
class StopsStartingAt : public Implementation {
public:
    StopsStartingAt(std::atomic<std::size_t>& runs, std::size_t from) : runs_(runs), from_(from) {}
    ProcessResult run(const std::string& text, milliseconds) override { return run(text); }
    ProcessResult run(const std::string& text) override {
        if (runs_.fetch_add(1) >= from_) throw ProcessError("cannot create a pipe: Too many open files");
        ProcessResult r;
        r.out = fake::right_faces(io::read_graph(text));
        return r;
    }
    void restart() override {}
    [[nodiscard]] std::size_t starts() const override { return 0; }

private:
    std::atomic<std::size_t>& runs_;
    std::size_t from_;
};

TEST(DiffEngine, AWorkerThatCannotRunTheCommandEndsTheRunWithItsError) {
    for (const std::size_t jobs : {std::size_t{1}, std::size_t{2}, std::size_t{4}}) {
        for (const std::size_t from : {std::size_t{0}, std::size_t{7}}) {
            SCOPED_TRACE("--jobs " + std::to_string(jobs) + ", failing from run " + std::to_string(from));
            std::atomic<std::size_t> runs{0};
            fake::FakeClock clock;
            DiffOptions o;
            o.impl = "fake";
            o.cases = 40;
            o.jobs = jobs;
            o.schedule.large_vertices = 0;
            const ImplementationFactory make = [&](const ProcessLimits&) {
                return std::make_unique<StopsStartingAt>(runs, from);
            };
            try {
                (void)run_diff(o, {}, make, clock);
                ADD_FAILURE() << "run_diff returned";
            } catch (const ProcessError& e) {
                EXPECT_STREQ(e.what(), "cannot create a pipe: Too many open files");
            }
            EXPECT_GT(runs.load(), from);
        }
    }
}

TEST(DiffEngine, OnlyCaseReplaysOneCase) {
    Harness h;
    h.options.only_case = 17;
    const DiffResult r = h.run(right);
    EXPECT_EQ(r.cases_run, 1U);
    EXPECT_EQ(r.first_case, 17U);
    EXPECT_EQ(h.counters.runs, 1U);
}

TEST(DiffEngine, TheJsonReportIsValidWhateverTheImplementationPrinted) {
    Harness h;
    const DiffResult r = h.run(
        [](const Call& run) { return run.graph.edges.size() >= 2 ? fake::answer("\xff\xfe{\"faces\": \x01") : right(run); });
    ASSERT_EQ(r.failures.size(), 1U);
    const std::string json = report_json(h.options, r);
    io::JsonReader reader(json);
    reader.skip_value();
    reader.end_document();  // throws on invalid JSON or invalid UTF-8 in a string
    // Stray bytes become U+FFFD in the JSON, and are escaped in the text
    // that JUnit carries: neither file holds a byte that is not UTF-8.
    EXPECT_NE(json.find("\"stdout\": \"\xEF\xBF\xBD\xEF\xBF\xBD{"), std::string::npos) << json;
    const std::string junit = report_junit(h.options, r);
    EXPECT_EQ(junit.find('\xff'), std::string::npos);
    EXPECT_NE(junit.find("\\xFF\\xFE{"), std::string::npos);
}

Reply skip(std::string reason) { return fake::answer("{\"skip\": \"" + reason + "\"}"); }

TEST(DiffEngine, ASkipIsCountedByReasonAndIsNeitherAFailureNorAPass) {
    Harness h;
    const DiffResult some = h.run([](const Call& c) { return c.graph.vertices.size() % 2 == 1 ? skip("odd") : right(c); });
    EXPECT_TRUE(some.failures.empty());
    EXPECT_GT(some.skipped_by_impl, 0U);
    ASSERT_EQ(some.skip_reasons.size(), 1U);
    EXPECT_EQ(some.skip_reasons[0].first, "odd");
    EXPECT_EQ(some.checked() + some.skipped_by_impl + some.skipped, some.cases_run);
    EXPECT_TRUE(run_passes(some));
    Harness all;
    const DiffResult none = all.run([](const Call&) { return skip("not implemented"); });
    EXPECT_TRUE(none.failures.empty());
    EXPECT_EQ(none.checked(), 0U);
    EXPECT_FALSE(run_passes(none));  // a run that checks nothing is no pass
    EXPECT_NE(format_report(all.options, none).find("no case was checked"), std::string::npos);
}

TEST(DiffEngine, ARefusalIsOneFailureWhateverTheNumbersInItsMessage) {
    Harness h;
    h.options.keep_going = true;
    h.options.cases = 150;
    const DiffResult r = h.run([](const Call& c) {
        for (std::size_t v = 0; v < c.graph.vertices.size(); ++v) {
            if (degree(c.graph, v) == 0) {
                return fake::answer("{\"refused\": \"vertex " + std::to_string(v) + " at (" +
                                    std::to_string(c.graph.vertices[v].x) + ", 7) is isolated\"}");
            }
        }
        return right(c);
    });
    ASSERT_EQ(r.failures.size(), 1U);
    const Failure& f = r.failures[0];
    EXPECT_EQ(f.example.outcome.kind, FailureKind::Refused);
    EXPECT_EQ(f.signature, "refused: vertex # at (#, #) is isolated||1v0e");
    EXPECT_GT(f.classes.size(), 1U);  // seen in several coordinate classes, one failure
}

TEST(DiffEngine, OneBugInSeveralCoordinateClassesIsOneFailure) {
    Harness h;
    h.options.keep_going = true;
    h.options.cases = 150;
    const DiffResult r = h.run(reverses_cycles);
    ASSERT_EQ(r.failures.size(), 1U);
    EXPECT_GT(r.failures[0].classes.size(), 1U);
    EXPECT_GT(r.failures[0].keys.size(), 1U);
}

TEST(DiffEngine, ASlowButRightCaseIsAPerformanceNoteNotAHang) {
    Harness h;
    h.options.limits.timeout = milliseconds(1000);
    h.options.schedule.large_vertices = 600;
    h.options.cases = 50;  // case 49 is large
    const DiffResult r = h.run([](const Call& c) {
        Reply reply = right(c);
        reply.cost = milliseconds(2 * static_cast<long>(c.graph.vertices.size() + c.graph.edges.size()));
        return reply;
    });
    EXPECT_TRUE(r.failures.empty());
    ASSERT_EQ(r.slow_count, 1U);
    EXPECT_EQ(r.slow[0].number, 49U);
    EXPECT_GT(r.slow[0].took, milliseconds(1000));
    EXPECT_GE(r.slow[0].limit, r.slow[0].took);
}

TEST(DiffEngine, TimeBoundsShrinkingToo) {
    Harness h;
    h.options.cases.reset();
    h.options.time = milliseconds(3000);
    h.options.keep_going = true;
    const DiffResult r = h.run([](const Call& c) {
        Reply reply = reverses_cycles(c);
        reply.cost = milliseconds(100);
        return reply;
    });
    ASSERT_FALSE(r.failures.empty());
    EXPECT_LE(r.elapsed, milliseconds(3000 + 100));  // at most one run past the deadline
}

TEST(DiffEngine, ShrinkingKeepsTheClassNotTheFirstDifference) {
    // The first case fails with one kind of difference, smaller graphs with
    // another: the counterexample is the smallest wrong answer.
    Harness h;
    const DiffResult r = h.run([](const Call& c) {
        if (c.graph.edges.size() < 3) return right(c);
        if (c.graph.edges.size() >= 6) return fake::answer("{\"faces\": []}");  // missing cycles
        return reverses_cycles(c);                                              // reversed cycles
    });
    ASSERT_EQ(r.failures.size(), 1U);
    EXPECT_EQ(r.failures[0].example.graph.edges.size(), 3U);
    EXPECT_TRUE(r.failures[0].example.minimal);
}

}  // namespace
}  // namespace dcel::diff
