// The half-edges around a vertex, found by direction. Internal to the
// edits and the stabbing walk.
#pragma once

#include "dcel/dcel.hpp"
#include "dcel/geometry/directions.hpp"

namespace dcel::detail {

// The outgoing half-edge of v that points in direction `dir`, or null. O(degree).
[[nodiscard]] HalfEdgeId outgoing_in_direction(const Dcel& d, VertexId v, const Direction& dir);

// For a direction `dir` out of v that no edge of v takes: the outgoing
// half-edge r such that dir lies strictly inside the wedge from cw(r) =
// next(twin(r)) counterclockwise to r. The face filling that wedge is
// face(cw(r)). Requires v to have an edge. O(degree).
[[nodiscard]] HalfEdgeId wedge_after(const Dcel& d, VertexId v, const Direction& dir);

}  // namespace dcel::detail
