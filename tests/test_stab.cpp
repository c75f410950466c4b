// Stabbing: hand-checked walks across the bundled map, then every walk on
// random maps against the independent checks of oracles/stab_walk.hpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "dcel/error.hpp"
#include "dcel/queries.hpp"
#include "dcel/stab.hpp"
#include "oracles/stab_walk.hpp"
#include "support/edit_helpers.hpp"
#include "support/random_maps.hpp"

namespace dcel {

// How gtest prints a piece in a failure message.
void PrintTo(const StabPiece& p, std::ostream* os) {
    switch (p.kind) {
        case StabPiece::Kind::Face: *os << p.face; return;
        case StabPiece::Kind::Vertex: *os << p.vertex; return;
        case StabPiece::Kind::Edge: *os << (p.along ? "along " : "across ") << p.edge; return;
    }
}

namespace {

using test_support::countries;
using test_support::graph;
using Pieces = std::vector<StabPiece>;

StabPiece F(Index f) { return StabPiece::in_face(FaceId(f)); }
StabPiece X(Index e) { return StabPiece::across(EdgeId(e)); }
StabPiece A(Index e) { return StabPiece::along_edge(EdgeId(e)); }
StabPiece V(Index v) { return StabPiece::at(VertexId(v)); }

Pieces reversed(Pieces p) {
    std::reverse(p.begin(), p.end());
    return p;
}

TEST(Stab, SegmentsAcrossTheCountries) {
    const Dcel d = build(countries());
    // West, over the border x = 4, into East (the Enclave starts at y = 2).
    EXPECT_EQ(stab_segment(d, {1, 1}, {7, 1}), (Pieces{F(1), X(6), F(2)}));
    // Through the capital (2, 3), over the border, over the Enclave's west
    // side x = 5, ending inside the Enclave.
    EXPECT_EQ(stab_segment(d, {1, 3}, {6, 3}), (Pieces{F(1), V(10), F(1), X(6), F(2), X(10), F(3)}));
    EXPECT_EQ(stab_segment(d, {6, 3}, {1, 3}), reversed({F(1), V(10), F(1), X(6), F(2), X(10), F(3)}));
    // Along the south coast, vertex to vertex.
    EXPECT_EQ(stab_segment(d, {0, 0}, {8, 0}), (Pieces{V(0), A(0), V(1), A(1), V(2)}));
    // From the sea through the corner (4, 0) into East (the wedge between
    // east and north at v1), ending on the Enclave's south side.
    EXPECT_EQ(stab_segment(d, {2, -2}, {6, 2}), (Pieces{F(0), V(1), F(2), X(7)}));
    // Starting and ending inside edges.
    EXPECT_EQ(stab_segment(d, {2, 0}, {6, 0}), (Pieces{A(0), V(1), A(1)}));
    EXPECT_EQ(stab_segment(d, {4, 3}, {6, 3}), (Pieces{X(6), F(2), X(10), F(3)}));
    EXPECT_EQ(stab_segment(d, {4, 1}, {4, 2}), (Pieces{A(6)}));
    // Points.
    EXPECT_EQ(stab_segment(d, {6, 3}, {6, 3}), (Pieces{F(3)}));
    EXPECT_EQ(stab_segment(d, {4, 0}, {4, 0}), (Pieces{V(1)}));
    EXPECT_EQ(stab_segment(d, {4, 2}, {4, 2}), (Pieces{X(6)}));
}

TEST(Stab, LinesAcrossTheCountries) {
    const Dcel d = build(countries());
    // y = 3: sea, x = 0 coast (e5), West, the capital, West, the border
    // (e6), East, the Enclave (e10 in, e8 out), East, x = 8 coast (e2), sea.
    const Pieces y3{F(0), X(5), F(1), V(10), F(1), X(6), F(2), X(10), F(3), X(8), F(2), X(2), F(0)};
    EXPECT_EQ(stab_line(d, {-1, 3}, {1, 3}, half_edge_of(EdgeId(6), 1)), y3);
    EXPECT_EQ(stab_line(d, {-1, 3}, {1, 3}, half_edge_of(EdgeId(2), 0)), y3);
    EXPECT_EQ(stab_line(d, {-1, 3}, {1, 3}), y3);
    EXPECT_EQ(stab_line(d, {1, 3}, {-1, 3}), reversed(y3));
    EXPECT_EQ(faces_in_order(y3),
              (std::vector<FaceId>{FaceId(0), FaceId(1), FaceId(1), FaceId(2), FaceId(3), FaceId(2), FaceId(0)}));
    // y = 0, along the coast; and a line through a corner only.
    EXPECT_EQ(stab_line(d, {-1, 0}, {1, 0}), (Pieces{F(0), V(0), A(0), V(1), A(1), V(2), F(0)}));
    EXPECT_EQ(stab_line(d, {8, 6}, {9, 5}), (Pieces{F(0), V(3), F(0)}));  // y = 14 - x touches the corner
    // y = x - 2 also meets the corner, after crossing the map from (2, 0).
    EXPECT_EQ(stab_line(d, {8, 6}, {9, 7}), (Pieces{F(0), X(0), F(1), X(6), F(2), X(10), F(3), X(9), F(2), V(3), F(0)}));
    EXPECT_EQ(stab_line(d, {20, 0}, {20, 1}), (Pieces{F(0)}));
    EXPECT_THROW((void)stab_line(d, {20, 0}, {20, 1}, HalfEdgeId(0)), TopologyError);
    EXPECT_THROW((void)stab_line(d, {1, 1}, {1, 1}), InvalidInput);
    // From a given half-edge: the same refusals, and ids that do not exist.
    try {
        (void)stab_line(d, {1, 1}, {1, 1}, HalfEdgeId(0));
        ADD_FAILURE() << "two equal points accepted";
    } catch (const InvalidInput& e) {
        EXPECT_EQ(e.kind(), InputErrorKind::BadCoordinate);
        EXPECT_NE(std::string(e.what()).find("a line needs two different points, but both are (1, 1)"), std::string::npos)
            << e.what();
    }
    for (const HalfEdgeId cut : {HalfEdgeId(22), HalfEdgeId(9999), HalfEdgeId()}) {
        try {
            (void)stab_line(d, {-1, 3}, {1, 3}, cut);
            ADD_FAILURE() << "half-edge " << cut.str() << " accepted; the map has 22";
        } catch (const InvalidInput& e) {
            EXPECT_EQ(e.kind(), InputErrorKind::BadIndex);
            EXPECT_NE(std::string(e.what()).find("there is no half-edge " + cut.str()), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW((void)stab_segment(d, {1, 1}, {NAN, 1}), InvalidInput);
    // Only isolated vertices on the line.
    const Dcel points = build(graph({{3, 3}, {1, 1}, {5, 0}}, {}));
    EXPECT_EQ(stab_line(points, {0, 0}, {1, 1}), (Pieces{F(0), V(1), F(0), V(0), F(0)}));
}

TEST(Stab, WalksOnRandomMapsMatchBruteForce) {
    std::size_t pieces_seen = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Dcel d = test_support::random_map(seed, 60, 8);
        std::mt19937_64 rng(seed * 7919);
        auto coord = [&] { return static_cast<double>(rng() % 21) / 2.0 - 0.5; };
        for (int k = 0; k < 150; ++k) {
            const Point a{coord(), coord()};
            const Point b = k % 5 == 0 ? a : Point{coord(), coord()};
            const Pieces p = stab_segment(d, a, b);
            const std::string problem = oracle::check_walk(d, a, b, p);
            ASSERT_EQ(problem, "") << "seed " << seed << " from (" << a.x << ", " << a.y << ") to (" << b.x << ", " << b.y
                                   << ")";
            ASSERT_EQ(stab_segment(d, b, a), reversed(p)) << "seed " << seed;
            pieces_seen += p.size();
            if (!(a == b)) {
                const Pieces line = stab_line(d, a, b);
                ASSERT_EQ(line.front(), F(0));
                ASSERT_EQ(line.back(), F(0));
                // The segment's walk is a stretch of the line's. (Test the
                // size first: with one piece, [begin + 1, end - 1) is not a range.)
                ASSERT_TRUE(p.size() <= 2 ||
                            std::search(line.begin(), line.end(), p.begin() + 1, p.end() - 1) != line.end());
            }
        }
    }
    EXPECT_GT(pieces_seen, 10000U);
}

}  // namespace
}  // namespace dcel
