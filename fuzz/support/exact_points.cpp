#include "support/exact_points.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

namespace dcel::fuzz {
namespace {

// v = mantissa * 2^exponent with an odd mantissa (or v == 0).
struct Dyadic {
    std::int64_t mantissa = 0;
    int exponent = 0;
};

Dyadic dyadic(double v) {
    if (v == 0) return {};
    int e = 0;
    const double m = std::frexp(v, &e);  // v = m * 2^e, 0.5 <= |m| < 1, exact
    Dyadic d{static_cast<std::int64_t>(std::ldexp(m, 53)), e - 53};
    while ((d.mantissa & 1) == 0) {
        d.mantissa /= 2;
        ++d.exponent;
    }
    return d;
}

}  // namespace

std::vector<ExactPoint> exact_points(const std::vector<Point>& points) {
    std::vector<Dyadic> xs;
    std::vector<Dyadic> ys;
    int emin = INT_MAX;
    for (const Point& p : points) {
        xs.push_back(dyadic(p.x));
        ys.push_back(dyadic(p.y));
        for (const Dyadic& d : {xs.back(), ys.back()}) {
            if (d.mantissa != 0) emin = std::min(emin, d.exponent);
        }
    }
    auto scaled = [&](const Dyadic& d) {
        BigInt v = d.mantissa;
        if (d.mantissa != 0) v <<= (d.exponent - emin);
        return v;
    };
    std::vector<ExactPoint> out;
    out.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        ExactPoint& p = out.emplace_back();
        p.x = scaled(xs[i]);
        p.y = scaled(ys[i]);
    }
    return out;
}

int orientation(const ExactPoint& a, const ExactPoint& b, const ExactPoint& c) {
    const BigInt cross = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    return cross.sign();
}

bool strictly_between(const ExactPoint& a, const ExactPoint& b, const ExactPoint& p) {
    if (p == a || p == b || orientation(a, b, p) != 0) return false;
    // Collinear: p is inside when it lies within the bounding box of ab.
    const bool in_x = (a.x <= p.x && p.x <= b.x) || (b.x <= p.x && p.x <= a.x);
    const bool in_y = (a.y <= p.y && p.y <= b.y) || (b.y <= p.y && p.y <= a.y);
    return in_x && in_y;
}

}  // namespace dcel::fuzz
