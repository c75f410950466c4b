// Checking a C++ DCEL implementation against the reference inside its own
// tests: GoogleTest assertions and a RapidCheck property over dcel::gen.
//
// Header-only, so the core library needs neither GoogleTest nor RapidCheck.
// Link the CMake target dcel::check_testing (the library and dcel::gen) and
// your own GTest::gtest and rapidcheck.
//
//   EXPECT_TRUE(dcel::check::agrees_with_reference(graph, my_faces(graph)));
//   EXPECT_TRUE(dcel::check::faces_solver_agrees(my_faces));   // runs RapidCheck
//   RC_GTEST_PROP(Mine, agrees, ()) { dcel::check::rc_assert_faces_agree(my_faces); }
//
// On failure the message holds the (shrunk) graph as one line of JSON, which
// pastes into `dcel check - answer.json` or `dcel render -`, and the report,
// first difference first.
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cstdint>
#include <exception>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/check/compare.hpp"
#include "dcel/check/report.hpp"
#include "dcel/dump.hpp"
#include "dcel/error.hpp"
#include "dcel/gen/generate.hpp"
#include "dcel/io/graph_json.hpp"

namespace dcel::check {

using FacesSolver = std::function<FacesAnswer(const PlanarGraph&)>;
using DumpSolver = std::function<DcelDump(const PlanarGraph&)>;

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

// A graph drawn from dcel::gen: every family, size following RapidCheck's
// size, shrinking only to smaller valid graphs (gen::shrink_candidates).
struct GraphCase {
    gen::Params params;
    PlanarGraph graph;
};

inline void showValue(const GraphCase& c, std::ostream& os) {
    os << "family " << gen::family_name(c.params.family) << ", seed " << c.params.seed << ": " << io::write_graph(c.graph);
}

inline rc::Gen<GraphCase> graphs() {
    const auto all = gen::all_families();
    const std::vector<gen::Family> families(all.begin(), all.end());
    const rc::Gen<gen::Params> params = rc::gen::withSize([families](int size) {
        return rc::gen::apply(
            [](gen::Family f, std::uint64_t seed, int n) {
                return gen::Params{f, seed, static_cast<std::size_t>(n)};
            },
            rc::gen::elementOf(families), rc::gen::arbitrary<std::uint64_t>(), rc::gen::inRange(0, size + 4));
    });
    return rc::gen::mapcat(rc::gen::noShrink(params), [](const gen::Params& p) {
        return rc::Gen<GraphCase>([p](const rc::Random&, int) {
            return rc::shrinkable::shrinkRecur(GraphCase{p, gen::generate(p)}, [](const GraphCase& c) {
                return rc::seq::map(rc::seq::fromContainer(gen::shrink_candidates(c.graph)),
                                    [params = c.params](PlanarGraph g) {
                                        return GraphCase{params, std::move(g)};
                                    });
            });
        });
    });
}

// The property: the solver's answer for a generated graph agrees. `last`
// keeps the message of the latest failure, which after shrinking is the
// minimal one.
template <class Solver, class Compare>
void rc_assert_agrees(const Solver& solver, Compare compare, std::string* last) {
    const GraphCase c = *graphs();
    const Dcel reference = build(c.graph);
    std::string failure;
    try {
        const Report report = compare(reference, solver(c.graph));
        if (!report.agrees()) failure = describe(c.graph, report);
    } catch (const std::exception& e) {
        failure = "graph: " + io::write_graph(c.graph) + "the solver threw: " + e.what() + "\n";
    }
    if (failure.empty()) return;
    if (last != nullptr) *last = failure;
    RC_FAIL(failure);
}

template <class Solver, class Compare>
::testing::AssertionResult solver_agrees(const Solver& solver, Compare compare) {
    std::string last;
    if (rc::check("agrees with the reference DCEL on graphs from dcel::gen",
                  [&] { rc_assert_agrees(solver, compare, &last); })) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "smallest failing case found:\n" << last;
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

// Inside a RapidCheck property: draws one graph and fails with the first
// difference (RC_FAIL), so RapidCheck shrinks the graph and prints it.
inline void rc_assert_faces_agree(const FacesSolver& solver) {
    testing_detail::rc_assert_agrees(solver, testing_detail::faces, nullptr);
}
inline void rc_assert_dump_agrees(const DumpSolver& solver) {
    testing_detail::rc_assert_agrees(solver, testing_detail::dump, nullptr);
}

// Runs the property with rc::check (RC_PARAMS applies: seed, max_success,
// ...): success, or a failure holding the shrunk graph and its report.
[[nodiscard]] inline ::testing::AssertionResult faces_solver_agrees(const FacesSolver& solver) {
    return testing_detail::solver_agrees(solver, testing_detail::faces);
}
[[nodiscard]] inline ::testing::AssertionResult dump_solver_agrees(const DumpSolver& solver) {
    return testing_detail::solver_agrees(solver, testing_detail::dump);
}

}  // namespace dcel::check
