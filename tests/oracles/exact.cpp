#include "oracles/exact.hpp"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gmp.h>

namespace dcel::oracle {
namespace {

// __extension__: no -Wpedantic warning; it takes the typedef form only.
__extension__ typedef __int128 Wide;            // NOLINT(modernize-use-using)
__extension__ typedef unsigned __int128 UWide;  // NOLINT(modernize-use-using)

// v = mantissa * 2^exponent, read off the bits (v finite); mantissa odd, or 0.
struct Dyadic {
    std::int64_t mantissa = 0;
    int exponent = 0;
};

Dyadic dyadic(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    const auto biased = static_cast<int>((bits >> 52U) & 0x7ffU);
    std::uint64_t m = bits & ((std::uint64_t{1} << 52U) - 1);
    int e = -1074;  // subnormal: m * 2^-1074
    if (biased != 0) {
        m |= std::uint64_t{1} << 52U;
        e = biased - 1075;
    } else if (m == 0) {
        return {};  // 0.0 and -0.0
    }
    const int zeros = std::countr_zero(m);
    m >>= static_cast<unsigned>(zeros);
    const auto magnitude = static_cast<std::int64_t>(m);
    return {(bits >> 63U) != 0 ? -magnitude : magnitude, e + zeros};
}

int bit_length(std::int64_t m) { return 64 - std::countl_zero(static_cast<std::uint64_t>(m < 0 ? -m : m)); }

// One power of two, 2^scale, that turns every added value into an integer,
// and how many bits the largest of those integers has.
class CommonScale {
public:
    void add(const Dyadic& d) {
        if (d.mantissa == 0) return;
        low_ = std::min(low_, d.exponent);
        high_ = std::max(high_, d.exponent + bit_length(d.mantissa));
    }
    [[nodiscard]] int scale() const { return low_ == INT_MAX ? 0 : low_; }
    [[nodiscard]] int bits() const { return low_ == INT_MAX ? 0 : high_ - low_; }
    // The value / 2^scale; only when bits() <= 62.
    [[nodiscard]] std::int64_t small(const Dyadic& d) const {
        return d.mantissa == 0 ? 0 : d.mantissa * (std::int64_t{1} << static_cast<unsigned>(d.exponent - low_));
    }
    // Only when bits() <= 125.
    [[nodiscard]] Wide wide(const Dyadic& d) const {
        return d.mantissa == 0 ? 0 : static_cast<Wide>(d.mantissa) * (Wide{1} << static_cast<unsigned>(d.exponent - low_));
    }
    void to_gmp(const Dyadic& d, mpz_t out) const {
        mpz_set_si(out, d.mantissa);
        if (d.mantissa != 0) mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(d.exponent - low_));
    }
    [[nodiscard]] BigInt big(const Dyadic& d) const {
        BigInt v = d.mantissa;
        if (d.mantissa != 0) v <<= static_cast<unsigned>(d.exponent - low_);
        return v;
    }

private:
    int low_ = INT_MAX;
    int high_ = INT_MIN;
};

int sign_of(Wide v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// 2^k as a rational.
Rational power_of_two(int k) {
    const BigInt one = 1;
    return k >= 0 ? Rational(BigInt(one << static_cast<unsigned>(k)))
                  : Rational(one, BigInt(one << static_cast<unsigned>(-k)));
}

bool between(double lo, double x, double hi) { return std::min(lo, hi) <= x && x <= std::max(lo, hi); }

}  // namespace

Rational exact(double v) { return Rational(v); }

int sign_of(const Rational& r) { return r.sign(); }

namespace {

// The three widths of the exact cross product, by how many bits the scaled
// operands need. Each computes the sign of (v0 - v1)(v2 - v3) - (v4 - v5)(v6 - v7).

// Up to 62 bits: differences below 2^63, products below 2^126, their
// difference below 2^127.
int cross_sign_64(const CommonScale& scale, const Dyadic (&v)[8]) {
    std::int64_t n[8];
    for (int i = 0; i < 8; ++i) n[i] = scale.small(v[i]);
    const Wide det = static_cast<Wide>(n[0] - n[1]) * (n[2] - n[3]) - static_cast<Wide>(n[4] - n[5]) * (n[6] - n[7]);
    return sign_of(det);
}

// A 256-bit magnitude, for products of two 128-bit ones.
struct U256 {
    UWide hi, lo;
};

U256 multiply(UWide a, UWide b) {
    const auto a0 = static_cast<std::uint64_t>(a), a1 = static_cast<std::uint64_t>(a >> 64U);
    const auto b0 = static_cast<std::uint64_t>(b), b1 = static_cast<std::uint64_t>(b >> 64U);
    const UWide p00 = static_cast<UWide>(a0) * b0, p01 = static_cast<UWide>(a0) * b1;
    const UWide p10 = static_cast<UWide>(a1) * b0, p11 = static_cast<UWide>(a1) * b1;
    // The middle 64-bit column with its carries: below 3 * 2^64.
    const UWide mid = (p00 >> 64U) + static_cast<std::uint64_t>(p01) + static_cast<std::uint64_t>(p10);
    return {p11 + (p01 >> 64U) + (p10 >> 64U) + (mid >> 64U), (mid << 64U) | static_cast<std::uint64_t>(p00)};
}

int compare(const U256& a, const U256& b) {
    if (a.hi != b.hi) return a.hi < b.hi ? -1 : 1;
    return a.lo < b.lo ? -1 : (a.lo > b.lo ? 1 : 0);
}

// A signed product x * y as a sign and a magnitude (|x|, |y| < 2^127).
struct Product {
    int sign;
    U256 magnitude;
};
Product product(Wide x, Wide y) {
    const auto mx = static_cast<UWide>(x < 0 ? -x : x), my = static_cast<UWide>(y < 0 ? -y : y);
    return {sign_of(x) * sign_of(y), multiply(mx, my)};
}

// Up to 125 bits: differences below 2^126 fit a 128-bit integer, and the
// sign of p - q is a comparison of two 256-bit products.
int cross_sign_128(const CommonScale& scale, const Dyadic (&v)[8]) {
    Wide n[8];
    for (int i = 0; i < 8; ++i) n[i] = scale.wide(v[i]);
    const Product p = product(n[0] - n[1], n[2] - n[3]);
    const Product q = product(n[4] - n[5], n[6] - n[7]);
    if (p.sign != q.sign) return p.sign > q.sign ? 1 : -1;
    return p.sign * compare(p.magnitude, q.magnitude);
}

// Any width: GMP integers, in scratch variables that keep their limbs
// between calls (no allocation once they have grown).
int cross_sign_gmp(const CommonScale& scale, const Dyadic (&v)[8]) {
    struct Scratch {
        mpz_t n[8], p, q;
        Scratch() {
            for (mpz_t& x : n) mpz_init(x);
            mpz_init(p);
            mpz_init(q);
        }
        ~Scratch() {
            for (mpz_t& x : n) mpz_clear(x);
            mpz_clear(p);
            mpz_clear(q);
        }
        Scratch(const Scratch&) = delete;
        Scratch& operator=(const Scratch&) = delete;
    };
    thread_local Scratch s;
    for (int i = 0; i < 8; ++i) scale.to_gmp(v[i], s.n[i]);
    mpz_sub(s.p, s.n[0], s.n[1]);
    mpz_sub(s.q, s.n[2], s.n[3]);
    mpz_mul(s.p, s.p, s.q);
    mpz_sub(s.q, s.n[4], s.n[5]);
    mpz_sub(s.n[0], s.n[6], s.n[7]);
    mpz_mul(s.q, s.q, s.n[0]);
    const int c = mpz_cmp(s.p, s.q);
    return c > 0 ? 1 : (c < 0 ? -1 : 0);
}

}  // namespace

int cross_sign(Point p1, Point q1, Point p2, Point q2) {
    // (q1 - p1) x (q2 - p2) = (v0 - v1)(v2 - v3) - (v4 - v5)(v6 - v7)
    const Dyadic v[8] = {dyadic(q1.x), dyadic(p1.x), dyadic(q2.y), dyadic(p2.y),
                         dyadic(q1.y), dyadic(p1.y), dyadic(q2.x), dyadic(p2.x)};
    CommonScale scale;
    for (const Dyadic& d : v) scale.add(d);
    if (scale.bits() <= 62) return cross_sign_64(scale, v);
    if (scale.bits() <= 125) return cross_sign_128(scale, v);
    return cross_sign_gmp(scale, v);
}

int orientation(Point a, Point b, Point c) { return cross_sign(a, b, a, c); }

int direction_order(Point p1, Point q1, Point p2, Point q2) {
    auto upper = [](Point p, Point q) { return q.y > p.y || (q.y == p.y && q.x > p.x); };
    const bool u1 = upper(p1, q1), u2 = upper(p2, q2);
    if (u1 != u2) return u1 ? -1 : 1;
    return -cross_sign(p1, q1, p2, q2);  // within a half-plane: the first is clockwise of the second
}

int angle_order(Point centre, Point a, Point b) { return direction_order(centre, a, centre, b); }

Rational twice_area(const std::vector<Point>& ring) {
    std::vector<Dyadic> xs, ys;
    xs.reserve(ring.size());
    ys.reserve(ring.size());
    CommonScale scale;
    for (const Point& p : ring) {
        xs.push_back(dyadic(p.x));
        ys.push_back(dyadic(p.y));
        scale.add(xs.back());
        scale.add(ys.back());
    }
    const std::size_t n = ring.size();
    BigInt sum = 0;
    if (scale.bits() <= 52 && n < (std::size_t{1} << 20U)) {
        // Each term below 2^105, fewer than 2^21 of them: below 2^126.
        Wide s = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            s += static_cast<Wide>(scale.small(xs[i])) * scale.small(ys[j]) -
                 static_cast<Wide>(scale.small(ys[i])) * scale.small(xs[j]);
        }
        const bool negative = s < 0;
        const auto magnitude = static_cast<UWide>(negative ? -s : s);
        sum = static_cast<std::uint64_t>(magnitude >> 64U);
        sum <<= 64U;
        sum += static_cast<std::uint64_t>(magnitude);
        if (negative) sum = -sum;
    } else {
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t j = (i + 1) % n;
            sum += scale.big(xs[i]) * scale.big(ys[j]) - scale.big(ys[i]) * scale.big(xs[j]);
        }
    }
    return Rational(sum) * power_of_two(2 * scale.scale());
}

int winding_number(Point p, const std::vector<Point>& ring) {
    int w = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point a = ring[i], b = ring[(i + 1) % ring.size()];
        // An edge counts when it crosses the horizontal line through p
        // (half-open in y) to the right of p: upwards with p on its left,
        // downwards with p on its right.
        if (a.y <= p.y) {
            if (b.y > p.y && orientation(a, b, p) > 0) ++w;
        } else if (b.y <= p.y && orientation(a, b, p) < 0) {
            --w;
        }
    }
    return w;
}

bool is_nearest_double(double v, const Rational& exact_value) {
    constexpr double kMax = std::numeric_limits<double>::max();
    const Rational overflow = exact(kMax) + exact(std::ldexp(1.0, 970));  // halfway to 2^1024
    if (std::isinf(v)) return v > 0 ? exact_value >= overflow : exact_value <= -overflow;
    if (!std::isfinite(v)) return false;
    const Rational error = abs(exact(v) - exact_value);
    for (const double neighbour : {std::nextafter(v, HUGE_VAL), std::nextafter(v, -HUGE_VAL)}) {
        if (std::isinf(neighbour)) continue;  // beyond v lies overflow, checked above by symmetry
        const Rational other = abs(exact(neighbour) - exact_value);
        if (other < error) return false;
        // A tie goes to the even significand: the last bit of the pattern.
        if (other == error && (std::bit_cast<std::uint64_t>(std::fabs(v)) & 1U) != 0) return false;
    }
    return std::fabs(v) < kMax || abs(exact_value) < overflow;
}

namespace {

// Segment tests written once over any view of points: V gives point(a) and
// orientation(a, b, c) for its handles (Points themselves, or indexes into
// an ExactPoints).
template <class V, class H>
bool strictly_on_segment_in(const V& view, H a, H b, H p) {
    const Point pa = view.point(a), pb = view.point(b), pp = view.point(p);
    if (pp == pa || pp == pb) return false;
    return between(pa.x, pp.x, pb.x) && between(pa.y, pp.y, pb.y) && view.orientation(a, b, p) == 0;
}

template <class V, class H>
Meeting meeting_in(const V& view, H a, H b, H c, H d) {
    const Point pa = view.point(a), pb = view.point(b), pc = view.point(c), pd = view.point(d);
    if ((pa == pc && pb == pd) || (pa == pd && pb == pc)) return Meeting::Same;
    const bool shared = pa == pc || pa == pd || pb == pc || pb == pd;
    auto inside = [&] {
        return strictly_on_segment_in(view, a, b, c) || strictly_on_segment_in(view, a, b, d) ||
               strictly_on_segment_in(view, c, d, a) || strictly_on_segment_in(view, c, d, b);
    };
    const int o1 = view.orientation(a, b, c), o2 = view.orientation(a, b, d);
    if (o1 == 0 && o2 == 0) {
        // Collinear: they share more than a point when an end of one lies inside the other.
        if (inside()) return Meeting::Overlap;
        return shared ? Meeting::SharedEndpoint : Meeting::None;
    }
    const int o3 = view.orientation(c, d, a), o4 = view.orientation(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0) return Meeting::Crossing;
    if (inside()) return Meeting::Touch;
    return shared ? Meeting::SharedEndpoint : Meeting::None;
}

// Points as their own handles.
struct Plain {
    static Point point(Point p) { return p; }
    static int orientation(Point a, Point b, Point c) { return dcel::oracle::orientation(a, b, c); }
};

}  // namespace

bool strictly_on_segment(Point a, Point b, Point p) { return strictly_on_segment_in(Plain{}, a, b, p); }

Meeting meeting(Point a, Point b, Point c, Point d) { return meeting_in(Plain{}, a, b, c, d); }

ExactPoints::ExactPoints(const std::vector<Point>& points) : points_(&points) {
    std::vector<Dyadic> d;
    d.reserve(2 * points.size());
    CommonScale scale;
    for (const Point& p : points) {
        for (const double v : {p.x, p.y}) {
            if (!std::isfinite(v)) return;  // stays on the per-call route
            d.push_back(dyadic(v));
            scale.add(d.back());
        }
    }
    if (scale.bits() > 62) return;
    integers_ = true;
    x_.reserve(points.size());
    y_.reserve(points.size());
    for (std::size_t i = 0; i < d.size(); i += 2) {
        x_.push_back(scale.small(d[i]));
        y_.push_back(scale.small(d[i + 1]));
    }
}

int ExactPoints::orientation(Index a, Index b, Index c) const {
    if (!integers_) return dcel::oracle::orientation(point(a), point(b), point(c));
    // Differences below 2^63, products below 2^126: exact in 128 bits.
    const Wide det = static_cast<Wide>(x_[b] - x_[a]) * (y_[c] - y_[a]) - static_cast<Wide>(y_[b] - y_[a]) * (x_[c] - x_[a]);
    return sign_of(det);
}

int ExactPoints::angle_order(Index centre, Index a, Index b) const {
    const Point c = point(centre), pa = point(a), pb = point(b);
    auto upper = [&](Point q) { return q.y > c.y || (q.y == c.y && q.x > c.x); };
    if (upper(pa) != upper(pb)) return upper(pa) ? -1 : 1;
    return -orientation(centre, a, b);
}

bool ExactPoints::strictly_on_segment(Index a, Index b, Index p) const { return strictly_on_segment_in(*this, a, b, p); }

Meeting ExactPoints::meeting(Index a, Index b, Index c, Index d) const { return meeting_in(*this, a, b, c, d); }

Rational parameter_of_point(Point a, Point b, Point p) {
    const Rational wx = exact(b.x) - exact(a.x), wy = exact(b.y) - exact(a.y);
    return ((exact(p.x) - exact(a.x)) * wx + (exact(p.y) - exact(a.y)) * wy) / (wx * wx + wy * wy);
}

Rational parameter_of_crossing(Point a, Point b, Point c, Point d) {
    const Rational wx = exact(b.x) - exact(a.x), wy = exact(b.y) - exact(a.y);
    const Rational ex = exact(d.x) - exact(c.x), ey = exact(d.y) - exact(c.y);
    const Rational cx = exact(c.x) - exact(a.x), cy = exact(c.y) - exact(a.y);
    return (cx * ey - cy * ex) / (wx * ey - wy * ex);
}

}  // namespace dcel::oracle
