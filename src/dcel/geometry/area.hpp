// Signed area of a closed polygon given edge by edge: counterclockwise is
// positive. `visit(f)` must call f(a, b) once for every directed edge a->b.
//
// polygon_area_sign is exact: a floating-point shoelace sum with a proven
// error bound decides most polygons; ExactSum decides the rest.
// polygon_twice_area is 2 * area from ExactSum, rounded once to a double.
#pragma once

#include <cmath>
#include <cstddef>

#include "dcel/geometry/exact_sum.hpp"
#include "dcel/geometry/point.hpp"
#include "dcel/geometry/sign.hpp"

namespace dcel::detail {

template <class Visit>
[[nodiscard]] double polygon_twice_area(Visit&& visit) {
    ExactSum sum;
    visit([&](Point a, Point b) {
        sum.add_product(a.x, b.y);
        sum.subtract_product(a.y, b.x);
    });
    return sum.to_double();
}

template <class Visit>
[[nodiscard]] Sign polygon_area_sign(Visit&& visit) {
    double sum = 0;
    double magnitude = 0;
    std::size_t n = 0;
    visit([&](Point a, Point b) {
        const double l = a.x * b.y;
        const double r = a.y * b.x;
        sum += l - r;
        magnitude += std::fabs(l) + std::fabs(r);
        ++n;
    });
    // Each term carries at most 2 eps relative error and recursive summation
    // adds gamma_{n-1}; (n + 2) eps covers both, and the factor 1.0001 covers
    // the rounding of `magnitude` and of the bound itself for n < 1e10. Above
    // 2^-900 the absolute error of an underflowing product is negligible.
    const double bound = (static_cast<double>(n) + 2.0) * 0x1p-53 * magnitude * 1.0001;
    if (magnitude >= 0x1p-900 && std::isfinite(magnitude) && std::fabs(sum) > bound) return sign_of(sum);
    ExactSum exact;
    visit([&](Point a, Point b) {
        exact.add_product(a.x, b.y);
        exact.subtract_product(a.y, b.x);
    });
    return exact.sign();
}

}  // namespace dcel::detail
