// Checking a C++ DCEL implementation against the reference inside its own
// tests: GoogleTest assertions and RapidCheck properties over dcel::gen's
// graphs (graph_cases.hpp).
//
// Header-only, so the core library needs neither GoogleTest nor RapidCheck.
// Link the CMake target dcel::testing (the library and dcel::gen) and
// your own GTest::gtest and rapidcheck; RC_GTEST_PROP needs
// <rapidcheck/gtest.h> besides this header.
//
//   EXPECT_TRUE(dcel::testing::agrees_with_reference(graph, my_faces(graph)));
//   EXPECT_TRUE(dcel::testing::faces_solver_agrees(my_faces));   // runs RapidCheck
//   RC_GTEST_PROP(Mine, agrees, ()) { dcel::testing::rc_assert_faces_agree(my_faces); }
//
// Strong by default: the graphs are targeted from the first case on
// (near-degenerate coordinates, holes inside holes, isolated vertices, large
// graphs, magnitudes near 2^-700 and 2^700; GraphCaseOptions::targeted), so
// RapidCheck's default 100 cases catch a textbook atan2 solver, a
// counterclockwise next, a hole in the wrong face, a solver that fails on
// isolated vertices and solvers that snap tiny or clamp huge coordinates on
// every seed tried
// (properties/test_check_testing_seeds.cpp runs seeds 1 to 20).
//
// On failure the message holds the (shrunk) graph as one line of JSON, which
// pastes into `dcel check - answer.json` or `dcel render -`, the report, first
// difference first, and the seed that replays the run.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <sstream>
#include <string>

#include "dcel/build.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/dump.hpp"
#include "dcel/error.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/testing/graph_cases.hpp"

namespace dcel::testing {

// The answer types and the comparison are dcel::check's; the helpers here
// run it on the graphs of graph_cases.hpp.
using check::compare_dump;
using check::compare_faces;
using check::FacesAnswer;
using check::Report;
using check::report_text;

using FacesSolver = std::function<FacesAnswer(const PlanarGraph&)>;
using DumpSolver = std::function<DcelDump(const PlanarGraph&)>;

// How faces_solver_agrees and dump_solver_agrees run RapidCheck. An unset
// field takes RapidCheck's configuration (the RC_PARAMS environment
// variable: seed=, max_success=, max_size=), and RapidCheck's defaults when
// RC_PARAMS does not set it: a random seed, 100 cases, max_size 100.
struct CheckOptions {
    std::optional<std::uint64_t> seed = std::nullopt;
    std::optional<int> cases = std::nullopt;     // successful cases needed to pass
    std::optional<int> max_size = std::nullopt;  // the size of the last case (the graph size follows it)
    GraphCaseOptions graphs = {.families = {}, .vertices_per_size = 3, .targeted = true};
};

namespace testing_detail {

inline std::string describe(const PlanarGraph& graph, const Report& report) {
    return "graph: " + io::write_graph(graph) + check::report_text(report);
}

// Compares, or says why the reference refused the graph (then it is not a
// planar straight-line graph, and no answer can be right or wrong).
template <class Answer, class Compare>
::testing::AssertionResult agrees(const PlanarGraph& graph, const Answer& answer, Compare compare) {
    try {
        const Report report = compare(build(graph), answer);
        if (report.agrees()) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << describe(graph, report);
    } catch (const InvalidInput& e) {
        return ::testing::AssertionFailure() << "the reference refuses the graph: " << e.what();
    }
}

// The property: the solver's answer for a generated graph agrees. A solver
// that throws fails the case like a wrong answer.
template <class Solver, class Compare>
void rc_assert_agrees(const Solver& solver, Compare compare, const GraphCaseOptions& graphs) {
    const GraphCase c = *graph_cases(graphs);
    const Dcel reference = build(c.graph);
    std::string failure;
    try {
        const Report report = compare(reference, solver(c.graph));
        if (!report.agrees()) failure = describe(c.graph, report);
    } catch (const std::exception& e) {
        failure = "graph: " + io::write_graph(c.graph) + "the solver threw: " + e.what() + "\n";
    }
    if (!failure.empty()) RC_FAIL(failure);
}

inline rc::detail::TestParams params(const CheckOptions& options) {
    rc::detail::TestParams p = rc::detail::configuration().testParams;
    if (options.seed) p.seed = *options.seed;
    if (options.cases) p.maxSuccess = *options.cases;
    if (options.max_size) p.maxSize = *options.max_size;
    return p;
}

template <class Solver, class Compare>
::testing::AssertionResult solver_agrees(const Solver& solver, Compare compare, const CheckOptions& options) {
    const rc::detail::TestParams p = params(options);
    rc::detail::TestMetadata metadata;
    metadata.id = metadata.description = "agrees with the reference DCEL on graphs from dcel::gen";
    const rc::detail::TestResult result = rc::detail::checkProperty(
        rc::detail::toProperty([&] { rc_assert_agrees(solver, compare, options.graphs); }), metadata, p);
    if (result.template is<rc::detail::SuccessResult>()) return ::testing::AssertionSuccess();
    std::ostringstream os;
    if (result.template is<rc::detail::FailureResult>()) {
        const auto& failure = result.template get<rc::detail::FailureResult>();
        // RapidCheck's description starts with where RC_FAIL stands (this
        // header), which tells the reader nothing.
        const std::string& text = failure.description;
        const std::size_t ours = text.find("graph: ");
        os << "failed after " << failure.numSuccess << " agreeing cases; replay with CheckOptions{.seed = " << p.seed
           << "} or RC_PARAMS=\"seed=" << p.seed << " max_success=" << p.maxSuccess << " max_size=" << p.maxSize
           << "\"; smallest failing case found:\n"
           << (ours == std::string::npos ? text : text.substr(ours));
    } else {
        rc::detail::printResultMessage(result, os);
    }
    return ::testing::AssertionFailure() << os.str();
}

inline Report faces(const Dcel& d, const FacesAnswer& a) { return compare_faces(d, a); }
inline Report dump(const Dcel& d, const DcelDump& a) { return compare_dump(d, a); }

}  // namespace testing_detail

// One graph: success, or a failure whose message is the graph and the report.
[[nodiscard]] inline ::testing::AssertionResult agrees_with_reference(const PlanarGraph& graph, const FacesAnswer& answer) {
    return testing_detail::agrees(graph, answer, testing_detail::faces);
}
[[nodiscard]] inline ::testing::AssertionResult agrees_with_reference(const PlanarGraph& graph, const DcelDump& answer) {
    return testing_detail::agrees(graph, answer, testing_detail::dump);
}

// Inside a RapidCheck property (RC_GTEST_PROP): draws one graph and fails
// with the first difference (RC_FAIL), so RapidCheck shrinks the graph and
// prints it. RC_PARAMS sets the seed and the number of cases.
inline void rc_assert_faces_agree(const FacesSolver& solver, const GraphCaseOptions& graphs = CheckOptions{}.graphs) {
    testing_detail::rc_assert_agrees(solver, testing_detail::faces, graphs);
}
inline void rc_assert_dump_agrees(const DumpSolver& solver, const GraphCaseOptions& graphs = CheckOptions{}.graphs) {
    testing_detail::rc_assert_agrees(solver, testing_detail::dump, graphs);
}

// Runs the property itself: success, or a failure holding the shrunk graph,
// its report and the seed.
[[nodiscard]] inline ::testing::AssertionResult faces_solver_agrees(const FacesSolver& solver,
                                                                    const CheckOptions& options = {}) {
    return testing_detail::solver_agrees(solver, testing_detail::faces, options);
}
[[nodiscard]] inline ::testing::AssertionResult dump_solver_agrees(const DumpSolver& solver,
                                                                   const CheckOptions& options = {}) {
    return testing_detail::solver_agrees(solver, testing_detail::dump, options);
}

}  // namespace dcel::testing
