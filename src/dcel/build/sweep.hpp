// A plane sweep (Shamos-Hoey) over the edges of a graph, in O((V+E) log(V+E)).
//
// It answers two questions in one pass:
//  - do any two edges meet other than at a shared endpoint? (a crossing, a
//    vertex inside an edge, or a collinear overlap), and
//  - for chosen vertices, which edge lies directly below the vertex (the
//    first edge hit by a ray shot straight down, ties broken by the sweep's
//    slightly tilted line: an edge passing through a point directly below).
// The second is how build() places holes: a component's lowest-then-leftmost
// vertex sees the face that contains the whole component above that edge.
//
// Preconditions (build() checks them first): finite, pairwise distinct
// points; valid, non-loop, non-duplicate edges; no two edges leaving one
// vertex in the same direction.
#pragma once

#include <span>
#include <vector>

#include "dcel/build/rank_graph.hpp"
#include "dcel/graph.hpp"
#include "dcel/ids.hpp"

namespace dcel::detail {

struct SweepInput {
    const PlanarGraph& graph;
    std::span<const VertexId> lex_order;  // every vertex, sorted by lex_less
    // The half-edges leaving vertex v are ring[ring_offset[v] .. ring_offset[v+1]),
    // sorted counterclockwise from east (as compare_angle orders them).
    std::span<const Index> ring_offset;
    std::span<const HalfEdgeId> ring;
    std::span<const char> wanted;  // wanted[v]: report the edge below v
};

// Returns below[v] for each wanted vertex (null: nothing below). When
// check_intersections is set, throws InvalidInput (Crossing, VertexOnEdge or
// Overlap) naming the first offending pair the sweep meets. When it is not
// set and edges do intersect, the answers are unspecified, but the sweep
// stays memory safe and terminates.
[[nodiscard]] std::vector<EdgeId> sweep(const SweepInput& in, bool check_intersections);

// The same sweep on a graph in rank form (what build() uses). For each rank r
// with wanted[r] set, below[r] becomes the slot of the left-to-right
// half-edge of the edge below (kNoIndex: nothing below); other entries are
// left alone. `graph` is the input, used only to word error messages.
//
// When `in_status` is not empty, only the edges of ranks r with in_status[r]
// set enter the status (a set closed under edges: whole components), and
// the other ranks are only located, when wanted: `below` then answers for
// the sub-graph of those edges. Requires !check_intersections (the skipped
// edges are not checked).
void sweep_ranks(const RankGraph& rg, const PlanarGraph& graph, std::span<const char> wanted, std::span<Index> below,
                 bool check_intersections, std::span<const char> in_status = {});

}  // namespace dcel::detail
