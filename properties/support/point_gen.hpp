// RapidCheck generators of points and point triples for the predicate
// properties: random, and adversarial (exactly or nearly collinear, large
// offsets with tiny differences, tiny magnitudes and subnormals, -0.0,
// values near DBL_MAX whose differences overflow, Kettner et al.'s points
// near a diagonal).
#pragma once

#include <rapidcheck.h>

#include <array>
#include <ostream>

#include "dcel/geometry/point.hpp"

namespace dcel::props {

struct Triple {
    std::array<Point, 3> p;
};
void showValue(const Triple& t, std::ostream& os);

[[nodiscard]] rc::Gen<Triple> adversarial_triples();

}  // namespace dcel::props
