// Formatting of numbers and ids for messages and output. Doubles are written
// in the shortest form that reads back to the same value.
#pragma once

#include <string>

#include "dcel/geometry/point.hpp"
#include "dcel/graph.hpp"

namespace dcel {

[[nodiscard]] std::string format_double(double v);
[[nodiscard]] std::string format_point(Point p);  // "(x, y)"
// "edge 3 [u, v] from (ux, uy) to (vx, vy)"
[[nodiscard]] std::string describe_edge(const PlanarGraph& g, EdgeId e);
// "vertex 4 (x, y)"
[[nodiscard]] std::string describe_vertex(const PlanarGraph& g, VertexId v);

}  // namespace dcel
