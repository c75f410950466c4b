// The input: a planar straight-line graph given as points and index pairs.
#pragma once

#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/ids.hpp"

namespace dcel {

// An undirected edge between two vertices; edge k of the input becomes the
// half-edges 2k (u->v) and 2k+1 (v->u).
struct GraphEdge {
    VertexId u;
    VertexId v;
    friend bool operator==(const GraphEdge&, const GraphEdge&) = default;
};

struct PlanarGraph {
    std::vector<Point> vertices;
    std::vector<GraphEdge> edges;
};

// The ends of half-edge h of g, by that numbering (h must be < 2 * edges).
[[nodiscard]] inline VertexId graph_origin(const PlanarGraph& g, HalfEdgeId h) {
    const GraphEdge& e = g.edges[h.index() >> 1U];
    return (h.index() & 1U) == 0 ? e.u : e.v;
}
[[nodiscard]] inline VertexId graph_target(const PlanarGraph& g, HalfEdgeId h) { return graph_origin(g, twin(h)); }

}  // namespace dcel
