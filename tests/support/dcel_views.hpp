// Read-only views of a built DCEL for the properties and the fuzz harnesses:
// its boundary cycles as vertex sequences, and its faces as vertex-id shapes
// (face_shapes.hpp's FaceShape) that can be renamed or mirrored to compare
// two DCELs of related graphs.
#pragma once

#include <vector>

#include "dcel/dcel.hpp"
#include "support/boost_oracle.hpp"
#include "support/face_shapes.hpp"

namespace dcel::props {

// Every boundary cycle (origin vertices in next order), canonical, sorted.
[[nodiscard]] std::vector<VertexCycle> dcel_cycles(const Dcel& d);

// The faces of d with every vertex id v replaced by rename[v]; when
// `reverse` is set, every cycle is also reversed (what mirroring does).
[[nodiscard]] std::vector<testing::FaceShape> face_shapes_renamed(const Dcel& d, const std::vector<Index>& rename,
                                                                  bool reverse = false);

// The vertices of the cycle through h, in next order.
[[nodiscard]] std::vector<Point> cycle_points(const Dcel& d, HalfEdgeId h);

}  // namespace dcel::props
