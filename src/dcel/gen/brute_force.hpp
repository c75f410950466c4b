// Brute-force validity checks for generated graphs, independent of build()
// and its plane sweep: every pair of edges and every vertex-edge pair is
// tested directly, O(V E + E^2), with the library's exact orient2d. The
// generated graphs are checked again by the independent oracles
// (tests/oracles/, used by the properties and the fuzz harnesses), so a bug
// in orient2d that let a generator accept a bad graph would show there.
#pragma once

#include <optional>
#include <string>

#include "dcel/geometry/point.hpp"
#include "dcel/graph.hpp"

namespace dcel::gen {

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
