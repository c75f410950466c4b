// add_edge, add_edge_to_point and add_vertex. Expected cycles are derived by
// hand from the next rule (comments give the reasoning where it is not a
// plain polygon); every result is also checked against validate() and a
// rebuild from scratch (EXPECT_SOUND).
#include <gtest/gtest.h>

#include <cmath>

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

TEST(AddEdge, CutsAFaceAlongANewBorder) {
    // West (0 1 4 5) gets a border at y = 4 from (0, 4) on edge 5-0 to (4, 4)
    // on the West/East border 1-4. The new face is the part on the left of
    // 11 -> 12, going east: the north. The capital (2, 3) stays in West.
    Dcel d = build(countries());
    EXPECT_EQ(split_edge(d, EdgeId(5), {0, 4}).vertices.added, VertexId(11));
    EXPECT_EQ(split_edge(d, EdgeId(6), {4, 4}).vertices.added, VertexId(12));
    EXPECT_SOUND(d);
    const Change c = add_edge(d, VertexId(11), VertexId(12));
    EXPECT_SOUND(d);
    EXPECT_EQ(c.edges.added, EdgeId(13));
    EXPECT_EQ(c.faces.added, FaceId(4));
    EXPECT_EQ(c.faces.added_from, kWest);
    EXPECT_EQ(d.face(HalfEdgeId(26)), FaceId(4));  // left of 11 -> 12
    EXPECT_EQ(d.face(HalfEdgeId(27)), kWest);
    EXPECT_EQ(d.isolated(kWest), std::vector<VertexId>{VertexId(10)});
    EXPECT_EQ(face_shapes(d), sorted_shapes({
                                  {{}, {{0, 11, 5, 4, 3, 2, 1}}, {}},
                                  {{0, 1, 12, 11}, {}, {10}},
                                  {{4, 5, 11, 12}, {}, {}},
                                  {{1, 2, 3, 4, 12}, {{6, 9, 8, 7}}, {}},
                                  {{6, 7, 8, 9}, {}, {}},
                              }));
}

TEST(AddEdge, JoinsAHoleToItsFaceThenSplitsTheFace) {
    // 7-2 joins the Enclave's outside to East's outer boundary: no new face,
    // East loses its hole. Then 8-3 closes East off: the new face is on the
    // left of 8 -> 3 (north-east bound, so the west side), East keeps 2 3 8 7.
    Dcel d = build(countries());
    const Change join = add_edge(d, VertexId(7), VertexId(2));
    EXPECT_SOUND(d);
    EXPECT_TRUE(join.faces.added.is_null());
    EXPECT_TRUE(d.inner(kEast).empty());
    EXPECT_EQ(d.num_faces(), 4U);
    const Change split = add_edge(d, VertexId(8), VertexId(3));
    EXPECT_SOUND(d);
    EXPECT_EQ(split.faces.added, FaceId(4));
    EXPECT_EQ(split.faces.added_from, kEast);
    // At 7, arriving from 2 (heading north-west), the next edge clockwise of
    // 7->2 is 7->6 (west); at 9 from 6 it is 9->8; at 8 from 9 it is 8->3.
    EXPECT_EQ(face_shapes(d), sorted_shapes({
                                  {{}, {{0, 5, 4, 3, 2, 1}}, {}},
                                  {{0, 1, 4, 5}, {}, {10}},
                                  {{2, 3, 8, 7}, {}, {}},
                                  {{1, 2, 7, 6, 9, 8, 3, 4}, {}, {}},
                                  {{6, 7, 8, 9}, {}, {}},
                              }));
    EXPECT_EQ(d.face(half_edge(d, 2, 3)), kEast);
}

TEST(AddEdge, ClosingATreeMakesTheEnclosedRegionTheNewFace) {
    // A V (0,0)-(2,2)-(4,0) in the unbounded face, an isolated vertex (2, 1)
    // and a segment (1.5, 0.5)-(2.5, 0.5) under the V, and an isolated vertex
    // (9, 9) outside. Closing 0-2 (either way round) encloses the triangle:
    // the new face takes the vertex and the segment under the V, whatever
    // side of the new edge it is on.
    for (const bool forward : {true, false}) {
        Dcel d = build(graph({{0, 0}, {2, 2}, {4, 0}, {2, 1}, {1.5, 0.5}, {2.5, 0.5}, {9, 9}}, {{0, 1}, {1, 2}, {4, 5}}));
        const Change c = forward ? add_edge(d, VertexId(0), VertexId(2)) : add_edge(d, VertexId(2), VertexId(0));
        EXPECT_SOUND(d);
        EXPECT_EQ(c.faces.added, FaceId(1));
        EXPECT_EQ(c.faces.added_from, Dcel::kUnboundedFace);
        EXPECT_EQ(face_shapes(d), sorted_shapes({
                                      {{}, {{0, 1, 2}}, {6}},
                                      {{0, 2, 1}, {{4, 5}}, {3}},
                                  }));
    }
}

TEST(AddEdge, JoinsTwoHolesIntoOne) {
    // Two lone edges in the unbounded face; joining 1-2 makes a path 0-1-2-3.
    Dcel d = build(graph({{0, 0}, {1, 0}, {2, 1}, {3, 1}}, {{0, 1}, {2, 3}}));
    (void)add_edge(d, VertexId(1), VertexId(2));
    EXPECT_SOUND(d);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 1, 2, 3, 2, 1}}, {}}}));
}

TEST(AddEdge, BetweenIsolatedVerticesAndToAnIsolatedVertex) {
    // Square 0-3 holding isolated vertices 4 (1, 1), 5 (3, 1) and 6 (2, 3).
    Dcel d = build(graph({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {3, 1}, {2, 3}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
    (void)add_edge(d, VertexId(4), VertexId(5));  // a new hole of the square
    EXPECT_SOUND(d);
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2, 3}, {{4, 5}}, {6}}}));
    (void)add_edge(d, VertexId(2), VertexId(6));  // a dangling edge from the corner
    EXPECT_SOUND(d);
    // At 2, arriving from 1 (heading north), clockwise of 2->1 (south) comes 2->6 (south-west).
    EXPECT_EQ(face_shapes(d), sorted_shapes({{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2, 6, 2, 3}, {{4, 5}}, {}}}));
    (void)add_edge(d, VertexId(6), VertexId(5));  // joins the hole to the outer boundary
    EXPECT_SOUND(d);
    EXPECT_EQ(d.num_faces(), 2U);
    EXPECT_TRUE(d.inner(FaceId(1)).empty());
}

TEST(AddEdge, Refusals) {
    Dcel d = build(countries());
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(3), VertexId(3)), TopologyError, "two different vertices");
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(4), VertexId(1)), TopologyError, "already joined by edge e6");
    // Both diagonals of West pass through the capital (2, 3).
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(0), VertexId(4)), TopologyError, "passes through isolated vertex v10");
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(5), VertexId(1)), TopologyError, "passes through isolated vertex v10");
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(1), VertexId(3)), TopologyError, "crosses edge e7");
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(0), VertexId(2)), TopologyError, "overlaps edge e0");
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(5), VertexId(3)), TopologyError, "overlaps edge e3");
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(10), VertexId(8)), TopologyError, "crosses edge e6");
    EXPECT_REFUSED_UNCHANGED(d, add_edge(d, VertexId(0), VertexId(11)), InvalidInput, "there is no vertex v11");
    // A segment through a vertex with edges: (4, 0) lies on (2, -2)-(6, 2).
    Dcel e = build(graph({{2, -2}, {6, 2}, {4, 0}, {4, 3}}, {{2, 3}}));
    EXPECT_REFUSED_UNCHANGED(e, add_edge(e, VertexId(0), VertexId(1)), TopologyError, "passes through vertex v2");
}

TEST(AddEdgeToPoint, GrowsADanglingEdgeIntoAFace) {
    Dcel d = build(countries());
    const Change c = add_edge_to_point(d, VertexId(4), {6, 5});  // from (4, 6) into East
    EXPECT_SOUND(d);
    EXPECT_EQ(c.vertices.added, VertexId(11));
    EXPECT_EQ(c.edges.added, EdgeId(11));
    EXPECT_EQ(d.face(HalfEdgeId(22)), kEast);
    EXPECT_EQ(d.face(HalfEdgeId(23)), kEast);
    // From an isolated vertex: the capital gets a road, a new hole of West.
    (void)add_edge_to_point(d, VertexId(10), {1, 1});
    EXPECT_SOUND(d);
    EXPECT_TRUE(d.isolated(kWest).empty());
    EXPECT_EQ(d.inner(kWest).size(), 1U);
}

TEST(AddEdgeToPoint, Refusals) {
    Dcel d = build(countries());
    EXPECT_REFUSED_UNCHANGED(d, add_edge_to_point(d, VertexId(0), {4, 0}), TopologyError, "is vertex v1");
    EXPECT_REFUSED_UNCHANGED(d, add_edge_to_point(d, VertexId(0), {4, 3}), TopologyError, "lies inside edge e6");
    EXPECT_REFUSED_UNCHANGED(d, add_edge_to_point(d, VertexId(0), {6, 3}), TopologyError, "crosses edge e6");
    EXPECT_REFUSED_UNCHANGED(d, add_edge_to_point(d, VertexId(0), {3, 4.5}), TopologyError,
                             "passes through isolated vertex v10");
    EXPECT_REFUSED_UNCHANGED(d, add_edge_to_point(d, VertexId(0), {INFINITY, 0}), InvalidInput, "not finite");
}

TEST(AddVertex, LandsInTheFaceThatContainsIt) {
    Dcel d = build(countries());
    EXPECT_EQ(add_vertex(d, {6, 3}).vertices.added, VertexId(11));
    EXPECT_EQ(add_vertex(d, {6, 1}).vertices.added, VertexId(12));
    EXPECT_EQ(add_vertex(d, {1, 1}).vertices.added, VertexId(13));
    EXPECT_EQ(add_vertex(d, {-1, 3}).vertices.added, VertexId(14));
    EXPECT_SOUND(d);
    EXPECT_EQ(d.isolated(kEnclave), std::vector<VertexId>{VertexId(11)});
    EXPECT_EQ(d.isolated(kEast), std::vector<VertexId>{VertexId(12)});
    EXPECT_EQ(d.isolated(kWest), (std::vector<VertexId>{VertexId(10), VertexId(13)}));
    EXPECT_EQ(d.isolated(Dcel::kUnboundedFace), std::vector<VertexId>{VertexId(14)});
    EXPECT_REFUSED_UNCHANGED(d, add_vertex(d, {7, 4}), TopologyError, "is vertex v8");
    EXPECT_REFUSED_UNCHANGED(d, add_vertex(d, {6, 4}), TopologyError, "lies inside edge e9");
    EXPECT_REFUSED_UNCHANGED(d, add_vertex(d, {0, NAN}), InvalidInput, "not finite");
    Dcel empty;
    (void)add_vertex(empty, {1, 2});
    EXPECT_SOUND(empty);
}

}  // namespace
}  // namespace dcel
