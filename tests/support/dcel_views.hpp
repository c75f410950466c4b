// Read-only views of a built DCEL for the properties and the fuzz harnesses:
// its boundary cycles as vertex sequences, and its faces as vertex-id shapes
// (oracles/shapes.hpp) that can be renamed or mirrored to compare two DCELs
// of related graphs.
#pragma once

#include <vector>

#include "dcel/dcel.hpp"
#include "oracles/shapes.hpp"

namespace dcel::test_support {

// Every boundary cycle (origin vertices in next order), canonical, sorted.
[[nodiscard]] std::vector<oracle::Cycle> dcel_cycles(const Dcel& d);

// The faces of d with every vertex id v replaced by rename[v]; when
// `reverse` is set, every cycle is also reversed (what mirroring does).
[[nodiscard]] std::vector<oracle::FaceShape> face_shapes_renamed(const Dcel& d, const std::vector<Index>& rename,
                                                                 bool reverse = false);

// The vertices of the cycle through h, in next order.
[[nodiscard]] std::vector<Point> cycle_points(const Dcel& d, HalfEdgeId h);

}  // namespace dcel::test_support
