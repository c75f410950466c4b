// The DCEL of a planar straight-line graph worked out from first principles:
// the oracle for build(), validate() and the dump judge. It shares no code
// with the library (no lex order, rank graph, sweep or filtered predicate):
//   - next(u->v) is the half-edge leaving v just clockwise of v->u, in the
//     exact angular order (exact.hpp), found by sorting each vertex's
//     half-edges once (rotations.hpp);
//   - the cycles of next, with their exact doubled signed areas;
//   - the faces: the unbounded one, plus one per counterclockwise cycle;
//   - every other cycle (a component's clockwise outer boundary) and every
//     isolated vertex belongs to the smallest counterclockwise cycle of
//     another component that winds around it, or to the unbounded face.
// The input must be a valid planar straight-line graph (brute_force.hpp);
// on anything else the answer means nothing.
#pragma once

#include <vector>

#include "dcel/geometry/point.hpp"
#include "dcel/graph.hpp"
#include "oracles/exact.hpp"
#include "oracles/rotations.hpp"
#include "oracles/shapes.hpp"

namespace dcel::oracle {

[[nodiscard]] HalfEdgeGraph half_edges_of(const PlanarGraph& g);

struct ReferenceDcel {
    std::vector<Index> next;                   // per half-edge
    std::vector<Index> cycle_of;               // per half-edge
    std::vector<std::vector<Index>> cycles;    // half-edges in next order, from the smallest
    std::vector<Rational> twice_area;          // per cycle, signed
    std::vector<Index> face_of_cycle;          // 0 is the unbounded face
    std::vector<Index> outer_cycle;            // per face; kNoIndex for face 0
    std::vector<std::vector<Index>> inner;     // per face: cycle ids, ascending
    std::vector<std::vector<Index>> isolated;  // per face: vertex ids, ascending
    std::vector<Index> face_of_vertex;         // per isolated vertex its face; kNoIndex otherwise
};

[[nodiscard]] ReferenceDcel reference_dcel(const HalfEdgeGraph& h);
// The same, from h's rotation system, when the caller has sorted it already.
[[nodiscard]] ReferenceDcel reference_dcel(const HalfEdgeGraph& h, const Rotations& rotations);
[[nodiscard]] ReferenceDcel reference_dcel(const PlanarGraph& g);

// The faces as vertex-id shapes (shapes.hpp), to compare with a DCEL's.
[[nodiscard]] std::vector<FaceShape> face_shapes(const HalfEdgeGraph& h, const ReferenceDcel& r);
[[nodiscard]] std::vector<FaceShape> reference_faces(const PlanarGraph& g);

}  // namespace dcel::oracle
