// split_edge and its inverse merge_collinear_edges. Expected cycles are
// derived by hand (comments); every result is also checked against validate()
// and a rebuild from scratch (EXPECT_SOUND).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dcel/edit.hpp"
#include "dcel/error.hpp"
#include "support/edit_helpers.hpp"
#include "support/face_shapes.hpp"

namespace dcel {
namespace {

using test_support::face_shapes;
using test_support::graph;
using test_support::sorted_shapes;

Dcel triangle() { return build(graph({{0, 0}, {4, 0}, {0, 4}}, {{0, 1}, {1, 2}, {2, 0}})); }

TEST(SplitEdge, SplitsATriangleSideKeepingIdsAndDirection) {
    Dcel d = triangle();
    const Change c = split_edge(d, EdgeId(0), {2, 0});
    EXPECT_SOUND(d);
    // Vertex 3 at (2, 0); edge 0 now runs 0 -> 3 and the new edge 3 runs 3 -> 1.
    EXPECT_EQ(c.vertices.added, VertexId(3));
    EXPECT_EQ(c.edges.added, EdgeId(3));
    EXPECT_EQ(c.edges.added_from, EdgeId(0));
    EXPECT_TRUE(c.faces.added.is_null() && c.edges.removed.is_null());
    EXPECT_EQ(d.origin(HalfEdgeId(0)), VertexId(0));
    EXPECT_EQ(d.target(HalfEdgeId(0)), VertexId(3));
    EXPECT_EQ(d.origin(HalfEdgeId(6)), VertexId(3));
    EXPECT_EQ(d.target(HalfEdgeId(6)), VertexId(1));
    EXPECT_EQ(d.face(HalfEdgeId(6)), d.face(HalfEdgeId(0)));
    EXPECT_EQ(d.face(HalfEdgeId(7)), d.face(HalfEdgeId(1)));
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 2, 1, 3}}, {}}, {{0, 3, 1, 2}, {}, {}}}));
}

TEST(SplitEdge, SplitsALoneEdgeTwiceIntoAPath) {
    // A lone edge 0-1 along the x axis, split at x = 1 then x = 3: the path
    // 0-2-3-1, whose one cycle walks out and back.
    Dcel d = build(graph({{0, 0}, {4, 0}}, {{0, 1}}));
    (void)split_edge(d, EdgeId(0), {1, 0});
    EXPECT_SOUND(d);
    (void)split_edge(d, EdgeId(1), {3, 0});  // edge 1 is 2 -> 1 now
    EXPECT_SOUND(d);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 2, 3, 1, 3, 2}}, {}}}));
}

TEST(SplitEdge, SplitsTheTwinDirectionOfADanglingEdge) {
    // Square with a dangling edge 0-4 inside; splitting edge 4 (0 -> 4) where
    // 4 has degree 1 exercises the turn at the free end.
    Dcel d = build(graph({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}}));
    (void)split_edge(d, EdgeId(4), {1, 1});
    EXPECT_SOUND(d);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2, 3, 0, 5, 4, 5}, {}, {}}}));
}

TEST(SplitEdge, PointMustBeExactlyOnTheEdge) {
    Dcel d = build(graph({{0, 0}, {3, 1}}, {{0, 1}}));
    // (1, 1/3) rounds 1/3, so it is not on the segment: refused exactly.
    EXPECT_REFUSED_UNCHANGED(d, split_edge(d, EdgeId(0), {1, 1.0 / 3}), TopologyError, "not exactly on edge e0");
    EXPECT_REFUSED_UNCHANGED(d, split_edge(d, EdgeId(0), {0, 0}), TopologyError, "strictly between its ends");
    EXPECT_REFUSED_UNCHANGED(d, split_edge(d, EdgeId(0), {6, 2}), TopologyError, "not exactly on edge e0");
    EXPECT_REFUSED_UNCHANGED(d, split_edge(d, EdgeId(0), {std::nan(""), 0}), InvalidInput, "not finite");
    EXPECT_REFUSED_UNCHANGED(d, split_edge(d, EdgeId(1), {1.5, 0.5}), InvalidInput, "there is no edge e1");
    // (1.5, 0.5) is exactly on it.
    (void)split_edge(d, EdgeId(0), {1.5, 0.5});
    EXPECT_SOUND(d);
}

TEST(MergeCollinearEdges, UndoesASplit) {
    Dcel d = triangle();
    const auto before = face_shapes(d);
    (void)split_edge(d, EdgeId(1), {2, 2});  // vertex 3 on the hypotenuse
    const Change c = merge_collinear_edges(d, VertexId(3));
    EXPECT_SOUND(d);
    EXPECT_EQ(face_shapes(d), before);
    // The smaller edge id survives; the new edge (3) was the last, so nothing moves.
    EXPECT_EQ(c.edges.removed, EdgeId(3));
    EXPECT_EQ(c.edges.merged_into, EdgeId(1));
    EXPECT_TRUE(c.edges.moved.is_null());
    EXPECT_EQ(c.vertices.removed, VertexId(3));
    EXPECT_TRUE(c.vertices.moved.is_null());
    // Edge 1 keeps its origin: 2*1 still leaves vertex 1 and now ends at 2.
    EXPECT_EQ(d.origin(HalfEdgeId(2)), VertexId(1));
    EXPECT_EQ(d.target(HalfEdgeId(2)), VertexId(2));
}

TEST(MergeCollinearEdges, MovesTheLastVertexAndEdgeIntoTheFreedIds) {
    // Path 0 - 1 - 2 along the x axis plus a separate edge 3-4; merging at
    // vertex 1 frees vertex 1 and edge 1 (edges 0 = 0-1, 1 = 1-2): vertex 4
    // and edge 2 (3-4) move into them.
    Dcel d = build(graph({{0, 0}, {1, 0}, {2, 0}, {0, 5}, {1, 6}}, {{0, 1}, {1, 2}, {3, 4}}));
    const Change c = merge_collinear_edges(d, VertexId(1));
    EXPECT_SOUND(d);
    EXPECT_EQ(c.vertices.removed, VertexId(1));
    EXPECT_EQ(c.vertices.moved, VertexId(4));
    EXPECT_EQ(c.edges.removed, EdgeId(1));
    EXPECT_EQ(c.edges.merged_into, EdgeId(0));
    EXPECT_EQ(c.edges.moved, EdgeId(2));
    EXPECT_EQ(d.num_vertices(), 4U);
    EXPECT_EQ(d.point(VertexId(1)).y, 6);  // the old vertex 4
    // Edge 0 is 0-2 now; edge 1 is the old 3-4, same direction: 3 -> (old 4 = new 1).
    EXPECT_EQ(d.target(HalfEdgeId(0)), VertexId(2));
    EXPECT_EQ(d.origin(HalfEdgeId(2)), VertexId(3));
    EXPECT_EQ(d.target(HalfEdgeId(2)), VertexId(1));
    EXPECT_EQ(c.renamed(VertexId(4)), VertexId(1));
    EXPECT_EQ(c.renamed(EdgeId(2)), EdgeId(1));
    EXPECT_EQ(c.renamed(EdgeId(1)), EdgeId(0));
    EXPECT_EQ(c.renamed(HalfEdgeId(5)), HalfEdgeId(3));
    EXPECT_TRUE(c.renamed(HalfEdgeId(2)).is_null());
}

TEST(MergeCollinearEdges, RefusesCornersAndOtherDegrees) {
    Dcel d = build(graph({{0, 0}, {4, 0}, {0, 4}, {9, 9}, {2, -3}, {6, 0}}, {{0, 1}, {1, 2}, {2, 0}, {1, 5}}));
    // v0 is a corner (degree 2, not straight); v1 has degree 3; v5 degree 1; v3 and v4 isolated.
    EXPECT_REFUSED_UNCHANGED(d, merge_collinear_edges(d, VertexId(0)), TopologyError, "not exactly on the segment");
    EXPECT_REFUSED_UNCHANGED(d, merge_collinear_edges(d, VertexId(1)), TopologyError, "has 3 edges");
    EXPECT_REFUSED_UNCHANGED(d, merge_collinear_edges(d, VertexId(5)), TopologyError, "has 1 edge;");
    EXPECT_REFUSED_UNCHANGED(d, merge_collinear_edges(d, VertexId(3)), TopologyError, "has 0 edges");
    EXPECT_REFUSED_UNCHANGED(d, merge_collinear_edges(d, VertexId(6)), InvalidInput, "there is no vertex v6");
}

TEST(MergeCollinearEdges, AtAVertexWhoseFarEndIsFree) {
    // Path 0 - 1 - 2 with both far ends of degree 1: the merged edge is lone.
    Dcel d = build(graph({{0, 0}, {1, 1}, {3, 3}}, {{1, 2}, {0, 1}}));
    (void)merge_collinear_edges(d, VertexId(1));
    EXPECT_SOUND(d);
    EXPECT_EQ(d.num_edges(), 1U);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 1}}, {}}}));  // old v2 is now v1
}

}  // namespace
}  // namespace dcel
