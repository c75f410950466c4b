#include "dcel/input_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel {
namespace {

[[noreturn]] void throw_same_direction(const PlanarGraph& g, VertexId v, HalfEdgeId a, HalfEdgeId b) {
    const EdgeId lo = std::min(edge_of(a), edge_of(b));
    const EdgeId hi = std::max(edge_of(a), edge_of(b));
    const VertexId ta = graph_target(g, a);
    if (ta == graph_target(g, b)) {
        throw InvalidInput(InputErrorKind::DuplicateEdge,
                           "edges " + std::to_string(lo.index()) + " and " + std::to_string(hi.index()) +
                               " both join vertices " + std::to_string(std::min(v, ta).index()) + " and " +
                               std::to_string(std::max(v, ta).index()) + "; remove one of them",
                           {v, ta}, {lo, hi});
    }
    throw InvalidInput(InputErrorKind::Overlap,
                       describe_edge(g, lo) + " and " + describe_edge(g, hi) + " overlap: both leave vertex " +
                           std::to_string(v.index()) + " in the same direction; merge them into one chain of edges",
                       {v}, {lo, hi});
}

}  // namespace

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
                                       " is out of range (there are " + std::to_string(n) +
                                       " vertices, numbered from 0)",
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

std::vector<VertexId> sort_vertices_checked(const PlanarGraph& g) {
    const auto n = static_cast<Index>(g.vertices.size());
    std::vector<VertexId> order(n);
    for (Index v = 0; v < n; ++v) order[v] = VertexId(v);
    // Ties broken by id, so equal points end up adjacent, smaller id first.
    std::sort(order.begin(), order.end(), [&](VertexId a, VertexId b) {
        const Point pa = g.vertices[a.index()];
        const Point pb = g.vertices[b.index()];
        if (lex_less(pa, pb)) return true;
        if (lex_less(pb, pa)) return false;
        return a < b;
    });
    for (std::size_t i = 1; i < order.size(); ++i) {
        const VertexId a = order[i - 1];
        const VertexId b = order[i];
        if (g.vertices[a.index()] == g.vertices[b.index()]) {
            throw InvalidInput(InputErrorKind::DuplicatePoint,
                               "vertices " + std::to_string(a.index()) + " and " + std::to_string(b.index()) +
                                   " are at the same point " + format_point(g.vertices[a.index()]) +
                                   "; merge them into one vertex",
                               {a, b});
        }
    }
    return order;
}

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

    for (Index v = 0; v < n; ++v) {
        const auto first = r.ring.begin() + r.offset[v];
        const auto last = r.ring.begin() + r.offset[v + 1];
        const Point c = g.vertices[v];
        auto direction = [&](HalfEdgeId h) { return g.vertices[graph_target(g, h).index()]; };
        std::sort(first, last, [&](HalfEdgeId a, HalfEdgeId b) {
            const Sign s = compare_angle(c, direction(a), direction(b));
            return s == Sign::Zero ? a < b : s == Sign::Negative;
        });
        // adjacent_find never forms first + 1 on an empty ring (a null
        // pointer when the graph has no edges: undefined behaviour).
        const auto same = std::adjacent_find(first, last, [&](HalfEdgeId a, HalfEdgeId b) {
            return compare_angle(c, direction(a), direction(b)) == Sign::Zero;
        });
        if (same != last) throw_same_direction(g, VertexId(v), *same, *(same + 1));
    }
    return r;
}

}  // namespace dcel
