// The graph renumbered in sweep order, with each vertex's ring of outgoing
// half-edges sorted: the working form of build() and of the sweep.
//
// Vertex ranks follow lex_less, so the vertices of one ring and of one face
// sit close together in every array, whatever order the input came in: the
// later passes read memory almost sequentially. The half-edges keep their
// input ids (edge k owns 2k and 2k+1); a slot is a position in the rings.
#pragma once

#include <span>
#include <vector>

#include "dcel/build/lex_order.hpp"
#include "dcel/geometry/point.hpp"
#include "dcel/graph.hpp"
#include "dcel/ids.hpp"

namespace dcel::detail {

struct RankGraph {
    std::vector<Point> point;           // point[r]: the coordinates of the vertex of rank r
    std::vector<VertexId> vertex;       // vertex[r]: its input id
    std::vector<Index> offset;          // the ring of r is the slots offset[r] .. offset[r+1]
    std::vector<HalfEdgeId> half_edge;  // half_edge[s]: leaves the ring's vertex; CCW from east
    std::vector<Index> target;          // target[s]: the rank it goes to

    [[nodiscard]] Index num_vertices() const { return static_cast<Index>(vertex.size()); }
    [[nodiscard]] Index num_slots() const { return static_cast<Index>(half_edge.size()); }
    [[nodiscard]] Index degree(Index r) const { return offset[r + 1] - offset[r]; }
    // The slot just clockwise of slot s around its vertex r.
    [[nodiscard]] Index clockwise(Index r, Index s) const { return s == offset[r] ? offset[r + 1] - 1 : s - 1; }
    // The slot just counterclockwise of slot s around its vertex r.
    [[nodiscard]] Index counterclockwise(Index r, Index s) const { return s + 1 == offset[r + 1] ? offset[r] : s + 1; }

    // Rings up to this size are scanned; they sit next to their
    // neighbours' rings in memory, so a scan is a few cached reads.
    static constexpr Index kSmallRing = 16;
    [[nodiscard]] bool small(Index r) const { return degree(r) <= kSmallRing; }
    // The slot of t's ring whose half-edge goes to r; the edge must exist.
    // A scan for a small ring, else a binary search by exact angle (a
    // ring's directions are distinct). O(min(d, log d)).
    [[nodiscard]] Index slot_towards(Index t, Index r) const {
        if (!small(t)) return search_towards(t, r);
        Index x = offset[t];
        while (target[x] != r) ++x;
        return x;
    }
    [[nodiscard]] Index search_towards(Index t, Index r) const;  // the binary search
};

// Rings from a graph that passed check_elements, in the order `lex` gives.
// Throws DuplicateEdge or Overlap when two half-edges leave a vertex in the
// same direction, for the smallest such vertex id (as sort_rings_checked).
// O(V + E) plus the ring sorts, O(E log d) for maximum degree d. Consumes
// lex.rank_of_vertex (freed: the caller no longer needs it).
[[nodiscard]] RankGraph rank_graph_checked(const PlanarGraph& g, LexOrder&& lex);

// The same from rings already sorted in input-vertex space (used by the
// sweep's adapter for validate()). No checks.
[[nodiscard]] RankGraph rank_graph_from_rings(const PlanarGraph& g, std::span<const VertexId> lex_order,
                                              std::span<const Index> ring_offset, std::span<const HalfEdgeId> ring);

// Throws the DuplicateEdge or Overlap error for half-edges a and b, which
// leave v in the same direction.
[[noreturn]] void throw_same_direction(const PlanarGraph& g, VertexId v, HalfEdgeId a, HalfEdgeId b);

}  // namespace dcel::detail
