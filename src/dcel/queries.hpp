// Read-side queries on a built Dcel. Costs are per call.
#pragma once

#include <vector>

#include "dcel/dcel.hpp"
#include "dcel/geometry/sign.hpp"

namespace dcel {

// An area whose sign is exact; value is the exact area rounded once to a
// double (it may overflow to +-inf for coordinates near the double limit).
struct Area {
    double value = 0;
    Sign sign = Sign::Zero;
};

// Signed area of the boundary cycle through h (counterclockwise positive).
// O(length of the cycle).
[[nodiscard]] Area cycle_area(const Dcel& d, HalfEdgeId h);

// Area of a bounded face: its outer cycle's area minus the areas enclosed by
// its holes. Always positive for a valid DCEL. For the unbounded face:
// {+inf, Positive}. O(total length of the face's cycles).
[[nodiscard]] Area face_area(const Dcel& d, FaceId f);

// The faces across the edges of f's boundary cycles (outer and holes), each
// once, sorted by id, f itself excluded (a dangling edge has f on both
// sides). The "which countries border Switzerland" query. O(boundary size).
[[nodiscard]] std::vector<FaceId> neighbours(const Dcel& d, FaceId f);

// The faces met walking counterclockwise around v, starting with the face of
// out(v); a face appears once per wedge it fills. For an isolated vertex, the
// face containing it. O(degree), or O(F + isolated vertices) when isolated.
[[nodiscard]] std::vector<FaceId> faces_around(const Dcel& d, VertexId v);

// Every boundary cycle as its origin vertices in next order, starting from
// its smallest half-edge; cycles in order of that half-edge. O(E).
[[nodiscard]] std::vector<std::vector<VertexId>> boundary_cycles(const Dcel& d);

// The number of connected components, isolated vertices included: V - E + F - 1
// by Euler's formula for a valid DCEL. O(1).
[[nodiscard]] std::size_t count_components(const Dcel& d);

}  // namespace dcel
