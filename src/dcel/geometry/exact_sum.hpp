// ExactSum: the exact value of a sum of products of finite doubles.
//
// Every finite double is m * 2^e with an integer m < 2^53 and e in [-1074, 971],
// so a product of two lies on a fixed-point grid from 2^-2148 up to 2^2048. Two
// unsigned fixed-point registers (one for positive terms, one for negative) of
// 68 64-bit limbs cover that range with 127 bits of headroom for carries, so no
// sum of fewer than 2^100 terms can overflow or lose a bit. Nothing here uses
// floating-point arithmetic on the values, so underflow and overflow cannot
// occur. It is slow next to a floating-point filter (about 100 ns a product)
// and is meant as the exact fallback and as an oracle that is easy to trust.
#pragma once

#include <array>
#include <cstdint>

#include "dcel/geometry/sign.hpp"

namespace dcel::detail {

class ExactSum {
public:
    void add_product(double a, double b);       // += a * b, exactly
    void subtract_product(double a, double b);  // -= a * b, exactly
    void add(double a) { add_product(a, 1.0); }
    void subtract(double a) { subtract_product(a, 1.0); }

    [[nodiscard]] Sign sign() const;
    // The sum times 2^scale, rounded once to the nearest double (ties to
    // even), subnormals included; +-inf past DBL_MAX. The scale is applied
    // before rounding, so half a sum (scale -1) is not rounded twice.
    [[nodiscard]] double to_double(int scale = 0) const;

private:
    static constexpr int kLimbs = 68;
    static constexpr int kLowestExponent = -2176;  // weight of bit 0 of limb 0
    using Register = std::array<std::uint64_t, kLimbs>;

    static void accumulate(Register& reg, double a, double b);
    [[nodiscard]] static int compare(const Register& x, const Register& y);

    Register positive_{};
    Register negative_{};
};

}  // namespace dcel::detail
