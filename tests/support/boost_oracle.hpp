// Boost.Graph as an oracle for the faces, with its semantics spelled out
// (see ../shared/NOTES.md):
//  - planar_face_traversal walks each vertex's edges in the order the
//    embedding lists them. We list them clockwise, sorted by our own simple
//    comparator (exact_oracle's angle_order: quadrant, then a cross product in
//    integers or rationals), never by the library's compare_angle. Arriving
//    at w along e, Boost continues with the edge after e in w's list, which is
//    the library's next rule, so each Boost face is one boundary cycle walked
//    in the same direction.
//  - It knows nothing of holes: every component reports its own outer walk,
//    which is exactly the library's hole cycle. So we compare boundary
//    cycles, never faces; hole placement has its own geometric oracle.
//  - It skips isolated vertices (they lie on no cycle), and it needs an
//    explicit edge_index.
//  - Boyer-Myrvold finds *an* embedding, not the geometric one, so it only
//    serves for planarity and for counting faces.
#pragma once

#include <cstddef>
#include <vector>

#include "dcel/graph.hpp"

namespace dcel::props {

using VertexCycle = std::vector<Index>;  // origin vertices in walk order

// Rotated so the smallest vertex id comes first (among equal ones, the
// lexicographically smallest rotation).
[[nodiscard]] VertexCycle canonical_cycle(VertexCycle c);

// Every boundary cycle of the geometric embedding, from Boost's
// planar_face_traversal over our clockwise rotation system; canonical, sorted.
[[nodiscard]] std::vector<VertexCycle> boost_face_cycles(const PlanarGraph& g);

struct BoyerMyrvoldAnswer {
    bool planar = false;
    std::size_t faces = 0;       // planar_face_traversal faces over Boyer-Myrvold's embedding
    std::size_t components = 0;  // connected components with at least one edge
};
[[nodiscard]] BoyerMyrvoldAnswer boyer_myrvold(const PlanarGraph& g);

}  // namespace dcel::props
