// build() on hand-made tricky graphs. Every expected face below was worked
// out by hand from the next rule (next(u->v) leaves v just clockwise of
// v->u): the comments give the reasoning where it is not a plain polygon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numeric>
#include <random>
#include <string>
#include <tuple>
#include <utility>

#include "dcel/build.hpp"
#include "dcel/error.hpp"
#include "dcel/queries.hpp"
#include "dcel/validate.hpp"
#include "support/face_shapes.hpp"

namespace dcel {
namespace {

using test_support::face_shapes;
using test_support::FaceShape;
using test_support::sorted_shapes;

PlanarGraph graph(std::vector<Point> points, std::vector<std::pair<Index, Index>> edges) {
    PlanarGraph g;
    g.vertices = std::move(points);
    for (const auto& [u, v] : edges) g.edges.push_back({VertexId(u), VertexId(v)});
    return g;
}

// Components by breadth-first search: independent of the builder's union-find.
std::size_t components_by_bfs(const PlanarGraph& g) {
    std::vector<std::vector<Index>> adj(g.vertices.size());
    for (const GraphEdge& e : g.edges) {
        adj[e.u.index()].push_back(e.v.index());
        adj[e.v.index()].push_back(e.u.index());
    }
    std::vector<char> seen(g.vertices.size(), 0);
    std::size_t count = 0;
    for (Index s = 0; s < g.vertices.size(); ++s) {
        if (seen[s]) continue;
        ++count;
        std::vector<Index> stack{s};
        seen[s] = 1;
        while (!stack.empty()) {
            const Index x = stack.back();
            stack.pop_back();
            for (const Index y : adj[x]) {
                if (!seen[y]) {
                    seen[y] = 1;
                    stack.push_back(y);
                }
            }
        }
    }
    return count;
}

// Builds, checks the structure, Euler's formula and face areas, and compares
// the faces with the hand-derived ones; the unchecked mode (which places
// holes with less of the sweep) must give the same faces.
void expect_faces(const PlanarGraph& g, std::vector<FaceShape> expected) {
    const Dcel d = build(g);
    const auto violation = validate(d);
    ASSERT_FALSE(violation.has_value()) << violation->message;
    expected = sorted_shapes(std::move(expected));
    EXPECT_EQ(face_shapes(d), expected);
    EXPECT_EQ(face_shapes(build(g, {.check_crossings = false})), expected) << "unchecked";
    EXPECT_EQ(d.num_vertices() + d.num_faces(), d.num_edges() + 1 + components_by_bfs(g));  // V - E + F = 1 + C
    EXPECT_TRUE(d.is_unbounded(Dcel::kUnboundedFace));
    for (Index f = 1; f < d.num_faces(); ++f) EXPECT_EQ(face_area(d, FaceId(f)).sign, Sign::Positive);
}

TEST(Build, EmptyGraphHasOnlyTheUnboundedFace) { expect_faces(graph({}, {}), {{{}, {}, {}}}); }

TEST(Build, IsolatedVertices) { expect_faces(graph({{0, 0}, {1, 5}}, {}), {{{}, {}, {0, 1}}}); }

// Regression (found by fuzz/nonplanar under UBSan): sorting the rings formed
// first + 1 on an empty ring, undefined behaviour when the graph has no edges
// (a null iterator) or when the last vertex has none (past the end). Only a
// sanitizer build sees it; corpus/nonplanar/regressions/ replays it there.
TEST(Build, VerticesWithoutEdgesFirstAndLast) {
    expect_faces(graph({{0, 0}}, {}), {{{}, {}, {0}}});
    // Edge 0-1 is a hole of the unbounded face (one 2-cycle); 2 is isolated there.
    expect_faces(graph({{0, 0}, {2, 0}, {5, 5}}, {{0, 1}}), {{{}, {{0, 1}}, {2}}});
}

TEST(Build, LoneEdgeIsOneTwoCycle) {
    // next(0->1) = 1->0 and next(1->0) = 0->1: one cycle [0, 1], a hole of the unbounded face.
    expect_faces(graph({{0, 0}, {1, 1}}, {{0, 1}}), {{{}, {{0, 1}}, {}}});
}

TEST(Build, Triangle) {
    expect_faces(graph({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 2}, {2, 0}}), {{{}, {{0, 2, 1}}, {}}, {{0, 1, 2}, {}, {}}});
}

TEST(Build, SquareWithDiagonal) {
    expect_faces(graph({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}}),
                 {{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2}, {}, {}}, {{0, 2, 3}, {}, {}}});
}

TEST(Build, StarIsOneTourVisitingTheCentreBetweenLeaves) {
    // Arriving at the centre from a leaf, turn to the next leaf clockwise:
    // east (1), then south (4), west (3), north (2).
    expect_faces(graph({{0, 0}, {1, 0}, {0, 1}, {-1, 0}, {0, -1}}, {{0, 1}, {0, 2}, {0, 3}, {0, 4}}),
                 {{{}, {{0, 1, 0, 4, 0, 3, 0, 2}}, {}}});
}

TEST(Build, BowtieOuterBoundaryPassesTheSharedVertexTwice) {
    // Right triangle 0,1,2 and left triangle 0,3,4 share vertex 0. The outer
    // walk: 0->2->1->0, then clockwise at 0 from east-south to the left: 0->4->3->0.
    expect_faces(graph({{0, 0}, {2, -1}, {2, 1}, {-2, 1}, {-2, -1}}, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 4}, {4, 0}}),
                 {{{}, {{0, 2, 1, 0, 4, 3}}, {}}, {{0, 1, 2}, {}, {}}, {{0, 3, 4}, {}, {}}});
}

TEST(Build, DanglingTreeInsideAFace) {
    // At 0, arriving from 3 (north), clockwise next is 0->4 (north-east); the
    // tree 0-4-5 is walked out and back before 0->1.
    expect_faces(graph({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {2, 1}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {4, 5}}),
                 {{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2, 3, 0, 4, 5, 4}, {}, {}}});
}

TEST(Build, CollinearConsecutiveEdges) {
    expect_faces(graph({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}}),
                 {{{}, {{0, 4, 3, 2, 1}}, {}}, {{0, 1, 2, 3, 4}, {}, {}}});
}

TEST(Build, CollinearChainWithBranch) {
    // A path along y = x through 1 with a branch 1-4 going straight down. The
    // ring at 1, counterclockwise from east: 1->2 (45 deg), 1->0 (225), 1->4
    // (270). Arriving from 0, clockwise of 1->0 is 1->2; arriving from 2,
    // clockwise of 1->2 wraps round to 1->4; arriving from 4, it is 1->0.
    expect_faces(graph({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {1, -1}}, {{0, 1}, {1, 2}, {2, 3}, {1, 4}}),
                 {{{}, {{0, 1, 2, 3, 2, 1, 4, 1}}, {}}});
}

TEST(Build, HolesAndIsolatedVerticesLandInTheirFaces) {
    // Square 0-3; inside it box A (4-7) holding isolated 11, segment B (8-9)
    // above A, isolated 10; isolated 12 outside. Below B's leftmost vertex is
    // A's top edge, whose upper side is A's outer boundary, so B goes where A
    // goes: into the square.
    expect_faces(
        graph({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {5, 2}, {5, 4}, {2, 4}, {3, 6}, {4, 7}, {1, 1}, {3, 3}, {20, 20}},
              {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {8, 9}}),
        {{{}, {{0, 3, 2, 1}}, {12}}, {{0, 1, 2, 3}, {{4, 7, 6, 5}, {8, 9}}, {10}}, {{4, 5, 6, 7}, {}, {11}}});
}

TEST(Build, RayFromHoleHitsAVertexOfAnotherHole) {
    // Segment 7-8 starts straight above triangle 4-5-6's apex (5, 3). The
    // sweep's tilted line sees edge 6-5 below it, on the triangle's outside.
    expect_faces(graph({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 1}, {6, 1}, {5, 3}, {5, 5}, {6, 6}},
                       {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 4}, {7, 8}}),
                 {{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2, 3}, {{4, 6, 5}, {7, 8}}, {}}, {{4, 5, 6}, {}, {}}});
}

TEST(Build, ComponentInANotchStaysOutside) {
    // A C-shaped polygon opening east; segment 8-9 sits in the notch, so the
    // edge below it (2-3) has the notch, i.e. the unbounded face, above it.
    expect_faces(graph({{0, 0}, {10, 0}, {10, 2}, {2, 2}, {2, 8}, {10, 8}, {10, 10}, {0, 10}, {5, 4}, {6, 5}},
                       {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}, {8, 9}}),
                 {{{}, {{0, 7, 6, 5, 4, 3, 2, 1}, {8, 9}}, {}}, {{0, 1, 2, 3, 4, 5, 6, 7}, {}, {}}});
}

TEST(Build, AForestHasOnlyTheUnboundedFace) {
    // A U-shaped path 0-1-2-3 (open to the west) with segment 4-5 and
    // isolated 6 in its notch: no cycle anywhere, so all three are holes of
    // the unbounded face. The path's walk goes out and back: 0,1,2,3,2,1.
    expect_faces(graph({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 6}, {5, 2}}, {{0, 1}, {1, 2}, {2, 3}, {4, 5}}),
                 {{{}, {{0, 1, 2, 3, 2, 1}, {4, 5}}, {6}}});
}

TEST(Build, TreesAmongCyclesLandInTheirFaces) {
    // Square S (0-3) holds path A (4-5-6), segment B (7-8) straight above A,
    // triangle T (9-11) and segment C (12-13) above T's upper-left edge, and
    // isolated 19 above A. Below B's and 19's leftmost points is A's edge
    // 4-5 (a tree: no face of its own), then S's bottom: they are in S.
    // Below C is T's edge 9-11, whose upper side is T's outside: C is where
    // T is, in S. Isolated 17 is inside T. Path D (14-16) and isolated 18
    // are outside S.
    expect_faces(graph({{0, 0},   {20, 0},  {20, 20}, {0, 20},  {2, 3},  {12, 3}, {12, 5}, {5, 8},   {7, 9},   {14, 10},
                        {18, 10}, {16, 12}, {15, 15}, {17, 16}, {30, 5}, {32, 6}, {31, 8}, {16, 11}, {-5, -5}, {8, 6}},
                       {{0, 1},
                        {1, 2},
                        {2, 3},
                        {3, 0},
                        {4, 5},
                        {5, 6},
                        {7, 8},
                        {9, 10},
                        {10, 11},
                        {11, 9},
                        {12, 13},
                        {14, 15},
                        {15, 16}}),
                 {{{}, {{0, 3, 2, 1}, {14, 15, 16, 15}}, {18}},
                  {{0, 1, 2, 3}, {{4, 5, 6, 5}, {7, 8}, {9, 11, 10}, {12, 13}}, {19}},
                  {{9, 10, 11}, {}, {17}}});
}

TEST(Build, HolesNestedDeeply) {
    // Squares of half-width n - i around the origin, i = 0..n-1. Face i+1 is
    // inside square i, with square i+1 as its only hole.
    const Index n = 300;
    PlanarGraph g;
    std::vector<FaceShape> expected;
    expected.push_back({{}, {{0, 3, 2, 1}}, {}});
    for (Index i = 0; i < n; ++i) {
        const double r = n - i;
        const Index b = 4 * i;
        g.vertices.insert(g.vertices.end(), {{-r, -r}, {r, -r}, {r, r}, {-r, r}});
        for (Index k = 0; k < 4; ++k) g.edges.push_back({VertexId(b + k), VertexId(b + (k + 1) % 4)});
        FaceShape inside{{b, b + 1, b + 2, b + 3}, {}, {}};
        if (i + 1 < n) inside.holes.push_back({b + 4, b + 7, b + 6, b + 5});
        expected.push_back(inside);
    }
    expect_faces(g, expected);
}

TEST(Build, FaceIdsAreDeterministicAndTheUnboundedFaceIsZero) {
    const PlanarGraph g = graph({{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}});
    const Dcel a = build(g);
    const Dcel b = build(g);
    ASSERT_EQ(a.num_faces(), b.num_faces());
    for (Index h = 0; h < a.num_half_edges(); ++h) EXPECT_EQ(a.face(HalfEdgeId(h)), b.face(HalfEdgeId(h)));
    // Bounded faces are numbered by their smallest half-edge: 0->1 (h0) is in
    // triangle 0,1,2; h1 (1->0) is outside; 2->3 (h4) is in triangle 0,2,3.
    EXPECT_EQ(a.face(HalfEdgeId(0)), FaceId(1));
    EXPECT_EQ(a.face(HalfEdgeId(1)), Dcel::kUnboundedFace);
    EXPECT_EQ(a.face(HalfEdgeId(4)), FaceId(2));
}

TEST(Build, HalfEdgeLayoutFollowsInputEdges) {
    const Dcel d = build(graph({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 2}, {2, 0}}));
    EXPECT_EQ(d.origin(HalfEdgeId(0)), VertexId(0));
    EXPECT_EQ(d.target(HalfEdgeId(0)), VertexId(1));
    EXPECT_EQ(d.origin(HalfEdgeId(5)), VertexId(0));  // edge 2 reversed: 0->2
    EXPECT_EQ(d.next(HalfEdgeId(0)), HalfEdgeId(2));  // 0->1 then 1->2
    EXPECT_EQ(d.prev(HalfEdgeId(2)), HalfEdgeId(0));
    EXPECT_EQ(d.out(VertexId(0)), HalfEdgeId(0));  // the smallest outgoing id
    EXPECT_EQ(d.out(VertexId(2)), HalfEdgeId(3));
}

// ---- Near-degenerate coordinates

TEST(Build, DirectionsCloserThanAtan2CanSee) {
    // From the origin, (1e15, 1e15+1) and (1e15+1, 1e15+2) differ by ~5e-31
    // rad. cross(a, b) = 1e15(1e15+2) - (1e15+1)^2 = -1: 0,1,2 is clockwise.
    expect_faces(graph({{0, 0}, {1e15, 1e15 + 1}, {1e15 + 1, 1e15 + 2}}, {{0, 1}, {1, 2}, {2, 0}}),
                 {{{}, {{0, 1, 2}}, {}}, {{0, 2, 1}, {}, {}}});
}

TEST(Build, LargeOffsetsDifferingByOne) {
    const double o = 1e15;
    expect_faces(graph({{o, o}, {o + 4, o}, {o + 4, o + 4}, {o, o + 4}, {o + 1, o + 1}, {o + 2, o + 1}, {o + 1, o + 2}},
                       {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 4}}),
                 {{{}, {{0, 3, 2, 1}}, {}}, {{0, 1, 2, 3}, {{4, 6, 5}}, {}}, {{4, 5, 6}, {}, {}}});
}

TEST(Build, SubnormalAndTinyCoordinates) {
    const double s = 0x1p-1074;
    expect_faces(graph({{0, 0}, {s, 0}, {0, s}}, {{0, 1}, {1, 2}, {2, 0}}), {{{}, {{0, 2, 1}}, {}}, {{0, 1, 2}, {}, {}}});
    const double t = 1e-300;
    expect_faces(graph({{0, 0}, {3 * t, 0}, {3 * t, 3 * t}, {t, 2 * t}}, {{0, 1}, {1, 2}, {2, 0}}),
                 {{{}, {{0, 2, 1}}, {3}}, {{0, 1, 2}, {}, {}}});  // (t, 2t) is above the diagonal: outside
}

TEST(Build, HugeCoordinates) {
    const double m = 1e308;
    expect_faces(graph({{-m, -m}, {m, -m}, {0, m}, {0, 0}}, {{0, 1}, {1, 2}, {2, 0}}),
                 {{{}, {{0, 2, 1}}, {}}, {{0, 1, 2}, {}, {3}}});
}

TEST(Build, NegativeZeroIsZero) {
    expect_faces(graph({{-0.0, 0.0}, {1, -0.0}, {0.0, 1}}, {{0, 1}, {1, 2}, {2, 0}}),
                 {{{}, {{0, 2, 1}}, {}}, {{0, 1, 2}, {}, {}}});
}

// ---- Invalid input: kind, ids, and the message names them

void expect_invalid(const PlanarGraph& g, InputErrorKind kind, const std::string& text, std::vector<Index> vertices,
                    std::vector<Index> edges) {
    try {
        (void)build(g);
        FAIL() << "accepted; expected " << to_string(kind);
    } catch (const InvalidInput& e) {
        EXPECT_EQ(e.kind(), kind) << e.what();
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
        std::vector<Index> vs, es;
        for (const VertexId v : e.vertices()) vs.push_back(v.index());
        for (const EdgeId k : e.edges()) es.push_back(k.index());
        EXPECT_EQ(vs, vertices) << e.what();
        EXPECT_EQ(es, edges) << e.what();
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);  // one line
    }
}

TEST(BuildRejects, NonFiniteCoordinates) {
    expect_invalid(graph({{0, 0}, {NAN, 1}}, {}), InputErrorKind::BadCoordinate, "vertex 1 has a non-finite", {1}, {});
    expect_invalid(graph({{0, 0}, {1, INFINITY}}, {}), InputErrorKind::BadCoordinate, "(1, inf)", {1}, {});
}

TEST(BuildRejects, IndexOutOfRange) {
    expect_invalid(graph({{0, 0}, {1, 0}}, {{0, 1}, {0, 2}}), InputErrorKind::BadIndex,
                   "edge 1: vertex index 2 is out of range (there are 2 vertices", {}, {1});
}

TEST(BuildRejects, SelfLoop) {
    expect_invalid(graph({{0, 0}, {1, 0}}, {{0, 1}, {1, 1}}), InputErrorKind::SelfLoop, "edge 1 [1, 1] is a self-loop", {1},
                   {1});
}

TEST(BuildRejects, DuplicatePointsIncludingSignedZero) {
    expect_invalid(graph({{0, 0}, {1, 0}, {1, 0}}, {{0, 1}}), InputErrorKind::DuplicatePoint,
                   "vertices 1 and 2 are at the same point (1, 0)", {1, 2}, {});
    expect_invalid(graph({{0, 0}, {-0.0, 0}}, {}), InputErrorKind::DuplicatePoint, "vertices 0 and 1", {0, 1}, {});
}

TEST(BuildRejects, DuplicateEdgeInEitherOrientation) {
    expect_invalid(graph({{0, 0}, {1, 0}, {0, 1}}, {{0, 1}, {1, 2}, {1, 0}}), InputErrorKind::DuplicateEdge,
                   "edges 0 and 2 both join vertices 0 and 1", {0, 1}, {0, 2});
    expect_invalid(graph({{0, 0}, {1, 0}}, {{0, 1}, {0, 1}}), InputErrorKind::DuplicateEdge, "edges 0 and 1", {0, 1},
                   {0, 1});
}

TEST(BuildRejects, Crossing) {
    expect_invalid(graph({{0, 0}, {2, 2}, {0, 2}, {2, 0}}, {{0, 1}, {2, 3}}), InputErrorKind::Crossing,
                   "edge 0 [0, 1] from (0, 0) to (2, 2) and edge 1 [2, 3] from (0, 2) to (2, 0) cross", {}, {0, 1});
}

TEST(BuildRejects, CrossingThatBoostsStraightLineCheckMisses) {
    // From NOTES.md: Boost 1.74's is_straight_line_drawing accepts this.
    expect_invalid(graph({{0, 5}, {40, 15}, {0, 14}, {40, 6}, {60, 5}, {20, 200}}, {{0, 1}, {2, 3}, {4, 5}}),
                   InputErrorKind::Crossing, "cross", {}, {0, 1});
}

TEST(BuildRejects, CrossingBetweenNearlyParallelEdgesFarAway) {
    // Two edges from the same far-off region whose crossing needs exact arithmetic.
    const double o = 1e15;
    expect_invalid(graph({{o, o}, {o + 4, o + 1}, {o, o + 1}, {o + 4, o}}, {{0, 1}, {2, 3}}), InputErrorKind::Crossing,
                   "cross", {}, {0, 1});
}

TEST(BuildRejects, VertexInsideEdge) {
    expect_invalid(graph({{0, 0}, {4, 0}, {2, 0}, {2, 3}}, {{0, 1}, {2, 3}}), InputErrorKind::VertexOnEdge,
                   "vertex 2 (2, 0) lies inside edge 0 [0, 1]", {2}, {0});
    // An isolated vertex on an edge, and an edge's end on another edge.
    expect_invalid(graph({{0, 0}, {4, 4}, {1, 1}}, {{0, 1}}), InputErrorKind::VertexOnEdge, "vertex 2 (1, 1)", {2}, {0});
    expect_invalid(graph({{0, 0}, {0, 4}, {0, 2}}, {{0, 1}}), InputErrorKind::VertexOnEdge, "vertex 2", {2}, {0});
}

TEST(BuildRejects, CollinearOverlap) {
    expect_invalid(graph({{0, 0}, {3, 0}, {1, 0}, {5, 0}}, {{0, 1}, {2, 3}}), InputErrorKind::Overlap,
                   "edge 0 [0, 1] from (0, 0) to (3, 0) and edge 1 [2, 3] from (1, 0) to (5, 0) overlap", {2}, {0, 1});
    // Sharing an endpoint and running the same way.
    expect_invalid(graph({{0, 0}, {4, 0}, {2, 0}}, {{0, 1}, {0, 2}}), InputErrorKind::Overlap,
                   "both leave vertex 0 in the same direction", {0}, {0, 1});
    // One edge inside another, vertical.
    expect_invalid(graph({{0, 0}, {0, 9}, {0, 2}, {0, 5}}, {{0, 1}, {2, 3}}), InputErrorKind::Overlap, "overlap", {2},
                   {0, 1});
}

TEST(BuildRejects, EndpointsTouchingAtADistance) {
    // Edge 1 ends exactly on edge 0 far from the origin, at (1e15+2, 1e15+1):
    // on the line from (1e15, 1e15) to (1e15+4, 1e15+2).
    const double o = 1e15;
    expect_invalid(graph({{o, o}, {o + 4, o + 2}, {o + 2, o + 1}, {o + 2, o + 9}}, {{0, 1}, {2, 3}}),
                   InputErrorKind::VertexOnEdge, "vertex 2", {2}, {0});
}

TEST(BuildOptions, UncheckedModeBuildsTheSameFacesOnValidInput) {
    const PlanarGraph g = graph({{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {5, 2}, {5, 4}, {2, 4}, {3, 6}, {4, 7}},
                                {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {8, 9}});
    EXPECT_EQ(face_shapes(build(g, {.check_crossings = false})), face_shapes(build(g)));
}

// The graph with its vertex ids, edge order and edge orientations shuffled;
// vertex v of the original is vertex new_id[v] of the shuffled graph.
struct ShuffledGraph {
    PlanarGraph graph;
    std::vector<Index> new_id;
};

ShuffledGraph graph_with_shuffled_ids(const std::vector<Point>& points, std::vector<std::pair<Index, Index>> edges,
                                      std::mt19937& rng) {
    std::vector<Index> new_id(points.size());
    std::iota(new_id.begin(), new_id.end(), 0);
    std::shuffle(new_id.begin(), new_id.end(), rng);
    std::vector<Point> shuffled(points.size());
    for (Index v = 0; v < points.size(); ++v) shuffled[new_id[v]] = points[v];
    for (auto& [u, v] : edges) {
        u = new_id[u];
        v = new_id[v];
        if (rng() % 2 != 0) std::swap(u, v);
    }
    std::shuffle(edges.begin(), edges.end(), rng);
    return {graph(shuffled, edges), std::move(new_id)};
}

// More than 8192 half-edges, so that build() writes the DCEL through
// several buckets of half-edge ids (write_half_edges), with shuffled ids so
// that consecutive slots write to different buckets: a triangulated lattice
// with gaps, a comb-shaped tree beside it (its cycle is labelled without a
// walk) and isolated vertices. validate() checks the result; the two modes
// must agree, and Euler's formula hold.
TEST(BuildOptions, LargeShuffledGraphSpansSeveralWriteBuckets) {
    std::mt19937 rng(7);
    constexpr Index kSide = 70;
    std::vector<Point> points;
    std::vector<std::pair<Index, Index>> edges;
    for (Index y = 0; y < kSide; ++y) {
        for (Index x = 0; x < kSide; ++x) points.push_back({static_cast<double>(x), static_cast<double>(y)});
    }
    for (Index y = 0; y < kSide; ++y) {
        for (Index x = 0; x < kSide; ++x) {
            const Index i = y * kSide + x;
            if (x + 1 < kSide && rng() % 4 != 0) edges.emplace_back(i, i + 1);
            if (y + 1 < kSide && rng() % 4 != 0) edges.emplace_back(i, i + kSide);
            if (x + 1 < kSide && y + 1 < kSide && rng() % 2 != 0)
                edges.emplace_back(i, i + kSide + 1);  // one diagonal a cell
        }
    }
    const auto comb = static_cast<Index>(points.size());  // a spine along y = 0 with teeth of 49 edges
    for (Index x = 0; x < 40; ++x) {
        for (Index y = 0; y < 50; ++y) {
            points.push_back({static_cast<double>(kSide + 5 + x), static_cast<double>(y)});
            if (y > 0) edges.emplace_back(comb + x * 50 + y - 1, comb + x * 50 + y);
        }
        if (x > 0) edges.emplace_back(comb + (x - 1) * 50, comb + x * 50);
    }
    for (Index k = 0; k < 5; ++k) points.push_back({-2.0 - k, 3.0 * k});
    const PlanarGraph g = graph_with_shuffled_ids(points, edges, rng).graph;
    ASSERT_GT(2 * g.edges.size(), 2U * 8192U);

    const Dcel d = build(g);
    const auto violation = validate(d);
    ASSERT_FALSE(violation.has_value()) << violation->message;
    const Dcel unchecked = build(g, {.check_crossings = false});
    const auto unchecked_violation = validate(unchecked);
    ASSERT_FALSE(unchecked_violation.has_value()) << unchecked_violation->message;
    EXPECT_EQ(face_shapes(unchecked), face_shapes(d));
    EXPECT_EQ(d.num_vertices() + d.num_faces(), d.num_edges() + 1 + components_by_bfs(g));
}

// Faces as face_shapes gives them, with every vertex id v replaced by
// rename[v] (cycles re-canonicalized, lists re-sorted).
std::vector<FaceShape> renamed(std::vector<FaceShape> shapes, const std::vector<Index>& rename) {
    for (FaceShape& f : shapes) {
        for (Index& v : f.outer) v = rename[v];
        for (test_support::Cycle& hole : f.holes) {
            for (Index& v : hole) v = rename[v];
        }
        for (Index& v : f.isolated) v = rename[v];
        f = test_support::normalized(std::move(f));
    }
    return sorted_shapes(std::move(shapes));
}

// Graphs whose half-edge ids follow the sweep (nested squares listed from
// the outside in, a path inside them) are written to the DCEL arrays in
// slot order, without the buckets (write_half_edges); the same graph with
// shuffled ids takes the buckets. Both must give the same faces, pass
// validate() in both modes, and satisfy Euler's formula.
TEST(BuildOptions, GraphInSweepOrderAndItsShuffleGiveTheSameFaces) {
    constexpr Index kSquares = 2100;  // 8400 edges: more than two write buckets of half-edges
    std::vector<Point> points;
    std::vector<std::pair<Index, Index>> edges;
    for (Index k = kSquares; k >= 1; --k) {
        const auto r = static_cast<double>(k + 10);
        const auto first = static_cast<Index>(points.size());
        for (const Point p : {Point{-r, -r}, Point{r, -r}, Point{r, r}, Point{-r, r}}) points.push_back(p);
        for (Index i = 0; i < 4; ++i) edges.emplace_back(first + i, first + (i + 1) % 4);
    }
    const auto path = static_cast<Index>(points.size());  // a path of 9 edges inside the innermost square
    for (Index i = 0; i < 10; ++i) points.push_back({-5.0 + i, static_cast<double>(i % 3)});
    for (Index i = 0; i + 1 < 10; ++i) edges.emplace_back(path + i, path + i + 1);
    points.push_back({0.0, -7.0});     // isolated, inside the innermost square
    points.push_back({-5000.0, 0.0});  // isolated, outside everything
    const PlanarGraph ordered = graph(points, edges);
    ASSERT_GT(2 * ordered.edges.size(), 2U * 8192U);

    std::mt19937 rng(11);
    const ShuffledGraph shuffled = graph_with_shuffled_ids(points, edges, rng);
    std::vector<Index> old_id(points.size());  // shuffled vertex id -> id in `ordered`
    for (Index v = 0; v < points.size(); ++v) old_id[shuffled.new_id[v]] = v;

    const std::vector<FaceShape> expected = face_shapes(build(ordered));
    ASSERT_EQ(expected.size(), kSquares + 1U);  // the unbounded face and one ring face per square
    for (const bool check : {true, false}) {
        for (const PlanarGraph* g : {&ordered, &shuffled.graph}) {
            const Dcel d = build(*g, {.check_crossings = check});
            const auto violation = validate(d);
            ASSERT_FALSE(violation.has_value()) << violation->message;
            EXPECT_EQ(g == &ordered ? face_shapes(d) : renamed(face_shapes(d), old_id), expected);
            EXPECT_EQ(d.num_vertices() + d.num_faces(), d.num_edges() + 1 + components_by_bfs(*g));
        }
    }
}

TEST(BuildOptions, UncheckedModeSurvivesCrossings) {
    // Unspecified faces, but no crash, no hang, and a structure that holds together.
    const PlanarGraph g = graph({{0, 0}, {2, 2}, {0, 2}, {2, 0}, {5, 5}, {6, 5}}, {{0, 1}, {2, 3}, {4, 5}});
    const Dcel d = build(g, {.check_crossings = false});
    EXPECT_EQ(d.num_edges(), 3U);
}

}  // namespace
}  // namespace dcel
