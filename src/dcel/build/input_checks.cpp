#include "dcel/build/input_checks.hpp"

#include <cmath>
#include <numeric>
#include <string>

#include "dcel/build/lex_order.hpp"
#include "dcel/build/rank_graph.hpp"
#include "dcel/build/ring_sort.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"

namespace dcel::detail {

void check_elements(const PlanarGraph& g) {
    // Ids are 32 bits and kNoIndex is reserved for "null".
    if (g.vertices.size() >= kNoIndex) {
        throw InvalidInput(InputErrorKind::TooLarge,
                           std::to_string(g.vertices.size()) + " vertices is more than 32-bit ids allow");
    }
    if (g.edges.size() >= kNoIndex / 2) {
        throw InvalidInput(InputErrorKind::TooLarge,
                           std::to_string(g.edges.size()) + " edges is more than 32-bit half-edge ids allow");
    }
    const auto n = static_cast<Index>(g.vertices.size());
    for (Index v = 0; v < n; ++v) {
        const Point p = g.vertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
            throw InvalidInput(InputErrorKind::BadCoordinate,
                               "vertex " + std::to_string(v) + " has a non-finite coordinate " + format_point(p) +
                                   "; coordinates must be finite numbers",
                               {VertexId(v)});
        }
    }
    for (Index k = 0; k < g.edges.size(); ++k) {
        const GraphEdge& e = g.edges[k];
        for (const VertexId v : {e.u, e.v}) {
            if (v.index() >= n) {
                throw InvalidInput(InputErrorKind::BadIndex,
                                   "edge " + std::to_string(k) + ": vertex index " +
                                       (v.is_null() ? std::string("null") : std::to_string(v.index())) +
                                       " is out of range (there are " + std::to_string(n) + " vertices, numbered from 0)",
                                   {}, {EdgeId(k)});
            }
        }
        if (e.u == e.v) {
            throw InvalidInput(InputErrorKind::SelfLoop,
                               "edge " + std::to_string(k) + " [" + std::to_string(e.u.index()) + ", " +
                                   std::to_string(e.v.index()) + "] is a self-loop; remove it",
                               {e.u}, {EdgeId(k)});
        }
    }
}

std::vector<VertexId> sort_vertices_checked(const PlanarGraph& g) { return lex_order_checked(g.vertices).vertex_of_rank; }

Rings sort_rings_checked(const PlanarGraph& g) {
    const auto n = static_cast<Index>(g.vertices.size());
    const auto half_edges = static_cast<Index>(2 * g.edges.size());
    Rings r;
    r.offset.assign(n + 1, 0);
    for (Index h = 0; h < half_edges; ++h) ++r.offset[graph_origin(g, HalfEdgeId(h)).index() + 1];
    std::partial_sum(r.offset.begin(), r.offset.end(), r.offset.begin());
    r.ring.resize(half_edges);
    std::vector<Index> fill(r.offset.begin(), r.offset.end() - 1);
    for (Index h = 0; h < half_edges; ++h) r.ring[fill[graph_origin(g, HalfEdgeId(h)).index()]++] = HalfEdgeId(h);

    std::vector<RingEntry> ring;
    for (Index v = 0; v < n; ++v) {
        const Index first = r.offset[v];
        const Index degree = r.offset[v + 1] - first;
        ring.resize(degree);
        for (Index i = 0; i < degree; ++i) {
            const HalfEdgeId h = r.ring[first + i];
            ring[i] = RingEntry{g.vertices[graph_target(g, h).index()], h, 0, 0};
        }
        const Point centre = g.vertices[v];
        const std::size_t same = sort_ring(centre, ring);
        for (Index i = 0; i < degree; ++i) r.ring[first + i] = ring[i].half_edge;
        if (same < ring.size()) throw_same_direction(g, VertexId(v), ring[same].half_edge, ring[same + 1].half_edge);
    }
    return r;
}

}  // namespace dcel::detail
