// dcel/testing/check_testing.hpp as a user would use it, on in-test solvers
// (support/planted_solvers.hpp): the helpers must pass the right one and fail
// the one with a planted bug, with a shrunk graph, a report and the seed.
// test_check_testing_seeds.cpp runs every planted bug on seeds 1 to 20.
#include "dcel/testing/check_testing.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "support/check_helpers.hpp"
#include "support/planted_solvers.hpp"

namespace {

using dcel::Index;
using dcel::PlanarGraph;
using dcel::check::FacesAnswer;
using dcel::props::planted::ccw_faces;
using dcel::props::planted::right_faces;

FacesAnswer buggy_faces(const PlanarGraph& g) { return ccw_faces(g); }

PlanarGraph triangle_with_tail() {
    PlanarGraph g;
    g.vertices = {{0, 0}, {4, 0}, {0, 4}, {-3, -1}};
    for (const auto& [u, v] : std::vector<std::pair<Index, Index>>{{0, 1}, {1, 2}, {2, 0}, {0, 3}}) {
        g.edges.push_back({dcel::VertexId(u), dcel::VertexId(v)});
    }
    return g;
}

TEST(CheckTesting, OneGraph) {
    const PlanarGraph g = triangle_with_tail();
    EXPECT_TRUE(dcel::testing::agrees_with_reference(g, right_faces(g)));
    const ::testing::AssertionResult wrong = dcel::testing::agrees_with_reference(g, buggy_faces(g));
    ASSERT_FALSE(wrong);
    const std::string message = wrong.message();
    EXPECT_NE(message.find("graph: {\"vertices\": [[0, 0], [4, 0]"), std::string::npos) << message;
    // The counterclockwise neighbour walks every cycle backwards.
    EXPECT_NE(message.find("reversed-cycle: answer cycle"), std::string::npos) << message;

    EXPECT_TRUE(dcel::testing::agrees_with_reference(g, dcel::to_dump(dcel::build(g))));
    dcel::DcelDump dump = dcel::to_dump(dcel::build(g));
    dump.vertices[3] = {-3, -2};
    EXPECT_FALSE(dcel::testing::agrees_with_reference(g, dump));

    PlanarGraph crossing = g;
    crossing.edges.push_back({dcel::VertexId(1), dcel::VertexId(3)});
    crossing.edges.push_back({dcel::VertexId(2), dcel::VertexId(3)});
    crossing.vertices[3] = {3, 3};  // 0-3 now crosses 1-2 at (2, 2)
    const auto refused = dcel::testing::agrees_with_reference(crossing, FacesAnswer{});
    EXPECT_FALSE(refused);
    EXPECT_NE(std::string(refused.message()).find("the reference refuses the graph"), std::string::npos);
}

TEST(CheckTesting, RightSolverAgreesOnGeneratedGraphs) {
    EXPECT_TRUE(dcel::testing::faces_solver_agrees(right_faces));
    EXPECT_TRUE(dcel::testing::dump_solver_agrees(
        [](const PlanarGraph& g) { return dcel::test_support::renumbered(dcel::to_dump(dcel::build(g)), 5); }));
}

TEST(CheckTesting, BuggySolverIsCaughtAndShrunk) {
    const ::testing::AssertionResult result = dcel::testing::faces_solver_agrees(buggy_faces);
    ASSERT_FALSE(result);
    const std::string message = result.message();
    std::cerr << message;
    EXPECT_NE(message.find("smallest failing case found:\ngraph: {\"vertices\""), std::string::npos);
    EXPECT_NE(message.find("replay with CheckOptions{.seed = "), std::string::npos) << message;
    // The counterclockwise neighbour differs from the clockwise one only at a
    // vertex of degree 3 or more: a star of 3 edges (4 vertices) is as small as
    // a counterexample gets, and shrinking must get close.
    const std::size_t vertices_at = message.find("\"vertices\": [");
    const std::size_t edges_at = message.find("\"edges\": [");
    ASSERT_NE(edges_at, std::string::npos);
    const std::string points = message.substr(vertices_at, edges_at - vertices_at);
    EXPECT_LE(std::count(points.begin(), points.end(), '['), 1 + 6) << points;
}

RC_GTEST_PROP(CheckTesting, prop_right_solver_in_a_property, ()) { dcel::testing::rc_assert_faces_agree(right_faces); }

}  // namespace
