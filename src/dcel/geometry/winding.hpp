// The winding number of a closed walk around a point, decided exactly.
//
// `visit(f)` must call f(a, b) once for every directed edge a -> b of the
// walk. The walk may revisit vertices and run along an edge and back (a face
// boundary with dangling edges): such back-and-forth parts cancel. The point
// must not lie on the walk. For a face's outer cycle the result is 1 inside
// and 0 outside; for a hole's cycle, -1 inside and 0 outside.
//
// Sunday's crossing rule: count upward crossings of the ray going east from
// q with q on the left, minus downward ones with q on the right. Half-open
// y-ranges make a ray through a vertex count once; orient2d decides sides.
#pragma once

#include "dcel/geometry/point.hpp"
#include "dcel/geometry/predicates.hpp"

namespace dcel::detail {

template <class Visit>
[[nodiscard]] int winding_number(Point q, Visit&& visit) {
    int w = 0;
    visit([&](Point a, Point b) {
        if (a.y <= q.y) {
            if (b.y > q.y && orient2d(a, b, q) == Sign::Positive) ++w;
        } else if (b.y <= q.y && orient2d(a, b, q) == Sign::Negative) {
            --w;
        }
    });
    return w;
}

}  // namespace dcel::detail
