// Brute-force validity checks for generated graphs, independent of build()
// and its plane sweep: every pair of edges and every vertex-edge pair is
// tested directly, O(V E + E^2). Orientation signs are exact: 128-bit integer
// arithmetic when the coordinates are small integers (the common case, and
// fast), ExactSum otherwise. The library's filtered orient2d is not used, so a
// bug in its filter cannot hide here.
#pragma once

#include <optional>
#include <string>

#include "dcel/geometry/point.hpp"
#include "dcel/geometry/sign.hpp"
#include "dcel/graph.hpp"

namespace dcel::gen {

[[nodiscard]] Sign exact_orient(Point a, Point b, Point c);

// p on the closed segment ab (a != b).
[[nodiscard]] bool on_closed_segment(Point a, Point b, Point p);

// Do closed segments ab and cd meet anywhere other than at one shared
// endpoint (a crossing, a touch, an overlap, or the same segment)?
[[nodiscard]] bool segments_conflict(Point a, Point b, Point c, Point d);

// Why g is not a valid planar straight-line graph (a one-line reason), or
// nothing when it is: finite coordinates, distinct points, indexes in range,
// no self-loops or duplicate edges, edges meet only at shared endpoints, and
// no vertex lies on an edge it is not an endpoint of.
[[nodiscard]] std::optional<std::string> find_problem(const PlanarGraph& g);

}  // namespace dcel::gen
