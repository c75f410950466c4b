// The exact predicates against the independent oracles (oracles/exact.hpp):
// exact integer arithmetic on the doubles' dyadic form, and GMP rationals,
// which represent every double exactly and compute with no rounding at all.
#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "dcel/geometry/area.hpp"
#include "dcel/geometry/exact_sum.hpp"
#include "dcel/geometry/predicates.hpp"
#include "dcel/geometry/segments.hpp"
#include "oracles/exact.hpp"

namespace {

using dcel::Point;
using dcel::Sign;
using dcel::oracle::exact;
using dcel::oracle::Rational;

Sign to_sign(int s) { return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero); }
Sign rational_sign(const Rational& r) { return to_sign(r.sign()); }
Sign oracle_orient(Point a, Point b, Point c) { return to_sign(dcel::oracle::orientation(a, b, c)); }
Sign oracle_compare_angle(Point c, Point a, Point b) { return to_sign(dcel::oracle::angle_order(c, a, b)); }

TEST(Orient2d, ConventionCounterclockwiseIsPositive) {
    EXPECT_EQ(dcel::orient2d({0, 0}, {1, 0}, {0, 1}), Sign::Positive);
    EXPECT_EQ(dcel::orient2d({0, 0}, {0, 1}, {1, 0}), Sign::Negative);
    EXPECT_EQ(dcel::orient2d({0, 0}, {1, 1}, {2, 2}), Sign::Zero);
}

TEST(Orient2d, OracleItselfIsRight) {
    // Guard the oracle: a hand-computed determinant. (1,0)-(0,0) x (0,1)-(0,0) = 1.
    EXPECT_EQ(oracle_orient({0, 0}, {1, 0}, {0, 1}), Sign::Positive);
    EXPECT_EQ(exact(0.1) * 10 == 1, false);  // 0.1 is not exactly a tenth: the oracle sees the double
    EXPECT_EQ(exact(0x1p-1074) * Rational(dcel::oracle::BigInt(1) << 1074), 1);
    // Operands far apart in exponent take the arbitrary-precision path.
    EXPECT_EQ(oracle_orient({0, 0}, {0x1p-1074, 0}, {0x1p1000, 0x1p-1074}), Sign::Positive);
    EXPECT_EQ(oracle_orient({0x1p-1074, 0x1p-1074}, {0x1p1000, 0x1p1000}, {-0x1p1000, -0x1p1000}), Sign::Zero);
}

// Doubles of every kind: integers, fractions, huge, tiny, subnormal, signed zero.
double interesting_double(std::mt19937_64& rng) {
    std::uniform_int_distribution<int> kind(0, 9);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> small(-8, 8);
    switch (kind(rng)) {
        case 0: return small(rng);
        case 1: return unit(rng);
        case 2: return std::ldexp(unit(rng), std::uniform_int_distribution<int>(-1074, 1023)(rng));
        case 3: return std::ldexp(unit(rng), -1060);  // subnormal
        case 4: return unit(rng) < 0 ? -0.0 : 0.0;
        case 5: return 1e15 + small(rng);
        case 6: return std::ldexp(unit(rng), 1023);
        case 7: return std::ldexp(unit(rng), -300);
        case 8: return std::ldexp(1.0 + small(rng) * DBL_EPSILON, 0);
        default: return std::ldexp(unit(rng), std::uniform_int_distribution<int>(-60, 60)(rng));
    }
}

Point interesting_point(std::mt19937_64& rng) { return {interesting_double(rng), interesting_double(rng)}; }

TEST(Orient2d, AgreesWithRationalsOnRandomTriples) {
    std::mt19937_64 rng(20261121);
    for (int i = 0; i < 40000; ++i) {
        const Point a = interesting_point(rng), b = interesting_point(rng), c = interesting_point(rng);
        ASSERT_EQ(dcel::orient2d(a, b, c), oracle_orient(a, b, c))
            << "a=(" << a.x << "," << a.y << ") b=(" << b.x << "," << b.y << ") c=(" << c.x << "," << c.y << ")";
    }
}

// Points on or next to a line: c = a + t (b - a) computed exactly where the
// arithmetic allows, then nudged by a few ulps. Most are within a hair of
// collinear, which is where a filter alone would guess.
TEST(Orient2d, AgreesWithRationalsNearCollinear) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> nudge(-2, 2);
    std::uniform_int_distribution<int> scale_exp(-1000, 1000);
    int zeros = 0;
    for (int i = 0; i < 40000; ++i) {
        const double s = std::ldexp(1.0, scale_exp(rng) / 2);
        const Point a{std::uniform_int_distribution<int>(-100, 100)(rng) * s,
                      std::uniform_int_distribution<int>(-100, 100)(rng) * s};
        const Point d{std::uniform_int_distribution<int>(-100, 100)(rng) * s,
                      std::uniform_int_distribution<int>(-100, 100)(rng) * s};
        const int t = std::uniform_int_distribution<int>(-5, 5)(rng);
        Point c{a.x + t * d.x, a.y + t * d.y};
        const Point b{a.x + d.x, a.y + d.y};
        for (int k = nudge(rng); k != 0; k += k > 0 ? -1 : 1) c.x = std::nextafter(c.x, k > 0 ? INFINITY : -INFINITY);
        const Sign expected = oracle_orient(a, b, c);
        zeros += expected == Sign::Zero;
        ASSERT_EQ(dcel::orient2d(a, b, c), expected) << i;
        ASSERT_EQ(dcel::orient2d_exact(a, b, c), expected) << i;
    }
    EXPECT_GT(zeros, 5000);  // the test really exercises collinear triples
}

TEST(Orient2d, AdversarialCases) {
    const double big = 1e15;
    // Coordinates near 1e15 differing by one.
    EXPECT_EQ(dcel::orient2d({big, big}, {big + 1, big + 1}, {big + 2, big + 2}), Sign::Zero);
    EXPECT_EQ(dcel::orient2d({big, big}, {big + 1, big + 1}, {big + 2, big + 3}), Sign::Positive);
    // Magnitudes near 1e-300 and subnormals: products underflow in doubles.
    const double t = 1e-300;
    EXPECT_EQ(dcel::orient2d({0, 0}, {t, 0}, {0, t}), Sign::Positive);
    EXPECT_EQ(dcel::orient2d({0, 0}, {t, t}, {2 * t, 2 * t}), Sign::Zero);
    const double sub = 0x1p-1074;
    EXPECT_EQ(dcel::orient2d({0, 0}, {sub, 0}, {0, sub}), Sign::Positive);
    EXPECT_EQ(dcel::orient2d({0, 0}, {sub, sub}, {3 * sub, 3 * sub}), Sign::Zero);
    EXPECT_EQ(dcel::orient2d({0, 0}, {sub, sub}, {3 * sub, 2 * sub}), Sign::Negative);
    // -0.0 and 0.0 are the same number.
    EXPECT_EQ(dcel::orient2d({-0.0, 0.0}, {1, -0.0}, {2, 0.0}), Sign::Zero);
    // Differences that overflow: coordinates near DBL_MAX of both signs.
    const double m = DBL_MAX;
    EXPECT_EQ(dcel::orient2d({-m, -m}, {m, m}, {0, 0}), Sign::Zero);
    EXPECT_EQ(dcel::orient2d({-m, -m}, {m, m}, {0, std::nextafter(0.0, 1.0)}), Sign::Positive);
    EXPECT_EQ(dcel::orient2d({-m, m}, {m, -m}, {m, m}), Sign::Positive);
    for (const auto& [a, b, c] : std::vector<std::tuple<Point, Point, Point>>{
             {{-m, -m}, {m, m}, {0, 0}},
             {{0.5, 0.5}, {12, 12}, {24, 24}},
             {{big, big + 1}, {big + 1, big + 2}, {0, 0}},
         }) {
        EXPECT_EQ(dcel::orient2d(a, b, c), oracle_orient(a, b, c));
    }
}

TEST(Orient2d, SymmetriesHold) {
    std::mt19937_64 rng(99);
    for (int i = 0; i < 10000; ++i) {
        const Point a = interesting_point(rng), b = interesting_point(rng), c = interesting_point(rng);
        const Sign s = dcel::orient2d(a, b, c);
        ASSERT_EQ(dcel::orient2d(b, c, a), s);
        ASSERT_EQ(dcel::orient2d(c, a, b), s);
        ASSERT_EQ(dcel::orient2d(b, a, c), -s);
    }
}

TEST(CompareAngle, DirectionsCloserThan1e16Radians) {
    // (1e15, 1e15+1) and (1e15+1, 1e15+2) from the origin differ by about
    // 5e-31 rad: atan2 gives both the same angle.
    const Point o{0, 0};
    const Point a{1e15, 1e15 + 1};
    const Point b{1e15 + 1, 1e15 + 2};
    EXPECT_EQ(std::atan2(a.y, a.x), std::atan2(b.y, b.x));  // why atan2 is not enough
    EXPECT_EQ(dcel::compare_angle(o, a, b), oracle_compare_angle(o, a, b));
    EXPECT_NE(dcel::compare_angle(o, a, b), Sign::Zero);
    EXPECT_EQ(dcel::compare_angle(o, b, a), -dcel::compare_angle(o, a, b));
}

TEST(CompareAngle, HalfPlaneBoundaries) {
    const Point o{0, 0};
    // East is first, then north, west, south; just below east is last.
    const std::vector<Point> ccw = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
    for (std::size_t i = 0; i < ccw.size(); ++i) {
        for (std::size_t j = 0; j < ccw.size(); ++j) {
            const Sign expected = i < j ? Sign::Negative : (i > j ? Sign::Positive : Sign::Zero);
            EXPECT_EQ(dcel::compare_angle(o, ccw[i], ccw[j]), expected) << i << " " << j;
        }
    }
    EXPECT_EQ(dcel::compare_angle(o, {-0.0, 1}, {0.0, 2}), Sign::Zero);
    EXPECT_EQ(dcel::compare_angle(o, {1, -0.0}, {2, 0.0}), Sign::Zero);
}

TEST(CompareAngle, AgreesWithRationals) {
    std::mt19937_64 rng(5);
    for (int i = 0; i < 30000; ++i) {
        const Point c = interesting_point(rng), a = interesting_point(rng), b = interesting_point(rng);
        if (a == c || b == c) continue;
        ASSERT_EQ(dcel::compare_angle(c, a, b), oracle_compare_angle(c, a, b));
    }
}

TEST(ExactSum, MatchesRationalsAndRoundsCorrectly) {
    std::mt19937_64 rng(11);
    for (int i = 0; i < 3000; ++i) {
        dcel::detail::ExactSum sum;
        Rational expected = 0;
        const int terms = std::uniform_int_distribution<int>(1, 12)(rng);
        for (int k = 0; k < terms; ++k) {
            const double a = interesting_double(rng), b = interesting_double(rng);
            if (k % 2 == 0) {
                sum.add_product(a, b);
                expected += exact(a) * exact(b);
            } else {
                sum.subtract_product(a, b);
                expected -= exact(a) * exact(b);
            }
        }
        ASSERT_EQ(sum.sign(), rational_sign(expected));
        // Correct rounding: no double is strictly closer to the exact sum.
        const double r = sum.to_double();
        if (std::isinf(r) || r == 0 || std::fabs(r) < DBL_MIN) continue;  // overflow / subnormal results
        const Rational err = abs(expected - exact(r));
        ASSERT_LE(err, abs(expected - exact(std::nextafter(r, INFINITY))));
        ASSERT_LE(err, abs(expected - exact(std::nextafter(r, -INFINITY))));
    }
}

// Sums near and below the least normal double, scaled by 2^-3 .. 2^3 before
// rounding: the result must be rounded once. Found by fuzz/oracle: face_area
// halved a rounded sum, and the conversion rounded to 53 bits before scaling
// into the subnormal range.
TEST(ExactSum, RoundsSubnormalAndScaledResultsOnce) {
    std::mt19937_64 rng(12);
    for (int i = 0; i < 20000; ++i) {
        dcel::detail::ExactSum sum;
        Rational expected = 0;
        const int terms = std::uniform_int_distribution<int>(1, 4)(rng);
        for (int k = 0; k < terms; ++k) {
            // Products from 2^-1140 to 2^-1000, with random significands.
            const double a = std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng),
                                        std::uniform_int_distribution<int>(-600, -500)(rng));
            const double b = std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng),
                                        std::uniform_int_distribution<int>(-540, -500)(rng));
            const bool add = k == 0 || rng() % 2 == 0;
            if (add) {
                sum.add_product(a, b);
                expected += exact(a) * exact(b);
            } else {
                sum.subtract_product(a, b);
                expected -= exact(a) * exact(b);
            }
        }
        const int scale = std::uniform_int_distribution<int>(-3, 3)(rng);
        const Rational scaled = expected * Rational(std::ldexp(1.0, scale));  // exact: 2^scale is a double
        const double r = sum.to_double(scale);
        ASSERT_TRUE(dcel::oracle::is_nearest_double(r, scaled)) << "scale " << scale << ": " << r;
    }
}

TEST(ExactSum, HalvesBeforeRounding) {
    dcel::detail::ExactSum near_half;  // 2^-1075 (1 + 2^-60): just above half the least subnormal
    near_half.add_product(0x1p-1074, 0.5);
    near_half.add_product(0x1p-1074, 0x1p-61);
    EXPECT_EQ(near_half.to_double(), 0x1p-1074);
    dcel::detail::ExactSum twice_max;  // 2 DBL_MAX overflows, its half does not
    twice_max.add_product(DBL_MAX, 2.0);
    EXPECT_EQ(twice_max.to_double(), INFINITY);
    EXPECT_EQ(twice_max.to_double(-1), DBL_MAX);
    dcel::detail::ExactSum odd;  // 3 * 2^-1074 halved: 1.5 ulps, a tie, goes to the even 2 ulps
    odd.add_product(0x1.8p-1073, 1.0);
    EXPECT_EQ(odd.to_double(-1), 0x1p-1073);
    odd.subtract_product(0x1p-1072, 1.0);  // now -2^-1074, halved: a tie between 0 and one ulp
    EXPECT_EQ(odd.to_double(-1), 0.0);
    EXPECT_TRUE(std::signbit(odd.to_double(-1)));
}

TEST(ExactSum, CancelsExactly) {
    dcel::detail::ExactSum s;
    s.add_product(DBL_MAX, DBL_MAX);
    s.add_product(0x1p-1074, 0x1p-1074);
    s.subtract_product(DBL_MAX, DBL_MAX);
    EXPECT_EQ(s.sign(), Sign::Positive);  // 2^-2148 survives next to 2^2048
    s.subtract_product(0x1p-1074, 0x1p-1074);
    EXPECT_EQ(s.sign(), Sign::Zero);
    EXPECT_EQ(s.to_double(), 0.0);
}

TEST(PolygonArea, SignAgreesWithRationals) {
    std::mt19937_64 rng(3);
    for (int i = 0; i < 5000; ++i) {
        std::vector<Point> poly;
        const int n = std::uniform_int_distribution<int>(2, 9)(rng);
        const bool near_degenerate = i % 2 == 0;
        for (int k = 0; k < n; ++k) {
            if (near_degenerate) {
                const double t = std::uniform_int_distribution<int>(-3, 3)(rng);
                poly.push_back({1e15 + t, 1e15 + 2 * t + (k == 0 ? std::uniform_int_distribution<int>(-1, 1)(rng) : 0)});
            } else {
                poly.push_back(interesting_point(rng));
            }
        }
        auto visit = [&](auto&& f) {
            for (std::size_t k = 0; k < poly.size(); ++k) f(poly[k], poly[(k + 1) % poly.size()]);
        };
        ASSERT_EQ(dcel::detail::polygon_area_sign(visit), rational_sign(dcel::oracle::twice_area(poly))) << i;
    }
}

// How the oracle's meeting (orientations and betweenness, exact) names a contact.
dcel::detail::Contact oracle_contact(Point a, Point b, Point c, Point d) {
    using dcel::detail::Contact;
    using dcel::oracle::Meeting;
    switch (dcel::oracle::meeting(a, b, c, d)) {
        case Meeting::None: return Contact::None;
        case Meeting::SharedEndpoint: return Contact::SharedEndpoint;
        case Meeting::Crossing: return Contact::Crossing;
        case Meeting::Touch: return Contact::Touch;
        case Meeting::Overlap:
        case Meeting::Same: return Contact::Overlap;
    }
    return Contact::None;
}

TEST(SegmentContact, AgreesWithExactBruteForce) {
    std::mt19937_64 rng(17);
    std::uniform_int_distribution<int> coord(0, 4);  // a tiny grid: many degenerate contacts
    int counts[5] = {};
    for (int i = 0; i < 60000; ++i) {
        auto p = [&] { return Point{static_cast<double>(coord(rng)), static_cast<double>(coord(rng))}; };
        const Point a = p(), b = p(), c = p(), d = p();
        if (a == b || c == d) continue;
        const dcel::detail::Contact expected = oracle_contact(a, b, c, d);
        ++counts[static_cast<int>(expected)];
        ASSERT_EQ(dcel::detail::segment_contact(a, b, c, d), expected)
            << "(" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ") vs (" << c.x << "," << c.y << ")-(" << d.x << ","
            << d.y << ")";
    }
    for (const int n : counts) EXPECT_GT(n, 100);  // every kind of contact occurred
}

}  // namespace
