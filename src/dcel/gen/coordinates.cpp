#include "dcel/gen/coordinates.hpp"

#include <array>
#include <cfloat>
#include <cmath>

#include "dcel/gen/generate.hpp"
#include "dcel/gen/rng.hpp"

namespace dcel::gen {

namespace {

constexpr std::array<CoordinateClass, 5> kClasses{CoordinateClass::SmallIntegers, CoordinateClass::Normal,
                                                  CoordinateClass::Huge, CoordinateClass::Tiny, CoordinateClass::Subnormal};
constexpr std::array<std::string_view, 5> kNames{"small-integers", "normal", "huge", "tiny", "subnormal"};

constexpr double kSmall = 0x1p31;

CoordinateClass class_of(double v) {
    const double a = std::fabs(v);
    if (a == 0) return CoordinateClass::SmallIntegers;
    if (a < DBL_MIN) return CoordinateClass::Subnormal;
    if (a < 0x1p-500) return CoordinateClass::Tiny;
    if (a > 0x1p500) return CoordinateClass::Huge;
    if (std::trunc(v) != v || a >= kSmall) return CoordinateClass::Normal;
    return CoordinateClass::SmallIntegers;
}

// Exotic first: the order in which one coordinate decides a graph's class.
int rank(CoordinateClass c) {
    switch (c) {
        case CoordinateClass::SmallIntegers: return 0;
        case CoordinateClass::Normal: return 1;
        case CoordinateClass::Huge: return 2;
        case CoordinateClass::Tiny: return 3;
        case CoordinateClass::Subnormal: return 4;
    }
    return 0;
}

// x + a without rounding? (TwoSum's tail is exactly zero then.)
bool add_exactly(double& x, double a) {
    const double s = x + a;
    const double av = s - x;
    const double tail = (x - (s - av)) + (a - av);
    if (!std::isfinite(s) || tail != 0) return false;
    x = s;
    return true;
}

std::optional<PlanarGraph> translated(PlanarGraph g, double ax, double ay) {
    for (Point& p : g.vertices) {
        if (!add_exactly(p.x, ax) || !add_exactly(p.y, ay)) return std::nullopt;
    }
    return g;
}

}  // namespace

std::span<const CoordinateClass> all_coordinate_classes() { return kClasses; }

std::string_view coordinate_class_name(CoordinateClass c) { return kNames[static_cast<std::size_t>(c)]; }

std::optional<CoordinateClass> coordinate_class_from_name(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i) {
        if (kNames[i] == name) return kClasses[i];
    }
    return std::nullopt;
}

CoordinateClass classify(const PlanarGraph& g) {
    CoordinateClass worst = CoordinateClass::SmallIntegers;
    for (const Point& p : g.vertices) {
        for (const double v : {p.x, p.y}) {
            const CoordinateClass c = class_of(v);
            if (rank(c) > rank(worst)) worst = c;
        }
    }
    return worst;
}

std::optional<PlanarGraph> to_coordinate_class(const PlanarGraph& g, CoordinateClass c, std::uint64_t seed) {
    if (classify(g) != CoordinateClass::SmallIntegers) return std::nullopt;
    Rng rng(seed);
    PlanarGraph base = g;
    if (!base.vertices.empty() && rng.chance(1, 2)) {
        // One vertex at the origin: zeros on both axes, where -0.0 can appear
        // (exact: integers of magnitude below 2^31 stay below 2^32).
        const Point o = base.vertices[rng.below(base.vertices.size())];
        for (Point& p : base.vertices) p = {p.x - o.x, p.y - o.y};
        if (classify(base) != CoordinateClass::SmallIntegers) base = g;
    }
    std::optional<PlanarGraph> out;
    switch (c) {
        case CoordinateClass::SmallIntegers: out = base; break;
        case CoordinateClass::Normal:
            if (rng.chance(1, 3)) {
                // A large offset with small differences: 2^40 .. 2^51, integral.
                const auto ox = static_cast<double>(rng.between(std::int64_t{1} << 40, std::int64_t{1} << 51));
                const auto oy = static_cast<double>(rng.between(std::int64_t{1} << 40, std::int64_t{1} << 51));
                out = translated(base, ox, rng.chance(1, 2) ? oy : -oy);
            } else {
                // Binary fractions: scaled by 2^-k, moved by a multiple of 2^-k.
                const int k = static_cast<int>(rng.between(1, 30));
                out = apply(base, Transform::ScalePow2, -k);
                if (out) {
                    const double step = std::ldexp(1.0, -k);
                    out = translated(*out, step * static_cast<double>(rng.between(-(1 << 20), 1 << 20)) * 3,
                                     step * static_cast<double>(rng.between(-(1 << 20), 1 << 20)) * 5);
                }
            }
            break;
        case CoordinateClass::Huge: out = apply(base, Transform::ScalePow2, rng.between(600, 990)); break;
        case CoordinateClass::Tiny: out = apply(base, Transform::ScalePow2, -rng.between(600, 990)); break;
        case CoordinateClass::Subnormal: out = apply(base, Transform::ScalePow2, -rng.between(1045, 1074)); break;
    }
    if (!out) return std::nullopt;
    for (Point& p : out->vertices) {
        if (p.x == 0 && rng.chance(1, 2)) p.x = -0.0;
        if (p.y == 0 && rng.chance(1, 2)) p.y = -0.0;
    }
    return out;
}

}  // namespace dcel::gen
