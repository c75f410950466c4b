// Code that the larger suites did not reach (found by scripts/coverage):
// cycle_area(), neighbours(), backwards walks, Change::renamed(), printing a Location, ExactSum::add/subtract,
// the names of the input error kinds, and an edge between two vertices of
// large degree. Expected values are worked out by hand, mostly on a 4x4
// square with the diagonal from (0,0) to (4,4) and a small triangle
// (3,1), (3.5,1), (3.5,1.5) inside its lower-right half.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/change.hpp"
#include "dcel/error.hpp"
#include "dcel/geometry/exact_sum.hpp"
#include "dcel/locate.hpp"
#include "dcel/queries.hpp"
#include "dcel/validate.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::ExactSum;
namespace {

Dcel square_with_hole() {
    PlanarGraph g;
    g.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {3, 1}, {3.5, 1}, {3.5, 1.5}};
    for (const auto& [u, v] :
         std::vector<std::pair<Index, Index>>{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {4, 5}, {5, 6}, {6, 4}}) {
        g.edges.push_back({VertexId(u), VertexId(v)});
    }
    return build(g);
}

// Half-edge 2k runs along edge k as given, 2k+1 against it.
constexpr HalfEdgeId kBottom(0);         // (0,0) -> (4,0): the lower-right half on its left
constexpr HalfEdgeId kBottomBack(1);     // (4,0) -> (0,0): the outside
constexpr HalfEdgeId kLeftDown(6);       // (0,4) -> (0,0): the upper-left half
constexpr HalfEdgeId kTriangle(10);      // (3,1) -> (3.5,1): inside the small triangle
constexpr HalfEdgeId kTriangleBack(11);  // (3.5,1) -> (3,1): the small triangle's outside

TEST(Queries, CycleAreaIsSignedByOrientation) {
    const Dcel d = square_with_hole();
    // The lower-right half (0,0), (4,0), (4,4) counterclockwise: 4 * 4 / 2.
    EXPECT_EQ(cycle_area(d, kBottom).value, 8.0);
    EXPECT_EQ(cycle_area(d, kBottom).sign, Sign::Positive);
    // The square's outer boundary, walked clockwise by the unbounded face.
    EXPECT_EQ(cycle_area(d, kBottomBack).value, -16.0);
    EXPECT_EQ(cycle_area(d, kBottomBack).sign, Sign::Negative);
    // The small triangle: legs 0.5 and 0.5, so 0.125, either way round.
    EXPECT_EQ(cycle_area(d, kTriangle).value, 0.125);
    EXPECT_EQ(cycle_area(d, kTriangleBack).value, -0.125);
}

TEST(Queries, CycleWalksBothWays) {
    const Dcel d = square_with_hole();
    // The lower-right half: h0 (0,0)->(4,0), h2 (4,0)->(4,4), then h9, edge 4
    // (0,0)-(4,4) walked from (4,4) back to (0,0).
    std::vector<HalfEdgeId> forwards;
    for (const HalfEdgeId h : d.cycle(kBottom)) forwards.push_back(h);
    EXPECT_EQ(forwards, (std::vector<HalfEdgeId>{HalfEdgeId(0), HalfEdgeId(2), HalfEdgeId(9)}));
    std::vector<HalfEdgeId> backwards;
    for (const HalfEdgeId h : d.cycle_reversed(kBottom)) backwards.push_back(h);
    EXPECT_EQ(backwards, (std::vector<HalfEdgeId>{HalfEdgeId(0), HalfEdgeId(9), HalfEdgeId(2)}));
    // Postfix ++ returns the position before the step.
    auto it = d.cycle(kBottom).begin();
    const auto before = it++;
    EXPECT_EQ(*before, HalfEdgeId(0));
    EXPECT_EQ(*it, HalfEdgeId(2));
}

TEST(Change, RenamedFollowsRemovalMergeAndMove) {
    // Face 2 merged into face 1 and the last face, 5, renumbered as 2.
    Change c;
    c.faces.removed = FaceId(2);
    c.faces.merged_into = FaceId(1);
    c.faces.moved = FaceId(5);
    EXPECT_EQ(c.renamed(FaceId(2)), FaceId(1));
    EXPECT_EQ(c.renamed(FaceId(5)), FaceId(2));
    EXPECT_EQ(c.renamed(FaceId(3)), FaceId(3));
    // An edge that just went away (nothing merged, nothing moved): null.
    c.edges.removed = EdgeId(4);
    EXPECT_TRUE(c.renamed(EdgeId(4)).is_null());
    EXPECT_EQ(c.renamed(EdgeId(7)), EdgeId(7));
}

TEST(Queries, NeighboursAreTheFacesAcrossEachBoundary) {
    const Dcel d = square_with_hole();
    const FaceId outside = d.face(kBottomBack);
    const FaceId lower = d.face(kBottom);
    const FaceId upper = d.face(kLeftDown);
    const FaceId triangle = d.face(kTriangle);
    ASSERT_EQ(std::set<FaceId>({outside, lower, upper, triangle}).size(), 4U);
    auto sorted = [](std::vector<FaceId> v) {
        std::sort(v.begin(), v.end());
        return v;
    };
    // The lower half borders the outside (bottom, right), the upper half
    // (diagonal) and, through its hole, the triangle.
    EXPECT_EQ(neighbours(d, lower), sorted({outside, upper, triangle}));
    EXPECT_EQ(neighbours(d, upper), sorted({outside, lower}));
    EXPECT_EQ(neighbours(d, triangle), sorted({lower}));
    // The unbounded face has no outer cycle; its hole is the square.
    EXPECT_EQ(neighbours(d, outside), sorted({lower, upper}));
}

TEST(Queries, LocationsPrintWithTheirKind) {
    auto text = [](const Location& l) {
        std::ostringstream os;
        os << l;
        return os.str();
    };
    EXPECT_EQ(text(Location::in_face(FaceId(2))), "in f2");
    EXPECT_EQ(text(Location::on_edge(EdgeId(6))), "on e6");
    EXPECT_EQ(text(Location::at_vertex(VertexId(1))), "at v1");
}

TEST(ExactSum, AddAndSubtractAreExactPastRounding) {
    // 1e300 + 1 - 1e300 rounds to 0 in doubles; the exact sum is 1.
    ExactSum s;
    s.add(1e300);
    s.add(1.0);
    s.subtract(1e300);
    EXPECT_EQ(s.sign(), Sign::Positive);
    EXPECT_EQ(s.to_double(), 1.0);
    s.subtract(1.0);
    EXPECT_EQ(s.sign(), Sign::Zero);
    // The smallest subnormal, taken away from zero.
    s.subtract(DBL_TRUE_MIN);
    EXPECT_EQ(s.sign(), Sign::Negative);
    EXPECT_EQ(s.to_double(), -DBL_TRUE_MIN);
}

TEST(InputErrorKind, EveryKindHasItsOwnName) {
    // The names used in messages and by the fuzz harnesses' kind checks.
    const std::vector<std::pair<InputErrorKind, std::string>> names = {
        {InputErrorKind::Syntax, "syntax"},      {InputErrorKind::Shape, "shape"},
        {InputErrorKind::BadIndex, "bad-index"}, {InputErrorKind::BadCoordinate, "bad-coordinate"},
        {InputErrorKind::TooLarge, "too-large"}, {InputErrorKind::DuplicatePoint, "duplicate-point"},
        {InputErrorKind::SelfLoop, "self-loop"}, {InputErrorKind::DuplicateEdge, "duplicate-edge"},
        {InputErrorKind::Crossing, "crossing"},  {InputErrorKind::VertexOnEdge, "vertex-on-edge"},
        {InputErrorKind::Overlap, "overlap"},
    };
    std::set<std::string> seen;
    for (const auto& [kind, name] : names) {
        EXPECT_EQ(to_string(kind), name);
        seen.insert(to_string(kind));
    }
    EXPECT_EQ(seen.size(), names.size());
    // A value outside the enumerators (valid for an enum class over int).
    EXPECT_EQ(std::string(to_string(static_cast<InputErrorKind>(99))), "unknown");
}

// An edge between two rings larger than RankGraph::kSmallRing (16) is the one
// case where build() finds a twin's slot by binary search. Hub A = (0,0) has
// 20 spokes to (k, -1) and hub B = (100,0) 20 spokes to (100 + k, 1), for
// k = -10..9, so each has degree 21; edge 0 joins them. A tree: one face.
TEST(BuildHubs, EdgeBetweenTwoLargeRings) {
    PlanarGraph g;
    g.vertices = {{0, 0}, {100, 0}};
    g.edges.push_back({VertexId(0), VertexId(1)});
    for (int hub = 1; hub >= 0; --hub) {  // B's spokes are edges 1..20, A's 21..40
        for (int k = -10; k <= 9; ++k) {
            g.vertices.push_back(hub == 1 ? Point{100.0 + k, 1} : Point{static_cast<double>(k), -1});
            g.edges.push_back({VertexId(static_cast<Index>(hub)), VertexId(static_cast<Index>(g.vertices.size() - 1))});
        }
    }
    const Dcel d = build(g);
    EXPECT_FALSE(validate(d).has_value());
    EXPECT_EQ(d.num_faces(), 1U);
    EXPECT_EQ(count_components(d), 1U);
    // next(A->B) leaves B just clockwise of west: B's spoke with the largest
    // angle below 180 degrees, to (90, 1) (k = -10): edge 1, half-edge 2.
    EXPECT_EQ(d.next(HalfEdgeId(0)), HalfEdgeId(2));
    // next(B->A) leaves A just clockwise of east: A's spoke with the largest
    // angle below 0, to (9, -1) (k = 9): edge 40, half-edge 80.
    EXPECT_EQ(d.next(HalfEdgeId(1)), HalfEdgeId(80));
    // The one boundary walk goes along every edge twice.
    std::size_t length = 0;
    for ([[maybe_unused]] const HalfEdgeId h : d.cycle(HalfEdgeId(0))) ++length;
    EXPECT_EQ(length, 2 * g.edges.size());
}

}  // namespace
}  // namespace dcel
