// for_each_boundary_cycle (the prefetching scan behind boundary_cycles() and
// `dcel faces`) against the plain definition, walked one cycle at a time:
// every id not yet seen, in increasing order, starts its cycle. The inputs
// are large enough to span many of the scan's blocks, mix blocks whose walks
// stay near (no prefetching) with blocks whose walks jump (prefetching), and
// include DCELs changed by edits, where cycles are no longer named by their
// smallest half-edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "dcel/build.hpp"
#include "dcel/edit.hpp"
#include "dcel/queries.hpp"
#include "dcel/query/cycle_scan.hpp"
#include "dcel/validate.hpp"
#include "support/check_helpers.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::CycleScanStats;
using detail::for_each_boundary_cycle;
using detail::kPrefetchFromHalfEdges;
namespace {

using test_support::faces_answer;  // the plain one-walk-at-a-time loop: the oracle
using Cycles = check::FacesAnswer;

Cycles as_indexes(const std::vector<std::vector<VertexId>>& cycles) {
    Cycles out;
    for (const auto& c : cycles) {
        std::vector<Index>& o = out.emplace_back();
        for (const VertexId v : c) o.push_back(v.index());
    }
    return out;
}

// With prefetch_from = 0, the pipeline runs on these small inputs too.
Cycles scanned(const Dcel& d, CycleScanStats* stats = nullptr, std::size_t prefetch_from = 0) {
    std::vector<std::vector<VertexId>> cycles;
    const CycleScanStats s = for_each_boundary_cycle(
        d, [&](std::span<const VertexId> origins) { cycles.emplace_back(origins.begin(), origins.end()); }, prefetch_from);
    if (stats != nullptr) *stats = s;
    return as_indexes(cycles);
}

// Grid edges of a side x side block of new vertices, spaced 2 apart, at
// x offset dx: row by row, so that the half-edges of each cell are close.
void add_grid(PlanarGraph& g, Index side, double dx) {
    const auto first = static_cast<Index>(g.vertices.size());
    for (Index y = 0; y < side; ++y) {
        for (Index x = 0; x < side; ++x) g.vertices.push_back({dx + 2.0 * x, 2.0 * y});
    }
    for (Index y = 0; y < side; ++y) {
        for (Index x = 0; x < side; ++x) {
            const Index v = first + y * side + x;
            if (x + 1 < side) g.edges.push_back({VertexId(v), VertexId(v + 1)});
            if (y + 1 < side) g.edges.push_back({VertexId(v), VertexId(v + side)});
        }
    }
}

// A grid with its edges in row order (near walks), a second grid whose
// edges come shuffled and reversed at random (far walks), a ring of 3000
// edges (two cycles longer than a block), and isolated vertices.
PlanarGraph mixed_graph(std::mt19937& rng) {
    PlanarGraph g;
    add_grid(g, 70, 0);
    const std::size_t shuffled_from = g.edges.size();
    add_grid(g, 80, 300);
    std::shuffle(g.edges.begin() + static_cast<std::ptrdiff_t>(shuffled_from), g.edges.end(), rng);
    for (std::size_t e = shuffled_from; e < g.edges.size(); ++e) {
        if (rng() % 2 != 0) std::swap(g.edges[e].u, g.edges[e].v);
    }
    const auto ring = static_cast<Index>(g.vertices.size());
    constexpr Index kRing = 3000;  // a 1500 x 1500 square's boundary, below both grids
    for (Index k = 0; k < kRing; ++k) {
        const Index side = k / 750;
        const double t = 2.0 * (k % 750);
        const double x = side == 0 ? t : side == 1 ? 1500 : side == 2 ? 1500 - t : 0;
        const double y = side == 0 ? 0 : side == 1 ? t : side == 2 ? 1500 : 1500 - t;
        g.vertices.push_back({x, y - 2000});
        g.edges.push_back({VertexId(ring + k), VertexId(ring + (k + 1) % kRing)});
    }
    for (Index k = 0; k < 7; ++k) g.vertices.push_back({-10.0 - k, 3.0 * k});
    return g;
}

TEST(CycleScan, NothingToReportWithoutEdges) {
    EXPECT_TRUE(scanned(Dcel()).empty());
    PlanarGraph g;
    g.vertices = {{0, 0}, {1, 0}};
    EXPECT_TRUE(scanned(build(g)).empty());
}

TEST(CycleScan, MatchesOneWalkAtATimeOnNearAndFarBlocks) {
    for (unsigned seed = 0; seed < 4; ++seed) {
        std::mt19937 rng(seed);
        const Dcel d = build(mixed_graph(rng));
        const Cycles expected = faces_answer(d);
        // One outer cycle a component with edges (7 vertices are isolated),
        // one cycle a bounded face.
        EXPECT_EQ(expected.size(), d.num_faces() + count_components(d) - 1 - 7);
        CycleScanStats stats;
        EXPECT_EQ(scanned(d, &stats), expected) << "seed " << seed;
        EXPECT_EQ(as_indexes(boundary_cycles(d)), expected);
        // Both kinds of block, and a switch each way: the first block always
        // prefetches, the row-ordered grid's do not, the shuffled grid's do.
        EXPECT_GE(stats.blocks, 10U);
        EXPECT_GE(stats.prefetched_blocks, 4U);
        EXPECT_LE(stats.prefetched_blocks, stats.blocks - 4);
        // With the default threshold, a DCEL this small is scanned without.
        EXPECT_EQ(scanned(d, &stats, kPrefetchFromHalfEdges), expected);
        EXPECT_EQ(stats.prefetched_blocks, 0U);
    }
}

TEST(CycleScan, MatchesOneWalkAtATimeAfterEdits) {
    std::mt19937 rng(12);
    Dcel d = build(mixed_graph(rng));
    // Removals move the last edge into the freed id, splits add edges at
    // the end: cycles stop being named by their smallest half-edge.
    for (int k = 0; k < 400; ++k) {
        const EdgeId e(static_cast<Index>(rng() % d.num_edges()));
        if (k % 2 == 0) {
            (void)remove_edge(d, e);
        } else {
            const Point a = d.point(d.origin(HalfEdgeId(2 * e.index())));
            const Point b = d.point(d.target(HalfEdgeId(2 * e.index())));
            (void)split_edge(d, e, {(a.x + b.x) / 2, (a.y + b.y) / 2});  // exact: the coordinates are dyadic
        }
    }
    const CheckResult violation = validate(d);
    ASSERT_FALSE(violation.has_value()) << violation->message;
    const Cycles expected = faces_answer(d);
    EXPECT_EQ(scanned(d), expected);
}

}  // namespace
}  // namespace dcel
