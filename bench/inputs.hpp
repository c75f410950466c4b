// The benchmark inputs, generated in the project (none stored). Every
// generator is deterministic in its arguments (own PRNG) and returns a valid
// planar straight-line graph with integer coordinates.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dcel/graph.hpp"

namespace dcel::bench {

// The Delaunay triangulation of n distinct random integer points in a square
// of side about 4 sqrt(n) * 256, vertices in Hilbert-curve order and edges
// sorted by their first vertex ("spatial order"). Points that the sweep-hull
// construction leaves out (exactly on a hull edge; rare) are dropped.
[[nodiscard]] PlanarGraph delaunay(std::size_t n, std::uint64_t seed);

// The same graph with a random permutation of vertex ids, of edge order and
// of each edge's orientation.
[[nodiscard]] PlanarGraph shuffled(const PlanarGraph& g, std::uint64_t seed);

// A w x h grid of unit squares' corners, row-major, with all horizontal and
// vertical edges: 2wh - w - h edges.
[[nodiscard]] PlanarGraph grid(std::size_t w, std::size_t h);

// One centre and `degree` leaves on the boundary of a square around it, all
// in distinct directions; leaves in angular order.
[[nodiscard]] PlanarGraph star(std::size_t degree);

// n concentric squares: every square but the innermost has one hole.
[[nodiscard]] PlanarGraph nested_squares(std::size_t n);

// n collinear points on a slanted line, joined as one chain.
[[nodiscard]] PlanarGraph collinear_chain(std::size_t n);

// Random sparse forests with many components: a jittered w x w grid of
// points, each grid edge kept with probability 1/2 unless it closes a cycle.
// Many trees, some isolated vertices, all holes of the unbounded face.
[[nodiscard]] PlanarGraph forest(std::size_t w, std::uint64_t seed);

}  // namespace dcel::bench
