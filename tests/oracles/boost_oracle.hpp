// Boost.Graph as an oracle for the faces, with its semantics spelled out:
//  - planar_face_traversal walks each vertex's edges in the order the
//    embedding lists them. We list them clockwise, sorted by the oracles'
//    own comparator (exact.hpp's angle_order), never by the library's
//    compare_angle. Arriving at w along e, Boost continues with the edge
//    after e in w's list, which is the library's next rule, so each Boost
//    face is one boundary cycle walked in the same direction.
//  - It knows nothing of holes: every component reports its own outer walk,
//    which is exactly the library's hole cycle. So we compare boundary
//    cycles, never faces; hole placement has its own oracle
//    (reference_dcel.hpp).
//  - It skips isolated vertices (they lie on no cycle), and it needs an
//    explicit edge_index.
//  - Boyer-Myrvold finds *an* embedding, not the geometric one, so it only
//    serves for planarity and for counting faces.
#pragma once

#include <cstddef>
#include <vector>

#include "dcel/graph.hpp"
#include "oracles/rotations.hpp"
#include "oracles/shapes.hpp"

namespace dcel::oracle {

// Every boundary cycle of the geometric embedding of a valid graph, from
// Boost's planar_face_traversal over our clockwise rotation system;
// canonical, sorted.
[[nodiscard]] std::vector<Cycle> boost_face_cycles(const PlanarGraph& g);
// The same over g's rotation system sorted already: rotation_system(half_edges_of(g)).
[[nodiscard]] std::vector<Cycle> boost_face_cycles(const PlanarGraph& g, const Rotations& rotations);

struct BoyerMyrvoldAnswer {
    bool planar = false;
    std::size_t faces = 0;       // planar_face_traversal faces over Boyer-Myrvold's embedding
    std::size_t components = 0;  // connected components with at least one edge
};
// Any graph: edges with an end out of range are ignored, and self-loops and
// repeated edges dropped first (they never change planarity, and Boost's
// test is documented for simple graphs). Faces and components are counted
// only for a planar graph.
[[nodiscard]] BoyerMyrvoldAnswer boyer_myrvold(const PlanarGraph& g);

}  // namespace dcel::oracle
