// Peers from Boost.Graph: planar_face_traversal on an adjacency_list.
//  - boost_geometric_cycles: the embedding is the geometric rotation system,
//    each vertex's edges in clockwise order of atan2 (Boost's traversal then
//    follows exactly dcel's next rule, so the cycles match on inputs where
//    atan2 orders directions correctly). Timed: graph + embedding + traversal.
//  - boost_bm_cycles: the embedding comes from Boyer-Myrvold planarity
//    testing instead: *an* embedding, not the geometric one (on 3-connected
//    graphs such as triangulations, the geometric one or its mirror image).
// Neither places holes nor lists isolated vertices (boostorg/graph#343).
#pragma once

#include "dcel/graph.hpp"
#include "peers/cycles.hpp"

namespace dcel::bench {

[[nodiscard]] PeerResult boost_geometric_cycles(const PlanarGraph& g, bool want_cycles);
[[nodiscard]] PeerResult boost_bm_cycles(const PlanarGraph& g, bool want_cycles);

}  // namespace dcel::bench
