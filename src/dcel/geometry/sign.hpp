#pragma once

namespace dcel {

enum class Sign : signed char { Negative = -1, Zero = 0, Positive = 1 };

[[nodiscard]] constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
[[nodiscard]] constexpr int to_int(Sign s) { return static_cast<int>(s); }

template <class T>
[[nodiscard]] constexpr Sign sign_of(T v) {
    return v > 0 ? Sign::Positive : (v < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace dcel
