// The one check that both the queries (stab) and the edits make of a point the
// caller gives: both coordinates finite. Internal to dcel.
#pragma once

#include <string_view>

#include "dcel/geometry/point.hpp"

namespace dcel::detail {

// Throws InvalidInput(BadCoordinate, "<operation>: the point (x, y) has a
// coordinate that is not finite").
void require_finite(Point p, std::string_view operation);

}  // namespace dcel::detail
