#include "support/point_gen.hpp"

#include <cfloat>
#include <cmath>
#include <cstring>
#include <iomanip>

namespace dcel::props {
namespace {

using rc::Gen;
namespace gen = rc::gen;

// Coordinates of one scale: every point of a triple shares it, which is
// where the predicates are hard.
Gen<double> coordinate(int style) {
    switch (style) {
        case 0: return gen::map(gen::inRange(-8, 9), [](int v) { return static_cast<double>(v); });
        case 1: return gen::map(gen::inRange(-8, 9), [](int v) { return 1e15 + v; });  // large offset, tiny differences
        case 2:                                                                        // tiny magnitudes, down to subnormals
            return gen::map(gen::pair(gen::inRange(-8, 9), gen::inRange(1000, 1075)),
                            [](std::pair<int, int> v) { return std::ldexp(static_cast<double>(v.first), -v.second); });
        case 3:  // near DBL_MAX: differences overflow
            return gen::map(gen::inRange(-8, 9), [](int v) {
                return std::copysign(DBL_MAX - std::ldexp(std::fabs(static_cast<double>(v)), 970), static_cast<double>(v));
            });
        case 4: return gen::element(0.0, -0.0, 1.0, -1.0, 0x1p-1074, -0x1p-1074);
        default:  // any finite double, from its bits
            return gen::map(gen::arbitrary<std::uint64_t>(), [](std::uint64_t bits) {
                double v = 0;
                std::memcpy(&v, &bits, sizeof v);
                return std::isfinite(v) ? v : 0.0;
            });
    }
}

Gen<Point> point(int style) {
    return gen::apply([](double x, double y) { return Point{x, y}; }, coordinate(style), coordinate(style));
}

// c on the line through a and b (c = a + t (b - a) with exact arithmetic
// where it is exact), then perhaps nudged by one ulp in x or y.
Triple near_collinear(Triple t, int scale, int nudge) {
    const Point a = t.p[0], b = t.p[1];
    Point c{a.x + (b.x - a.x) * scale, a.y + (b.y - a.y) * scale};
    if (nudge == 1) c.x = std::nextafter(c.x, DBL_MAX);
    if (nudge == 2) c.y = std::nextafter(c.y, -DBL_MAX);
    if (std::isfinite(c.x) && std::isfinite(c.y)) t.p[2] = c;
    return t;
}

// Kettner et al.'s classroom example of robustness problems: p near (0.5,
// 0.5) on a grid of 2^-53 steps, with q = (12, 12) and r = (24, 24). The
// floating-point determinant gets the sign wrong for many of these.
Gen<Triple> near_diagonal() {
    return gen::apply(
        [](int x, int y, int order) {
            const Point p{0.5 + std::ldexp(x, -53), 0.5 + std::ldexp(y, -53)};
            const Point q{12, 12}, r{24, 24};
            static const int kOrders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
            const Point points[3] = {p, q, r};
            const int* o = kOrders[order];
            return Triple{{points[o[0]], points[o[1]], points[o[2]]}};
        },
        // Full range from the first case: inRange alone scales with size.
        gen::resize(rc::kNominalSize, gen::inRange(0, 256)), gen::resize(rc::kNominalSize, gen::inRange(0, 256)),
        gen::inRange(0, 6));
}

}  // namespace

void showValue(const Triple& t, std::ostream& os) {
    os << std::setprecision(17);
    for (const Point& p : t.p) os << "(" << p.x << ", " << p.y << ") ";
}

Gen<Triple> adversarial_triples() {
    return gen::mapcat(gen::inRange(0, 9), [](int style) {
        if (style >= 6) return near_diagonal();  // a third of the cases: the hardest ones
        const Gen<Triple> any = gen::apply(
            [](Point a, Point b, Point c) {
                return Triple{{a, b, c}};
            },
            point(style), point(style), point(style));
        return gen::oneOf(any, gen::apply(near_collinear, any, gen::inRange(-3, 4), gen::inRange(0, 3)));
    });
}

}  // namespace dcel::props
