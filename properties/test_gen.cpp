// Unit tests of dcel::gen: family names, transforms refuse exactly what would
// round, planted defects are rejected, and shrinking reaches hand-derived
// minimal graphs. The families themselves: test_gen_families.cpp.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/gen/brute_force.hpp"
#include "dcel/gen/generate.hpp"
#include "oracles/brute_force.hpp"

namespace dcel::gen {
namespace {

PlanarGraph square() {
    return {
        {{0, 0}, {4, 0}, {4, 4}, {0, 4}},
        {{VertexId(0), VertexId(1)}, {VertexId(1), VertexId(2)}, {VertexId(2), VertexId(3)}, {VertexId(3), VertexId(0)}}};
}

TEST(Generate, FamiliesHaveTheirNames) {
    EXPECT_EQ(all_families().size(), 10u);
    for (const Family f : all_families()) EXPECT_EQ(family_from_name(family_name(f)), f);
    EXPECT_EQ(family_name(Family::GridWithHoles), "grid-with-holes");
    EXPECT_EQ(family_from_name("no-such-family"), std::nullopt);
}

TEST(Transform, RotationAndMirrorAreExact) {
    const PlanarGraph g{{{1, 2}, {-3, 0.5}}, {{VertexId(0), VertexId(1)}}};
    const PlanarGraph r = *apply(g, Transform::Rotate90);
    EXPECT_EQ(r.vertices[0], (Point{-2, 1}));
    EXPECT_EQ(r.vertices[1], (Point{-0.5, -3}));
    const PlanarGraph m = *apply(g, Transform::Mirror);
    EXPECT_EQ(m.vertices[0], (Point{-1, 2}));
    EXPECT_EQ(r.edges, g.edges);
}

TEST(Transform, RefusesWhatWouldRound) {
    const PlanarGraph half{{{0.5, 0}}, {}};
    EXPECT_EQ(apply(half, Transform::Translate, std::int64_t{1} << 53), std::nullopt);  // 2^53 + 0.5 rounds
    EXPECT_EQ(apply(half, Transform::Translate, 3)->vertices[0], (Point{3.5, -3}));
    const PlanarGraph one{{{1, 0}}, {}};
    EXPECT_EQ(apply(one, Transform::ScalePow2, -1074)->vertices[0].x, 0x1p-1074);
    EXPECT_EQ(apply(one, Transform::ScalePow2, -1075), std::nullopt);  // below the smallest subnormal
    const PlanarGraph three{{{0x3p-1074, 0}}, {}};
    EXPECT_EQ(apply(three, Transform::ScalePow2, -1), std::nullopt);  // 1.5 * 2^-1074 is not a double
    const PlanarGraph huge{{{DBL_MAX, 0}}, {}};
    EXPECT_EQ(apply(huge, Transform::ScalePow2, 1), std::nullopt);  // overflow
    EXPECT_EQ(apply(huge, Transform::ScalePow2, -1)->vertices[0].x, DBL_MAX / 2);
}

TEST(Plant, EachDefectIsRejectedWithItsKind) {
    const std::pair<Defect, InputErrorKind> cases[] = {{Defect::Crossing, InputErrorKind::Crossing},
                                                       {Defect::Touch, InputErrorKind::VertexOnEdge},
                                                       {Defect::Overlap, InputErrorKind::Overlap}};
    for (const auto& [defect, kind] : cases) {
        for (std::uint64_t seed = 0; seed < 10; ++seed) {
            const std::optional<PlanarGraph> bad = plant(square(), defect, seed);
            ASSERT_TRUE(bad.has_value());
            EXPECT_FALSE(oracle::find_defects(*bad).empty());
            try {
                (void)build(*bad);
                ADD_FAILURE() << "accepted a planted defect";
            } catch (const InvalidInput& e) {
                EXPECT_EQ(e.kind(), kind) << e.what();
            }
        }
    }
    EXPECT_EQ(plant(PlanarGraph{{{0, 0}}, {}}, Defect::Crossing, 1), std::nullopt);  // no edge to cross
}

TEST(Plant, OverlapStaysOnTheLineWithNearDegenerateCoordinates) {
    // Regression (found by Crossings.prop_planted_defect_...): here the point
    // past the end of edge 1 rounds off its line, so the attempt made a touch
    // (vertex-on-edge) where an overlap was asked for.
    const PlanarGraph g{{{1.2791052533825409e+29, 6897321058801102},
                         {1.2791052533825414e+29, 0},
                         {1.279105253382541e+29, 6897321058801113},
                         {1.2791052533825404e+29, 6897321058801111},
                         {1.2791052533825407e+29, 6897321058801112},
                         {1.2791052533825398e+29, 6897321058801120}},
                        {{VertexId(5), VertexId(3)},
                         {VertexId(0), VertexId(3)},
                         {VertexId(4), VertexId(3)},
                         {VertexId(4), VertexId(2)},
                         {VertexId(2), VertexId(1)}}};
    const std::optional<PlanarGraph> bad = plant(g, Defect::Overlap, 401);
    ASSERT_TRUE(bad.has_value());
    try {
        (void)build(*bad);
        ADD_FAILURE() << "accepted a planted overlap";
    } catch (const InvalidInput& e) {
        EXPECT_EQ(e.kind(), InputErrorKind::Overlap) << e.what();
    }
}

TEST(Shrink, ReachesTheSmallestGraphWithTheProperty) {
    const PlanarGraph big = generate({Family::Triangulation, 7, 60});
    ASSERT_GT(build(big).num_faces(), 1u);
    // The smallest graph with a bounded face is a triangle.
    const PlanarGraph t = shrink(big, [](const PlanarGraph& g) { return build(g).num_faces() > 1; });
    EXPECT_EQ(t.vertices.size(), 3u);
    EXPECT_EQ(t.edges.size(), 3u);
    // The smallest graph with an edge is one edge; snapping brings it to
    // coordinates 0 and 1 (ranks), or halves them towards 0.
    const PlanarGraph e = shrink(big, [](const PlanarGraph& g) { return !g.edges.empty(); });
    EXPECT_EQ(e.vertices.size(), 2u);
    EXPECT_EQ(e.edges.size(), 1u);
    for (const Point& p : e.vertices) EXPECT_LE(std::fabs(p.x) + std::fabs(p.y), 1.0);
}

TEST(Shrink, CandidatesOfAValidGraphAreValid) {
    for (const Family f : all_families()) {
        const PlanarGraph g = generate({f, 3, 30});
        for (const PlanarGraph& c : shrink_candidates(g)) {
            EXPECT_EQ(find_problem(c), std::nullopt) << family_name(f);
            EXPECT_TRUE(oracle::find_defects(c).empty()) << family_name(f);
        }
    }
}

}  // namespace
}  // namespace dcel::gen
