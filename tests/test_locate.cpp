// Point location: hand-checked answers on the bundled map, then the
// trapezoidal map (PointLocator) against the scan (locate_by_scan) at every
// half-integer point of random maps, and the scan against an independent
// oracle: build() placing the query point as an isolated vertex.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "dcel/locate.hpp"
#include "dcel/to_graph.hpp"
#include "support/edit_helpers.hpp"
#include "support/random_maps.hpp"

namespace dcel {
namespace {

using test_support::countries;
using test_support::graph;
using test_support::kEast;
using test_support::kEnclave;
using test_support::kWest;

void expect_both(const Dcel& d, const PointLocator& fast, Point p, Location expected) {
    EXPECT_EQ(locate_by_scan(d, p), expected) << "scan at (" << p.x << ", " << p.y << ")";
    EXPECT_EQ(fast.locate(p), expected) << "locator at (" << p.x << ", " << p.y << ")";
}

TEST(Locate, CountriesByHand) {
    const Dcel d = build(countries());
    const PointLocator fast(d);
    expect_both(d, fast, {1, 1}, Location::in_face(kWest));
    expect_both(d, fast, {6, 1}, Location::in_face(kEast));
    expect_both(d, fast, {6, 3}, Location::in_face(kEnclave));
    expect_both(d, fast, {20, 20}, Location::in_face(Dcel::kUnboundedFace));
    expect_both(d, fast, {4, -1}, Location::in_face(Dcel::kUnboundedFace));  // straight below a vertex
    expect_both(d, fast, {4, 7}, Location::in_face(Dcel::kUnboundedFace));   // straight above the border
    expect_both(d, fast, {4, 0}, Location::at_vertex(VertexId(1)));
    expect_both(d, fast, {2, 3}, Location::at_vertex(VertexId(10)));  // the capital, an isolated vertex
    expect_both(d, fast, {4, 3}, Location::on_edge(EdgeId(6)));       // inside the vertical border
    expect_both(d, fast, {6, 2}, Location::on_edge(EdgeId(7)));
    expect_both(d, fast, {-0.0, 3}, Location::on_edge(EdgeId(5)));
    // Exactness: just off the border on either side.
    expect_both(d, fast, {std::nextafter(4.0, 0.0), 3}, Location::in_face(kWest));
    expect_both(d, fast, {std::nextafter(4.0, 9.0), 3}, Location::in_face(kEast));
}

TEST(Locate, EmptyAndEdgelessMaps) {
    const Dcel empty;
    expect_both(empty, PointLocator(empty), {1, 2}, Location::in_face(Dcel::kUnboundedFace));
    const Dcel points = build(graph({{0, 0}, {1, 1}}, {}));
    const PointLocator fast(points);
    expect_both(points, fast, {1, 1}, Location::at_vertex(VertexId(1)));
    expect_both(points, fast, {0.5, 0.5}, Location::in_face(Dcel::kUnboundedFace));
}

// The oracle for a point in a face: build() places it, as an isolated
// vertex, in a face of the rebuilt DCEL; half-edge ids are the same there,
// so that face names the answer through any of its half-edges.
FaceId face_by_rebuild(const Dcel& d, Point p) {
    PlanarGraph g = to_graph(d);
    g.vertices.push_back(p);
    const Dcel r = build(g);
    const FaceId f = face_of_isolated_vertex(r, VertexId(static_cast<Index>(g.vertices.size() - 1)));
    if (r.is_unbounded(f)) return Dcel::kUnboundedFace;
    return d.face(r.outer(f));
}

TEST(Locate, TrapezoidalMapAgreesWithScanOnRandomMaps) {
    std::size_t faces_checked = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Dcel d = test_support::random_map(seed, 60, 8);
        ASSERT_FALSE(test_support::soundness_problem(d).has_value());
        const PointLocator fast(d, seed);
        for (int i = -2; i <= 18; ++i) {
            for (int j = -2; j <= 18; ++j) {
                const Point p{i / 2.0, j / 2.0};
                const Location scan = locate_by_scan(d, p);
                ASSERT_EQ(fast.locate(p), scan) << "seed " << seed << " at (" << p.x << ", " << p.y << ")";
                if (scan.kind == Location::Kind::Face && (i + j) % 3 == 0) {
                    ASSERT_EQ(scan.face, face_by_rebuild(d, p)) << "seed " << seed << " at (" << p.x << ", " << p.y << ")";
                    ++faces_checked;
                }
            }
        }
    }
    EXPECT_GT(faces_checked, 1000U);
}

TEST(Locate, GridWithVerticalEdgesAndSharedCoordinates) {
    // A 6 x 6 grid of unit squares: every x is shared by 7 vertices, half the
    // edges are vertical. Query every quarter point.
    const int n = 6;
    PlanarGraph g;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) g.vertices.push_back({static_cast<double>(i), static_cast<double>(j)});
    }
    auto id = [&](int i, int j) { return VertexId(static_cast<Index>(i * (n + 1) + j)); };
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            if (i < n) g.edges.push_back({id(i, j), id(i + 1, j)});
            if (j < n) g.edges.push_back({id(i, j), id(i, j + 1)});
        }
    }
    const Dcel d = build(g);
    for (std::uint64_t seed : {1ULL, 2ULL, 3ULL}) {
        const PointLocator fast(d, seed);
        for (int i = -1; i <= 4 * n + 1; ++i) {
            for (int j = -1; j <= 4 * n + 1; ++j) {
                const Point p{i / 4.0, j / 4.0};
                ASSERT_EQ(fast.locate(p), locate_by_scan(d, p)) << "at (" << p.x << ", " << p.y << ")";
            }
        }
    }
}

TEST(Locate, SearchDepthGrowsLogarithmically) {
    // Expected depth is O(log n) (de Berg et al., Lemma 6.6: at most about
    // 3 ln n + O(1) for a fixed query). Check the longest path of the DAG on
    // growing random maps against a generous 12 log2 E bound.
    for (const int steps : {200, 800, 3200}) {
        const Dcel d = test_support::random_map(7, steps, 60);
        const PointLocator fast(d);
        const double log_e = std::log2(static_cast<double>(d.num_edges()) + 2);
        std::cerr << "  E = " << d.num_edges() << ": depth " << fast.depth() << ", nodes " << fast.num_nodes() << "\n";
        EXPECT_LT(static_cast<double>(fast.depth()), 12 * log_e);
        EXPECT_LT(fast.num_nodes(), 40 * (d.num_edges() + 1));
    }
}

}  // namespace
}  // namespace dcel
