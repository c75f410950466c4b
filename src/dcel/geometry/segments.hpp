// How two closed segments meet, decided exactly. Endpoints are compared by
// coordinates, so equal points count as a shared endpoint.
#pragma once

#include "dcel/geometry/point.hpp"

namespace dcel::detail {

enum class Contact {
    None,            // disjoint
    SharedEndpoint,  // they meet only at an endpoint of both
    Crossing,        // they meet at one point inside both
    Touch,           // an endpoint of one lies inside the other
    Overlap,         // collinear, sharing more than a point
};

[[nodiscard]] Contact segment_contact(Point a, Point b, Point c, Point d);

// Is p strictly inside segment ab (on it, and not an endpoint)?
[[nodiscard]] bool strictly_inside_segment(Point a, Point b, Point p);

}  // namespace dcel::detail
