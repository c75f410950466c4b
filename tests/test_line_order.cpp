// The direction and line-order predicates against the exact oracles
// (oracles/exact.hpp) on random and adversarial inputs: large offsets with
// tiny differences, tiny magnitudes, values near the double limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>

#include "dcel/geometry/directions.hpp"
#include "dcel/geometry/line_order.hpp"
#include "dcel/geometry/predicates.hpp"
#include "oracles/exact.hpp"

namespace dcel {

// From the internals of the core (dcel::detail).
using detail::compare_direction;
using detail::cross_sign;
using detail::DirectedLine;
using detail::LineEvent;
namespace {

using oracle::Rational;
Sign to_sign(int s) { return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero); }

// Points from one of several adversarial families.
class Points {
public:
    explicit Points(std::uint64_t seed) : rng_(seed) {}
    Point next(int family) {
        std::uniform_int_distribution<int> small(-4, 4);
        switch (family) {
            case 0: return {static_cast<double>(small(rng_)), static_cast<double>(small(rng_))};
            case 1: return {1e15 + small(rng_), 1e15 + small(rng_)};            // huge offset, unit steps
            case 2: return {small(rng_) * 0x1p-1070, small(rng_) * 0x1p-1072};  // subnormals
            case 3: return {small(rng_) * 0x1p1020, small(rng_) * 0x1p1021};    // near DBL_MAX
            default: return {std::ldexp(1.0 + small(rng_) * 0x1p-52, small(rng_)), 0.5 + small(rng_) * 0x1p-53};
        }
    }

private:
    std::mt19937_64 rng_;
};

TEST(CrossSign, MatchesRationalsOnAdversarialInputs) {
    Points pts(1);
    for (int i = 0; i < 50000; ++i) {
        const int f = i % 5;
        const Point a = pts.next(f), b = pts.next(f), c = pts.next(f), d = pts.next(f);
        ASSERT_EQ(cross_sign(a, b, c, d), to_sign(oracle::cross_sign(a, b, c, d))) << i;
        if (!(a == b) && !(c == d)) {
            ASSERT_EQ(compare_direction(a, b, c, d), to_sign(oracle::direction_order(a, b, c, d))) << i;
        }
    }
}

TEST(CrossSign, AgreesWithOrient2dAndCompareAngle) {
    Points pts(2);
    for (int i = 0; i < 20000; ++i) {
        const int f = i % 5;
        const Point a = pts.next(f), b = pts.next(f), c = pts.next(f);
        ASSERT_EQ(cross_sign(a, b, a, c), orient2d(a, b, c));
        if (!(a == b) && !(a == c)) {
            ASSERT_EQ(compare_direction(a, b, a, c), compare_angle(a, b, c));
        }
    }
}

TEST(DirectedLine, OrdersCrossingsLikeRationalParameters) {
    // Random line through two points; random disjoint segments crossing it
    // (taken from a fan of segments that share one endpoint, so they never
    // cross each other) and random points on it.
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<int> coord(-20, 20);
    int compared = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Point a{static_cast<double>(coord(rng)), static_cast<double>(coord(rng))};
        const Point b{static_cast<double>(coord(rng)), static_cast<double>(coord(rng))};
        if (a == b) continue;
        const DirectedLine line(a, b);
        const Point hub{static_cast<double>(coord(rng)), static_cast<double>(coord(rng))};
        std::vector<std::pair<LineEvent, Rational>> events;
        for (int k = 0; k < 12; ++k) {
            const Point e{static_cast<double>(coord(rng)), static_cast<double>(coord(rng))};
            if (to_int(orient2d(a, b, hub)) * to_int(orient2d(a, b, e)) >= 0) continue;  // must cross strictly
            // Two segments of the fan along one ray would overlap: not allowed.
            const bool overlaps = std::any_of(events.begin(), events.end(), [&](const auto& x) {
                return x.first.crossing && compare_direction(hub, x.first.d, hub, e) == Sign::Zero;
            });
            if (overlaps) continue;
            events.push_back({LineEvent::cut(hub, e), oracle::parameter_of_crossing(a, b, hub, e)});
        }
        for (int k = 0; k < 4; ++k) {
            const int s = coord(rng);
            const Point p{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};  // exact for small integers
            events.push_back({LineEvent::at(p), Rational(s)});
        }
        for (const auto& [x, tx] : events) {
            for (const auto& [y, ty] : events) {
                ASSERT_EQ(line.compare(x, y), to_sign(oracle::sign_of(tx - ty))) << "trial " << trial;
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 100000);
}

}  // namespace
}  // namespace dcel
