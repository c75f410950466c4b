// The strtod_l fallback of parse_double (dcel/io/decimal.hpp), used where
// the standard library has no floating-point std::from_chars (libc++ before
// LLVM 20), compared with libstdc++'s std::from_chars: the same double bit
// for bit, the same error, the same end of the match, and the value left
// untouched on an error.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <version>

#include "dcel/io/decimal.hpp"

namespace {

#if defined(__cpp_lib_to_chars)

constexpr double kUntouched = -1234.5;  // what `value` holds before each call

// Empty when the fallback agrees with std::from_chars on s.
std::string disagreement(const std::string& s) {
    double want = kUntouched;
    double got = kUntouched;
    const char* const first = s.data();
    const char* const last = s.data() + s.size();
    const auto expected = std::from_chars(first, last, want);
    const auto actual = dcel::io::parse_double_strtod(first, last, got);
    // Bit for bit, NaNs too: nan(1) is the plain quiet NaN to from_chars,
    // where strtod would make 1 its payload.
    const bool same_value = std::bit_cast<std::uint64_t>(got) == std::bit_cast<std::uint64_t>(want);
    if (expected.ec == actual.ec && expected.ptr == actual.ptr && same_value) return "";
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "from_chars: %a ec %d read %td; fallback: %a ec %d read %td", want,
                  static_cast<int>(expected.ec), expected.ptr - first, got, static_cast<int>(actual.ec), actual.ptr - first);
    return "\"" + s + "\": " + buffer;
}

TEST(DecimalFallback, EdgesOfTheGrammar) {
    for (const char* s :
         {"0",          "-0",   "1",        "-1",        "0.5",   ".5",     "-.5",   "5.",   "-5.",   "1e5",
          "1E+5",       "1e-5", "1e",       "1e+",       "1e-",   "1.5e3x", "12abc", "+1",   " 1",    "-",
          ".",          "-.",   "",         "e5",        "0x1p3", "0X10",   "00012", "1..2", "1.2.3", "inf",
          "-inf",       "INF",  "Infinity", "-infinity", "infin", "infx",   "nan",   "-nan", "NaN",   "nan(123)",
          "nan(abc_9)", "nan(", "nan()",    "nan(1 2)",  "in",    "na",     "--1"}) {
        EXPECT_EQ(disagreement(s), "");
    }
}

// glibc's strtod makes the chars of nan(chars) the payload; from_chars does not.
TEST(DecimalFallback, NanCharsAreNoPayload) {
    for (const char* s : {"nan(1)", "-nan(1)", "NaN(0x5)", "nan(123456789012345678901234567890)"}) {
        EXPECT_EQ(disagreement(s), "");
    }
}

TEST(DecimalFallback, SubnormalsUnderflowAndOverflow) {
    for (const char* s : {"4.9406564584124654e-324",
                          "5e-324",
                          "-5e-324",
                          "3e-324",
                          "2.4703282292062328e-324",  // just above half the smallest subnormal: rounds up to it
                          "2.4703282292062327e-324",  // just below: rounds to zero, out of range
                          "2e-324",
                          "1e-400",
                          "-1e-400",
                          "0e-400",
                          "0.000e999",
                          "1e-310",
                          "-1.5e-315",
                          "2.2250738585072011e-308",
                          "2.2250738585072014e-308",
                          "2.2250738585072012e-308",
                          "1.7976931348623157e308",
                          "1.7976931348623158e308",
                          "1.7976931348623159e308",
                          "-1e309",
                          "1e400",
                          "1e99999999999999999999",
                          "1e-99999999999999999999",
                          "0e99999999999999999999"}) {
        EXPECT_EQ(disagreement(s), "");
    }
}

// Inputs that broke real strtod implementations, and halfway cases written
// with and without a deciding digit far to the right.
TEST(DecimalFallback, KnownHardCases) {
    for (const char* s : {"9007199254740993", "9007199254740993.0000000000000000000001", "9007199254740995",
                          "1.00000000000000011102230246251565404236316680908203125",
                          "1.00000000000000011102230246251565404236316680908203125000000000000000001",
                          "1.00000000000000011102230246251565404236316680908203124999999999999999999",
                          "2.2250738585072011e-308", "2.225073858507201136057409796709131975934819546351645648e-308", "0.1",
                          "0.3", "123456789012345678901234567890e-20", "7.038531e-26", "1448997445238699",
                          "8.98846567431158e307", "179769313486231580793728971405301e276",
                          "0.000000000000000000000000000000000000000000000000000000000000000000000000001e75"}) {
        EXPECT_EQ(disagreement(s), "");
    }
}

// Shortest round-trip and 17-digit forms of random doubles of every
// magnitude, subnormals included.
TEST(DecimalFallback, RandomDoublesPrinted) {
    std::mt19937_64 rng(20240611);
    int failures = 0;
    for (int i = 0; i < 100000 && failures < 10; ++i) {
        const double v = std::bit_cast<double>(rng());
        if (!std::isfinite(v)) continue;
        char shortest[64];
        const auto end = std::to_chars(shortest, shortest + sizeof shortest, v);
        char precise[64];
        std::snprintf(precise, sizeof precise, "%.17e", v);
        for (const std::string& s : {std::string(shortest, end.ptr), std::string(precise)}) {
            const std::string d = disagreement(s);
            EXPECT_EQ(d, "");
            failures += d.empty() ? 0 : 1;
        }
    }
}

// Random digit strings: up to 40 digits (beyond double precision, so many
// land near a rounding boundary), a random point, exponents from -400 to 400.
TEST(DecimalFallback, RandomDecimalStrings) {
    std::mt19937_64 rng(7);
    int failures = 0;
    for (int i = 0; i < 100000 && failures < 10; ++i) {
        std::string s = (rng() % 2 == 0) ? "-" : "";
        const int digits = 1 + static_cast<int>(rng() % 40);
        const int point = static_cast<int>(rng() % static_cast<std::uint64_t>(digits + 1));
        for (int k = 0; k < digits; ++k) {
            if (k == point) s += '.';
            s += static_cast<char>('0' + rng() % 10);
        }
        if (rng() % 4 != 0) s += "e" + std::to_string(static_cast<int>(rng() % 801) - 400);
        const std::string d = disagreement(s);
        EXPECT_EQ(d, "");
        failures += d.empty() ? 0 : 1;
    }
}

// Halfway cases: the exact midpoint between two adjacent doubles, written
// out in full, rounds to the even one; a digit more either way decides.
TEST(DecimalFallback, ExactMidpoints) {
    std::mt19937_64 rng(99);
    for (int i = 0; i < 2000; ++i) {
        const double a = std::bit_cast<double>(rng() & 0x7FEFFFFFFFFFFFFFULL);  // positive and finite
        const double b = std::nextafter(a, HUGE_VAL);
        if (std::isinf(b)) continue;
        // The midpoint has 54 significant bits: exact in x86's long double,
        // and printed in full by glibc's %Le.
        const long double exact = (static_cast<long double>(a) + static_cast<long double>(b)) / 2;
        char mid[1200];
        std::snprintf(mid, sizeof mid, "%.1100Le", exact);
        EXPECT_EQ(disagreement(mid), "");
    }
}

#else

TEST(DecimalFallback, NeedsStdFromCharsAsTheOracle) { GTEST_SKIP() << "no floating-point std::from_chars to compare with"; }

#endif

// The fallback reads '.' as the decimal point whatever the global locale.
TEST(DecimalFallback, IgnoresTheGlobalLocale) {
    const char* const saved = std::setlocale(LC_NUMERIC, nullptr);
    const std::string restore = saved != nullptr ? saved : "C";
    bool switched = false;
    for (const char* name : {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8"}) {
        if (std::setlocale(LC_NUMERIC, name) != nullptr) {
            switched = true;
            break;
        }
    }
    if (!switched) GTEST_SKIP() << "no locale with a decimal comma is installed";
    const std::string s = "2.5";
    double v = 0;
    const auto r = dcel::io::parse_double_strtod(s.data(), s.data() + s.size(), v);
    std::setlocale(LC_NUMERIC, restore.c_str());
    EXPECT_EQ(r.ec, std::errc());
    EXPECT_EQ(r.ptr, s.data() + s.size());
    EXPECT_EQ(v, 2.5);
}

TEST(DecimalFallback, ParseDoubleReadsAPlainNumber) {
    const std::string s = "-12.5e-1,";
    double v = 0;
    const auto r = dcel::io::parse_double(s.data(), s.data() + s.size(), v);
    EXPECT_EQ(r.ec, std::errc());
    EXPECT_EQ(r.ptr, s.data() + 8);
    EXPECT_EQ(v, -1.25);
}

}  // namespace
