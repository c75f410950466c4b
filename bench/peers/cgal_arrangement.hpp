// Peer: CGAL's Arrangement_2 on the exact kernel (EPECK), built with the
// sweep for non-intersecting curves (insert_non_intersecting_curves, and its
// empty-arrangement form that also takes the isolated points). It places
// holes and isolated vertices, as dcel does, but does not check crossings.
// Built only when find_package(CGAL) succeeds.
#pragma once

#include "dcel/graph.hpp"
#include "peers/cycles.hpp"

namespace dcel::bench {

// Builds the arrangement; with want_cycles, also reads back every boundary
// cycle (outer and inner CCBs of every face) as input vertex ids.
[[nodiscard]] PeerResult cgal_cycles(const PlanarGraph& g, bool want_cycles);

}  // namespace dcel::bench
