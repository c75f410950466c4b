#include "dcel/core/finite.hpp"

#include <cmath>
#include <string>

#include "dcel/error.hpp"
#include "dcel/format.hpp"

namespace dcel::detail {

void require_finite(Point p, std::string_view operation) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        std::string s(operation);
        s.append(": the point ").append(format_point(p)).append(" has a coordinate that is not finite");
        throw InvalidInput(InputErrorKind::BadCoordinate, s);
    }
}

}  // namespace dcel::detail
