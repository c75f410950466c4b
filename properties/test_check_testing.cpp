// dcel/check/testing.hpp as a user would use it: two small in-test DCEL
// face solvers, one right (exact angular order, clockwise neighbour) and one
// with a planted bug (the counterclockwise neighbour). The helpers must pass
// the first and fail the second, with a shrunk graph and a report.
#include "dcel/testing/check_testing.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "dcel/geometry/predicates.hpp"
#include "support/check_helpers.hpp"

namespace {

using dcel::Index;
using dcel::PlanarGraph;
using dcel::check::FacesAnswer;

// Faces from the next rule: next(u->v) is the half-edge leaving v next to
// v->u in clockwise order (or counterclockwise, with the bug).
FacesAnswer faces_by_rule(const PlanarGraph& g, bool clockwise) {
    const auto halves = static_cast<Index>(2 * g.edges.size());
    auto origin = [&](Index h) { return (h & 1U) == 0 ? g.edges[h >> 1U].u.index() : g.edges[h >> 1U].v.index(); };
    std::vector<std::vector<Index>> around(g.vertices.size());
    for (Index h = 0; h < halves; ++h) around[origin(h)].push_back(h);
    std::vector<Index> position(halves);
    for (std::size_t v = 0; v < around.size(); ++v) {
        const dcel::Point c = g.vertices[v];
        std::sort(around[v].begin(), around[v].end(), [&](Index a, Index b) {  // counterclockwise from east
            return dcel::compare_angle(c, g.vertices[origin(a ^ 1U)], g.vertices[origin(b ^ 1U)]) == dcel::Sign::Negative;
        });
        for (std::size_t i = 0; i < around[v].size(); ++i) position[around[v][i]] = static_cast<Index>(i);
    }
    auto next = [&](Index h) {
        const auto& ring = around[origin(h ^ 1U)];
        const std::size_t i = position[h ^ 1U];
        return ring[clockwise ? (i + ring.size() - 1) % ring.size() : (i + 1) % ring.size()];
    };
    FacesAnswer out;
    std::vector<char> seen(halves, 0);
    for (Index h = 0; h < halves; ++h) {
        if (seen[h] != 0) continue;
        auto& cycle = out.emplace_back();
        for (Index x = h; seen[x] == 0; x = next(x)) {
            seen[x] = 1;
            cycle.push_back(origin(x));
        }
    }
    return out;
}

FacesAnswer right_faces(const PlanarGraph& g) { return faces_by_rule(g, true); }
FacesAnswer buggy_faces(const PlanarGraph& g) { return faces_by_rule(g, false); }

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
    EXPECT_TRUE(dcel::check::agrees_with_reference(g, right_faces(g)));
    const ::testing::AssertionResult wrong = dcel::check::agrees_with_reference(g, buggy_faces(g));
    ASSERT_FALSE(wrong);
    const std::string message = wrong.message();
    EXPECT_NE(message.find("graph: {\"vertices\": [[0, 0], [4, 0]"), std::string::npos) << message;
    // The counterclockwise neighbour walks every cycle backwards.
    EXPECT_NE(message.find("reversed-cycle: answer cycle"), std::string::npos) << message;

    EXPECT_TRUE(dcel::check::agrees_with_reference(g, dcel::to_dump(dcel::build(g))));
    dcel::DcelDump dump = dcel::to_dump(dcel::build(g));
    dump.vertices[3] = {-3, -2};
    EXPECT_FALSE(dcel::check::agrees_with_reference(g, dump));

    PlanarGraph crossing = g;
    crossing.edges.push_back({dcel::VertexId(1), dcel::VertexId(3)});
    crossing.edges.push_back({dcel::VertexId(2), dcel::VertexId(3)});
    crossing.vertices[3] = {3, 3};  // 0-3 now crosses 1-2 at (2, 2)
    const auto refused = dcel::check::agrees_with_reference(crossing, FacesAnswer{});
    EXPECT_FALSE(refused);
    EXPECT_NE(std::string(refused.message()).find("the reference refuses the graph"), std::string::npos);
}

TEST(CheckTesting, RightSolverAgreesOnGeneratedGraphs) {
    EXPECT_TRUE(dcel::check::faces_solver_agrees(right_faces));
    EXPECT_TRUE(dcel::check::dump_solver_agrees(
        [](const PlanarGraph& g) { return dcel::testing::renumbered(dcel::to_dump(dcel::build(g)), 5); }));
}

TEST(CheckTesting, BuggySolverIsCaughtAndShrunk) {
    const ::testing::AssertionResult result = dcel::check::faces_solver_agrees(buggy_faces);
    ASSERT_FALSE(result);
    const std::string message = result.message();
    std::cerr << message;
    EXPECT_NE(message.find("smallest failing case found:\ngraph: {\"vertices\""), std::string::npos);
    // The counterclockwise neighbour differs from the clockwise one only at a
    // vertex of degree 3 or more: a star of 3 edges (4 vertices) is as small as
    // a counterexample gets, and shrinking must get close.
    const std::size_t vertices_at = message.find("\"vertices\": [");
    const std::size_t edges_at = message.find("\"edges\": [");
    ASSERT_NE(edges_at, std::string::npos);
    const std::string points = message.substr(vertices_at, edges_at - vertices_at);
    EXPECT_LE(std::count(points.begin(), points.end(), '['), 1 + 6) << points;
}

RC_GTEST_PROP(CheckTesting, prop_right_solver_in_a_property, ()) { dcel::check::rc_assert_faces_agree(right_faces); }

}  // namespace
