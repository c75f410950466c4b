// Fakes for the diff engine's unit tests: an implementation that answers
// from a C++ function instead of a process, and a clock moved by hand, so
// that the schedule, the judging, the grouping, the shrinking and every
// budget are tested quickly and deterministically, with no process and no
// waiting.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/diff/clock.hpp"
#include "dcel/diff/implementation.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::diff::fake {

using std::chrono::milliseconds;

// Time moves only when told: each fake run advances it by its cost.
class FakeClock : public Clock {
public:
    [[nodiscard]] time_point now() const override { return time_point(now_); }
    [[nodiscard]] milliseconds cpu() const override { return milliseconds(0); }
    void advance(milliseconds d) { now_ += d; }

private:
    std::chrono::steady_clock::duration now_{std::chrono::hours(1)};
};

// What a fake implementation sees of one run: the graph, the exact text,
// and (a --stream's state) the texts it was given since its last restart.
struct Call {
    const PlanarGraph& graph;
    const std::string& text;
    const std::vector<std::string>& before;
};

// One run's reply and how much fake time it takes.
struct Reply {
    ProcessResult result;
    milliseconds cost{1};
};
using Behaviour = std::function<Reply(const Call&)>;

inline Reply answer(std::string out, milliseconds cost = milliseconds(1)) {
    ProcessResult r;
    r.out = std::move(out);
    return {std::move(r), cost};
}
inline Reply exited(int status, std::string err = {}) {
    ProcessResult r;
    r.exit_status = status;
    r.err_tail = std::move(err);
    return {std::move(r), milliseconds(1)};
}
inline Reply signalled(int signal) {
    ProcessResult r;
    r.end = ProcessEnd::Signalled;
    r.signal = signal;
    return {std::move(r), milliseconds(1)};
}
// A hang: no reply within the run's timeout, which is what it costs.
inline Reply hangs() {
    ProcessResult r;
    r.end = ProcessEnd::TimedOut;
    return {std::move(r), milliseconds(-1)};
}

// The reference's own faces answer: what a right implementation prints.
inline std::string right_faces(const PlanarGraph& g) { return io::write_faces_of(build(g)); }

struct Counters {
    std::size_t runs = 0;
    std::size_t starts = 0;
};

class FakeImplementation : public Implementation {
public:
    FakeImplementation(Behaviour behaviour, FakeClock& clock, const ProcessLimits& limits, Counters& counters)
        : behaviour_(std::move(behaviour)), clock_(clock), limits_(limits), counters_(counters) {}

    ProcessResult run(const std::string& text) override { return run(text, limits_.timeout); }
    ProcessResult run(const std::string& text, milliseconds timeout) override {
        if (!started_) {
            started_ = true;
            ++counters_.starts;
        }
        ++counters_.runs;
        const PlanarGraph g = io::read_graph(text);
        Reply reply = behaviour_(Call{g, text, seen_});
        // A hang, or a run slower than its timeout: killed at the timeout.
        const bool killed = reply.cost.count() < 0 || reply.cost > timeout;
        if (killed) reply.result = hangs().result;
        clock_.advance(killed ? timeout : reply.cost);
        seen_.push_back(text);
        if (killed || reply.result.end != ProcessEnd::Exited || reply.result.exit_status != 0) restart();
        return std::move(reply.result);
    }
    void restart() override {
        seen_.clear();
        started_ = false;
    }
    [[nodiscard]] std::size_t starts() const override { return counters_.starts; }

private:
    Behaviour behaviour_;
    FakeClock& clock_;
    ProcessLimits limits_;
    Counters& counters_;
    std::vector<std::string> seen_;
    bool started_ = false;
};

// A factory for run_diff: every implementation it makes behaves alike and
// shares the clock and the counters.
inline ImplementationFactory factory(Behaviour behaviour, FakeClock& clock, Counters& counters) {
    return [behaviour = std::move(behaviour), &clock, &counters](const ProcessLimits& limits) {
        return std::make_unique<FakeImplementation>(behaviour, clock, limits, counters);
    };
}

}  // namespace dcel::diff::fake
