// One function per generator family (internal to dcel::gen), and the
// constructions they share.
//
// Size rule: every family returns exactly `n` vertices, for every n
// (properties/test_gen_families.cpp checks n in {0, 1, 2, 3, 5, 10, 100,
// 1000, 10000} with many seeds, and 1e5). A family whose own shapes fall
// short fills up with isolated vertices, placed where they meet nothing.
//
// Cost: O(n log n) time and O(n) memory in every family: 1e5 vertices take
// under a second of CPU in each (random-segments, the slowest, about 0.7 s;
// most under 0.2 s), 1e4 vertices under 30 ms. Validity comes either from a
// construction that is valid by design (argued next to it: triangulation,
// tree, grid-with-holes, nested-polygons, comb, star, the thin fan, the
// monotone polygon of random-segments) or from GraphBuilder, whose exact
// checks only look at nearby cells (random-segments, collinear-chain,
// components). The brute-force check (brute_force.hpp) stays the independent
// guard in the tests.
//
// Coordinates are integers, below 2^26 in magnitude for n up to 10^6, before
// near-degenerate maps them exactly to awkward doubles (nested-polygons alone
// goes up to about 2^27 and is not one of its bases).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dcel/gen/graph_builder.hpp"
#include "dcel/gen/rng.hpp"
#include "dcel/graph.hpp"

namespace dcel::gen::detail {

[[nodiscard]] PlanarGraph random_segments(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph triangulation(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph tree(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph grid_with_holes(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph nested_polygons(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph comb(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph star(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph collinear_chain(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph components(Rng& rng, std::size_t n);
[[nodiscard]] PlanarGraph near_degenerate(Rng& rng, std::size_t n);

// A small primitive integer direction (gcd 1), uniformly from a fixed list.
struct Step {
    std::int64_t dx;
    std::int64_t dy;
};
[[nodiscard]] Step random_direction(Rng& rng);

[[nodiscard]] inline Point at(std::int64_t x, std::int64_t y) { return {static_cast<double>(x), static_cast<double>(y)}; }

// Appends the point p to g; returns its id.
inline VertexId add_vertex(PlanarGraph& g, Point p) {
    g.vertices.push_back(p);
    return VertexId(static_cast<Index>(g.vertices.size() - 1));
}

// floor(sqrt(n)), exactly.
[[nodiscard]] std::int64_t isqrt(std::size_t n);

// The side of a square of lattice points for n random points: tight (about
// as many lattice points as vertices: collinear triples, shared directions
// and touching candidates everywhere), three times looser, or 64 times
// (general position). side^2 >= n always.
[[nodiscard]] std::int64_t point_square(Rng& rng, std::size_t n);

// n distinct lattice points in [0, side)^2 in random order (side^2 >= n).
// O(n) expected.
[[nodiscard]] std::vector<Point> distinct_points(Rng& rng, std::size_t n, std::int64_t side);

// A triangulation of the points' convex hull (collinear points included) by
// a sweep in lexicographic order, as index pairs. O(n log n).
[[nodiscard]] std::vector<GraphEdge> sweep_triangulation(const std::vector<Point>& points);

// A simple polygon through all the points (n >= 3, not all collinear), made
// of two lexicographically monotone chains; a path through them all when
// they are collinear. O(n log n).
[[nodiscard]] std::vector<GraphEdge> monotone_polygon(const std::vector<Point>& points);

// Adds isolated vertices until the builder holds n: random free points
// inside the graph's bounding box first, then a row above it, where nothing
// can be in the way.
void fill_with_isolated(GraphBuilder& b, Rng& rng, std::size_t n);

}  // namespace dcel::gen::detail
