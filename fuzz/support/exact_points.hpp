// Exact geometry for the oracles, independent of src/dcel/geometry.
//
// Every finite double is m * 2^e with an integer m. Scaling all coordinates
// of a graph by one power of two, 2^-emin, turns them into big integers
// (boost::multiprecision::cpp_int) without rounding, and every predicate the
// oracles need (orientation, comparisons, signed areas, winding numbers) is
// then plain integer arithmetic. Slow (coordinates of up to ~2100 bits), but
// the harnesses cap the input size, and it shares no code or idea with the
// library's filtered predicates.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>
#include <vector>

#include "dcel/geometry/point.hpp"

namespace dcel::fuzz {

using BigInt = boost::multiprecision::cpp_int;

struct ExactPoint {
    BigInt x;
    BigInt y;
    friend bool operator==(const ExactPoint&, const ExactPoint&) = default;
};

// All coordinates must be finite. Equal doubles (0.0 and -0.0 included) give
// equal exact points, and order is preserved.
[[nodiscard]] std::vector<ExactPoint> exact_points(const std::vector<Point>& points);

// Sign (-1, 0, +1) of the cross product (b - a) x (c - a): +1 when a, b, c
// turn counterclockwise.
[[nodiscard]] int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c);

// Is p on the closed segment ab and different from both endpoints? (a != b)
[[nodiscard]] bool strictly_between(const ExactPoint& a, const ExactPoint& b, const ExactPoint& p);

}  // namespace dcel::fuzz
