// remove_edge and remove_isolated_vertex, including the swap-with-last
// renumbering they report. Expected cycles are derived by hand; every result
// is also checked against validate() and a rebuild from scratch.
#include <gtest/gtest.h>

#include "dcel/edit.hpp"
#include "dcel/error.hpp"
#include "support/edit_helpers.hpp"
#include "support/face_shapes.hpp"

namespace dcel {
namespace {

using test_support::countries;
using test_support::face_shapes;
using test_support::graph;
using test_support::half_edge;
using test_support::kEast;
using test_support::kEnclave;
using test_support::kWest;
using test_support::sorted_shapes;

TEST(RemoveEdge, MergesTwoCountriesIntoTheSmallerId) {
    // Removing the border 1-4 (e6) merges East (f2) into West (f1). The last
    // face, the Enclave (f3), moves into id 2; the last edge, e10 = 9 -> 6,
    // moves into id 6 keeping its direction.
    Dcel d = build(countries());
    const Change c = remove_edge(d, EdgeId(6));
    EXPECT_SOUND(d);
    EXPECT_EQ(c.faces.removed, kEast);
    EXPECT_EQ(c.faces.merged_into, kWest);
    EXPECT_EQ(c.faces.moved, kEnclave);
    EXPECT_EQ(c.edges.removed, EdgeId(6));
    EXPECT_EQ(c.edges.moved, EdgeId(10));
    EXPECT_EQ(d.num_faces(), 3U);
    EXPECT_EQ(d.origin(HalfEdgeId(12)), VertexId(9));
    EXPECT_EQ(d.target(HalfEdgeId(12)), VertexId(6));
    EXPECT_EQ(d.face(half_edge(d, 6, 7)), FaceId(2));  // the Enclave, renumbered
    EXPECT_EQ(face_shapes(d), sorted_shapes({
                                  {{}, {{0, 5, 4, 3, 2, 1}}, {}},
                                  {{0, 1, 2, 3, 4, 5}, {{6, 9, 8, 7}}, {10}},
                                  {{6, 7, 8, 9}, {}, {}},
                              }));
}

TEST(RemoveEdge, OpeningAnEnclaveTurnsItsBoundaryIntoATreeHole) {
    // Removing 6-7 opens the Enclave (f3, the last face) into East (f2): its
    // boundary becomes the path 7-8-9-6, a hole of East walked out and back.
    Dcel d = build(countries());
    const Change c = remove_edge(d, EdgeId(7));
    EXPECT_SOUND(d);
    EXPECT_EQ(c.faces.removed, kEnclave);
    EXPECT_EQ(c.faces.merged_into, kEast);
    EXPECT_TRUE(c.faces.moved.is_null());
    EXPECT_EQ(face_shapes(d), sorted_shapes({
                                  {{}, {{0, 5, 4, 3, 2, 1}}, {}},
                                  {{0, 1, 4, 5}, {}, {10}},
                                  {{1, 2, 3, 4}, {{6, 9, 8, 7, 8, 9}}, {}},
                              }));
}

TEST(RemoveEdge, MergingIntoTheUnboundedFace) {
    Dcel d = build(graph({{0, 0}, {4, 0}, {0, 4}}, {{0, 1}, {1, 2}, {2, 0}}));
    const Change c = remove_edge(d, EdgeId(1));
    EXPECT_SOUND(d);
    EXPECT_EQ(c.faces.merged_into, Dcel::kUnboundedFace);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 1, 0, 2}}, {}}}));
}

TEST(RemoveEdge, ABridgeFromTheOuterBoundaryLeavesAHoleInTheSameFace) {
    // Square 0-3 with a triangle 4 5 6 inside, tied to corner 0 by the bridge
    // 0-4 (e7). Without the bridge the triangle is a hole of the square's face.
    Dcel d = build(graph({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {5, 6}},
                         {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 4}, {0, 4}}));
    const FaceId square = d.face(half_edge(d, 0, 1));
    (void)remove_edge(d, EdgeId(7));
    EXPECT_SOUND(d);
    EXPECT_EQ(d.inner(square).size(), 1U);
    EXPECT_EQ(face_shapes(d), sorted_shapes({
                                  {{}, {{0, 3, 2, 1}}, {}},
                                  {{0, 1, 2, 3}, {{4, 6, 5}}, {}},
                                  {{4, 5, 6}, {}, {}},
                              }));
}

TEST(RemoveEdge, ABridgeToATreeLeavesATreeHole) {
    // The part that breaks off has zero area (a path 4-5): it must become the
    // hole, not the outer boundary.
    Dcel d = build(
        graph({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 5}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {4, 5}}));
    (void)remove_edge(d, EdgeId(4));
    EXPECT_SOUND(d);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2, 3}, {{4, 5}}, {}}}));
}

TEST(RemoveEdge, ABridgeBetweenTwoIslandsLeavesTwoHoles) {
    // Two triangles joined by the bridge 2-3 in the unbounded face.
    Dcel d = build(
        graph({{0, 0}, {2, 0}, {1, 2}, {5, 2}, {4, 0}, {6, 0}}, {{0, 1}, {1, 2}, {2, 0}, {2, 3}, {3, 4}, {4, 5}, {5, 3}}));
    (void)remove_edge(d, EdgeId(3));
    EXPECT_SOUND(d);
    EXPECT_EQ(d.inner(Dcel::kUnboundedFace).size(), 2U);
    EXPECT_EQ(face_shapes(d), sorted_shapes({
                                  {{}, {{0, 2, 1}, {3, 5, 4}}, {}},
                                  {{0, 1, 2}, {}, {}},
                                  {{3, 4, 5}, {}, {}},
                              }));
}

TEST(RemoveEdge, DanglingAndLoneEdgesLeaveIsolatedVertices) {
    // Square 0-3 with a dangling edge 0-4 inside, and a lone edge 5-6 outside.
    Dcel d = build(graph({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {10, 10}, {11, 10}},
                         {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {5, 6}}));
    (void)remove_edge(d, EdgeId(4));  // the dangling 0-4: 4 becomes isolated in the square
    EXPECT_SOUND(d);
    EXPECT_EQ(d.isolated(FaceId(1)), std::vector<VertexId>{VertexId(4)});
    const Change c = remove_edge(d, EdgeId(4));  // now the lone 5-6, moved into id 4
    EXPECT_SOUND(d);
    EXPECT_TRUE(c.edges.moved.is_null());
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 3, 2, 1}}, {5, 6}}, {{0, 1, 2, 3}, {}, {4}}}));
    // Take the square apart: a merge, then dangling edges, then a lone edge.
    for (int i = 0; i < 4; ++i) {
        (void)remove_edge(d, EdgeId(0));
        EXPECT_SOUND(d);
    }
    EXPECT_EQ(d.num_faces(), 1U);
    EXPECT_EQ(d.isolated(Dcel::kUnboundedFace).size(), 7U);
    EXPECT_REFUSED_UNCHANGED(d, remove_edge(d, EdgeId(0)), InvalidInput, "there is no edge e0");
}

TEST(RemoveIsolatedVertex, RenumbersTheLastVertex) {
    Dcel d = build(countries());
    (void)add_vertex(d, {6, 3});  // v11 in the Enclave
    const Change c = remove_isolated_vertex(d, VertexId(10));
    EXPECT_SOUND(d);
    EXPECT_EQ(c.vertices.removed, VertexId(10));
    EXPECT_EQ(c.vertices.moved, VertexId(11));
    EXPECT_TRUE(d.isolated(kWest).empty());
    EXPECT_EQ(d.isolated(kEnclave), std::vector<VertexId>{VertexId(10)});
    EXPECT_EQ(d.point(VertexId(10)).x, 6);
    EXPECT_REFUSED_UNCHANGED(d, remove_isolated_vertex(d, VertexId(4)), TopologyError, "has 3 edges");
}

TEST(RemoveIsolatedVertex, MovesAVertexWithEdges) {
    // v0 isolated; the last vertex, 3, is a triangle corner: its half-edges
    // must follow it into id 0.
    Dcel d = build(graph({{9, 9}, {0, 0}, {4, 0}, {0, 4}}, {{1, 2}, {2, 3}, {3, 1}}));
    (void)remove_isolated_vertex(d, VertexId(0));
    EXPECT_SOUND(d);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{1, 0, 2}}, {}}, {{0, 1, 2}, {}, {}}}));
}

}  // namespace
}  // namespace dcel
