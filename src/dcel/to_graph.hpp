// The graph under a DCEL: its points, and edge k joining origin(2k) to
// origin(2k+1). build(to_graph(d)) gives d back, up to face numbering (and
// the choice of representative half-edges), for every valid d: this is how
// an edited DCEL is saved, and how the tests check an edit against a rebuild.
// O(V + E).
#pragma once

#include "dcel/dcel.hpp"
#include "dcel/graph.hpp"

namespace dcel {

[[nodiscard]] inline PlanarGraph to_graph(const Dcel& d) {
    PlanarGraph g;
    g.vertices = d.points();
    g.edges.reserve(d.num_edges());
    for (Index k = 0; k < d.num_edges(); ++k) {
        g.edges.push_back({d.origin(half_edge_of(EdgeId(k), 0)), d.origin(half_edge_of(EdgeId(k), 1))});
    }
    return g;
}

}  // namespace dcel
