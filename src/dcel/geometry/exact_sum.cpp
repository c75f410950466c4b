#include "dcel/geometry/exact_sum.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace dcel::detail {
namespace {

struct Decomposed {
    std::uint64_t mantissa;  // < 2^53; zero for +-0
    int exponent;            // |value| = mantissa * 2^exponent (callers take the sign from std::signbit)
};

Decomposed decompose(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    const auto biased = static_cast<int>((bits >> 52U) & 0x7FFU);
    const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52U) - 1);
    if (biased == 0) return {fraction, -1074};  // zero or subnormal
    return {fraction | (std::uint64_t{1} << 52U), biased - 1075};
}

}  // namespace

void ExactSum::accumulate(Register& reg, double a, double b) {
    const Decomposed da = decompose(a);
    const Decomposed db = decompose(b);
    if (da.mantissa == 0 || db.mantissa == 0) return;
    __extension__ typedef unsigned __int128 u128;  // NOLINT(modernize-use-using): __extension__ needs typedef
    const u128 product = static_cast<u128>(da.mantissa) * db.mantissa;  // < 2^106
    const int position = da.exponent + db.exponent - kLowestExponent;   // >= 28
    const int limb = position / 64;
    const int shift = position % 64;
    // The product shifted by `shift` spans at most three limbs.
    std::uint64_t parts[3];
    parts[0] = static_cast<std::uint64_t>(product << shift);
    const u128 high = shift == 0 ? (product >> 64U) : (product >> (64 - shift));
    parts[1] = static_cast<std::uint64_t>(high);
    parts[2] = static_cast<std::uint64_t>(high >> 64U);
    std::uint64_t carry = 0;
    int i = limb;
    for (int k = 0; k < 3 || carry != 0; ++k, ++i) {
        const std::uint64_t add = k < 3 ? parts[k] : 0;
        const u128 sum = static_cast<u128>(reg[static_cast<std::size_t>(i)]) + add + carry;
        reg[static_cast<std::size_t>(i)] = static_cast<std::uint64_t>(sum);
        carry = static_cast<std::uint64_t>(sum >> 64U);
    }
}

void ExactSum::add_product(double a, double b) {
    const bool negative = std::signbit(a) != std::signbit(b);
    accumulate(negative ? negative_ : positive_, a, b);
}

void ExactSum::subtract_product(double a, double b) {
    const bool negative = std::signbit(a) != std::signbit(b);
    accumulate(negative ? positive_ : negative_, a, b);
}

int ExactSum::compare(const Register& x, const Register& y) {
    for (int i = kLimbs - 1; i >= 0; --i) {
        const auto k = static_cast<std::size_t>(i);
        if (x[k] != y[k]) return x[k] < y[k] ? -1 : 1;
    }
    return 0;
}

Sign ExactSum::sign() const {
    const int c = compare(positive_, negative_);
    return c > 0 ? Sign::Positive : (c < 0 ? Sign::Negative : Sign::Zero);
}

double ExactSum::to_double(int scale) const {
    const int c = compare(positive_, negative_);
    if (c == 0) return 0.0;
    const Register& big = c > 0 ? positive_ : negative_;
    const Register& small = c > 0 ? negative_ : positive_;
    Register diff{};
    std::uint64_t borrow = 0;
    for (std::size_t i = 0; i < kLimbs; ++i) {
        const std::uint64_t d = big[i] - small[i] - borrow;
        borrow = (big[i] < small[i] || (big[i] == small[i] && borrow != 0)) ? 1 : 0;
        diff[i] = d;
    }
    int top = kLimbs - 1;
    while (diff[static_cast<std::size_t>(top)] == 0) --top;
    // Gather the 64 most significant bits, and fold every bit below them into
    // the lowest one (a sticky bit): enough to round to at most 53 bits.
    const auto t = static_cast<std::size_t>(top);
    const int lead = std::countl_zero(diff[t]);
    std::uint64_t head = diff[t] << lead;
    bool sticky = false;
    if (top > 0) {
        if (lead > 0) head |= diff[t - 1] >> (64 - lead);
        sticky = (lead > 0 ? (diff[t - 1] << lead) : diff[t - 1]) != 0;
        for (std::size_t i = 0; i + 1 < t && !sticky; ++i) sticky = diff[i] != 0;
    }
    if (sticky) head |= 1U;
    // The value is head * 2^exponent, with head's top bit set. Round it to
    // the result's precision here, in integers: 53 bits, fewer where the
    // result is subnormal (its last bit weighs 2^-1074). Converting head to
    // double and then scaling would round twice in the subnormal range.
    const long exponent = static_cast<long>(top) * 64 - lead + kLowestExponent + scale;  // weight of head's bit 0
    const long drop = std::max(11L, -1074 - exponent);                                   // low bits of head that do not fit
    if (drop > 64) return c > 0 ? 0.0 : -0.0;  // below 2^-1075, half the least subnormal
    const std::uint64_t kept = drop == 64 ? 0 : head >> drop;
    const std::uint64_t rest = drop == 64 ? head : head & ((std::uint64_t{1} << drop) - 1);
    const std::uint64_t half = std::uint64_t{1} << (drop - 1);
    const std::uint64_t rounded = kept + ((rest > half || (rest == half && (kept & 1U) != 0)) ? 1 : 0);
    // rounded <= 2^53 is exact as a double, and so is the scaling, unless it
    // overflows to infinity, which is then the correctly rounded result.
    const long at = exponent + drop;
    const double magnitude = at > 2000 ? HUGE_VAL : std::ldexp(static_cast<double>(rounded), static_cast<int>(at));
    return c > 0 ? magnitude : -magnitude;
}

}  // namespace dcel::detail
