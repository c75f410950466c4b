// The brute-force oracle for "is this a planar straight-line graph?": every
// pair of elements is compared, O(V^2 + V*E + E^2), in exact integer
// arithmetic (exact_points.hpp). It shares nothing with the library's checks
// or its sweep, and it reports every kind of defect present, not just the
// first, because build() may meet any of them first.
#pragma once

#include <bitset>
#include <string>

#include "dcel/error.hpp"
#include "dcel/graph.hpp"

namespace dcel::fuzz {

enum class Defect {
    BadIndex,        // an edge names a vertex that does not exist
    BadCoordinate,   // NaN or infinite
    DuplicatePoint,  // two vertices at one point (-0.0 == 0.0)
    SelfLoop,        // an edge from a vertex to itself
    DuplicateEdge,   // two edges joining the same two vertices, either way round
    Crossing,        // two edges cross at a point inside both
    Touch,           // a vertex lies inside an edge
    Overlap,         // two collinear edges share more than a point
    Count
};

using Defects = std::bitset<static_cast<std::size_t>(Defect::Count)>;

[[nodiscard]] inline bool has(const Defects& d, Defect k) { return d.test(static_cast<std::size_t>(k)); }
[[nodiscard]] std::string describe(const Defects& d);  // "crossing touch", or "none"

[[nodiscard]] Defects find_defects(const PlanarGraph& g);

// The defect an InvalidInput kind from build() stands for; Count for kinds
// build() never reports on a graph (Syntax, Shape, TooLarge).
[[nodiscard]] Defect defect_of(InputErrorKind kind);

}  // namespace dcel::fuzz
