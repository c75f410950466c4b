// Around every vertex, next(twin(h)) must visit all outgoing half-edges in
// clockwise angular order, as sorted by the oracle's own comparator.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>

#include "dcel/build.hpp"
#include "oracles/exact.hpp"
#include "support/graph_case.hpp"

namespace dcel::props {
namespace {

RC_GTEST_PROP(Rotation, prop_next_of_twin_turns_clockwise_through_all_outgoing, ()) {
    const GraphCase c = *graphs();
    const PlanarGraph& g = c.graph;
    const Dcel d = build(g);
    // Outgoing half-edges per vertex, from the input: 2k leaves u, 2k+1 leaves v.
    std::vector<std::vector<Index>> out(g.vertices.size());
    std::vector<VertexId> head(2 * g.edges.size());
    for (Index k = 0; k < g.edges.size(); ++k) {
        out[g.edges[k].u.index()].push_back(2 * k);
        out[g.edges[k].v.index()].push_back(2 * k + 1);
        head[2 * k] = g.edges[k].v;
        head[2 * k + 1] = g.edges[k].u;
    }
    for (Index v = 0; v < g.vertices.size(); ++v) {
        std::vector<Index> ring = out[v];
        if (ring.empty()) continue;
        const Point centre = g.vertices[v];
        // Clockwise = descending counterclockwise angle.
        std::sort(ring.begin(), ring.end(), [&](Index a, Index b) {
            return oracle::angle_order(centre, g.vertices[head[a].index()], g.vertices[head[b].index()]) > 0;
        });
        HalfEdgeId h(ring[0]);
        for (std::size_t i = 1; i <= ring.size(); ++i) {
            h = d.next(Dcel::twin(h));
            RC_ASSERT(h == HalfEdgeId(ring[i % ring.size()]));
        }
    }
}

}  // namespace
}  // namespace dcel::props
