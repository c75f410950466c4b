// validate(): does a DcelDump describe the correct DCEL of its own geometry?
//
// One named checker per invariant. Each returns the first violation it finds
// (with the ids involved) or nothing. They never trust what they check: the
// first ones use raw index loops with range checks, and every walk is capped.
// validate() runs them in dependency order and stops at the first violation;
// validate_all() runs every checker whose prerequisites hold and returns the
// first violation of each.
//
// Combinatorial invariants:
//   References      every stored id is in range (or null where null is allowed)
//   Twin            twin is an involution without fixed points
//   NextPrev        prev(next(h)) == h, so next is a permutation and prev its inverse
//   NextOrigin      origin(next(h)) == origin(twin(h)), the target of h
//   FaceOnCycle     face(next(h)) == face(h)
//   VertexOut       origin(out(v)) == v, and out(v) is null exactly when v has no edges
//   FaceRecords     every cycle is named by exactly one face record, as its outer
//                   or as an inner cycle, with matching face ids; exactly one face
//                   (the unbounded one) has no outer cycle
//   IsolatedVertices every vertex without edges is listed in exactly one face, and
//                   only such vertices are listed
// Geometric invariants (exact):
//   Embedding       points are distinct; edges meet only at shared endpoints
//   Rotation        around each vertex, next(twin(h)) steps through all outgoing
//                   half-edges in strictly clockwise angular order, one full turn
//   Orientation     outer cycles of bounded faces have positive area; inner
//                   cycles (a component's outer boundary) have area <= 0
//   HolePlacement   each component's outer boundary and each isolated vertex
//                   sits in the face that geometrically contains it
// The geometric checkers decide with validate()'s own code (src/dcel/validate/:
// embedding.cpp and segment_sweep.cpp, a sweep of its own), never build()'s,
// so that a bug in build()'s sweep cannot pass build()'s dumps here too.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/dump.hpp"

namespace dcel {

enum class Invariant {
    References,
    Twin,
    NextPrev,
    NextOrigin,
    FaceOnCycle,
    VertexOut,
    FaceRecords,
    IsolatedVertices,
    Embedding,
    Rotation,
    Orientation,
    HolePlacement,
};

[[nodiscard]] const char* to_string(Invariant invariant);

struct Violation {
    Invariant invariant;
    std::string message;  // one line, naming the ids (v3, h7, f2)
    std::vector<VertexId> vertices;
    std::vector<HalfEdgeId> half_edges;
    std::vector<FaceId> faces;
};

using CheckResult = std::optional<Violation>;

// The checkers, in the order validate() runs them. Each assumes the ones
// before it passed.
[[nodiscard]] CheckResult check_references(const DcelDump& d);
[[nodiscard]] CheckResult check_twin(const DcelDump& d);
[[nodiscard]] CheckResult check_next_prev(const DcelDump& d);
[[nodiscard]] CheckResult check_next_origin(const DcelDump& d);
[[nodiscard]] CheckResult check_face_on_cycle(const DcelDump& d);
[[nodiscard]] CheckResult check_vertex_out(const DcelDump& d);
[[nodiscard]] CheckResult check_face_records(const DcelDump& d);
[[nodiscard]] CheckResult check_isolated_vertices(const DcelDump& d);
[[nodiscard]] CheckResult check_embedding(const DcelDump& d);
[[nodiscard]] CheckResult check_rotation(const DcelDump& d);
[[nodiscard]] CheckResult check_orientation(const DcelDump& d);
[[nodiscard]] CheckResult check_hole_placement(const DcelDump& d);

[[nodiscard]] CheckResult validate(const DcelDump& d);
[[nodiscard]] CheckResult validate(const Dcel& d);
[[nodiscard]] std::vector<Violation> validate_all(const DcelDump& d);

}  // namespace dcel
