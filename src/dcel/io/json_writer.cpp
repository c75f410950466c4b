#include "dcel/io/json_writer.hpp"

#include "dcel/error.hpp"

namespace dcel::io {

void fail_not_finite(const std::string& path, double v) {
    const char* what = std::isnan(v) ? "NaN" : (v > 0 ? "Infinity" : "-Infinity");
    throw InvalidInput(InputErrorKind::BadCoordinate,
                       path + ": " + what + " cannot be written as JSON: coordinates must be finite numbers");
}

}  // namespace dcel::io
