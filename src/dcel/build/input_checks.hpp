// The checks every input graph passes before any face is built. build() runs
// them, and validate() runs them on the graph underlying a foreign dump.
// Each throws InvalidInput naming the offending elements.
#pragma once

#include <vector>

#include "dcel/graph.hpp"
#include "dcel/ids.hpp"

namespace dcel::detail {

// Sizes fit 32-bit ids, coordinates are finite, indexes are in range, no
// self-loops. O(V + E).
void check_elements(const PlanarGraph& g);

// All vertices sorted by lex_less (the sweep order); throws DuplicatePoint
// when two share a point. O(V log V).
[[nodiscard]] std::vector<VertexId> sort_vertices_checked(const PlanarGraph& g);

// Half-edge 2k runs u->v along input edge k, 2k+1 runs back. The half-edges
// leaving v are ring[offset[v] .. offset[v+1]), in exact counterclockwise
// order starting from east. Throws DuplicateEdge or Overlap when two leave v
// in the same direction. O(E log d) for maximum degree d.
struct Rings {
    std::vector<Index> offset;
    std::vector<HalfEdgeId> ring;
};
[[nodiscard]] Rings sort_rings_checked(const PlanarGraph& g);

}  // namespace dcel::detail
