// build(): a PlanarGraph in, its complete DCEL out, or InvalidInput.
//
// Cost: O((V + E) log(V + E)) time and O(V + E) memory. Sorting the vertices
// (duplicate points, sweep order) and each vertex's outgoing half-edges
// (exact angular order) is O(V log V + E log d); the plane sweep that rejects
// crossings and places holes is O((V + E) log(V + E)); the rest is linear.
#pragma once

#include "dcel/dcel.hpp"
#include "dcel/graph.hpp"

namespace dcel {

struct BuildOptions {
    // Reject crossings, vertices inside edges and collinear overlaps. When
    // false, the caller promises the edges do not meet except at shared
    // endpoints: the sweep then runs only to place holes (and not at all for a
    // connected graph). Every other check (coordinates, indexes, duplicate
    // points and edges, two edges leaving a vertex in one direction) always
    // runs. On input that breaks the promise the result is unspecified but the
    // call is memory safe and terminates.
    bool check_crossings = true;
};

// Throws InvalidInput naming the offending vertices and edges.
[[nodiscard]] Dcel build(const PlanarGraph& graph, const BuildOptions& options = {});

}  // namespace dcel
