// Point location: is a point at a vertex, inside an edge, or inside a face?
// Decided exactly (orient2d and coordinate comparisons only).
//
//  - locate_by_scan() (here, query/locate.cpp): no preprocessing, O(V + E)
//    per query. The simple reference answer, and what the edits use to place
//    a new vertex.
//  - PointLocator (point_locator.hpp, included here): a trapezoidal map,
//    O(log E) expected per query after O(E log E) expected preprocessing.
#pragma once

#include "dcel/dcel.hpp"
#include "dcel/location.hpp"
#include "dcel/point_locator.hpp"

namespace dcel {

// O(V + E): compares p with every vertex and edge, then finds the face whose
// outer cycle winds around p and none of whose holes does.
[[nodiscard]] Location locate_by_scan(const Dcel& d, Point p);

// The face containing the interior of the isolated vertex v (a vertex with no
// edges), by scanning the faces' lists: O(F + isolated vertices).
[[nodiscard]] FaceId face_of_isolated_vertex(const Dcel& d, VertexId v);

}  // namespace dcel
