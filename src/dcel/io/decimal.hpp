// Decimal text to double, correctly rounded, on any standard library.
//
// std::from_chars for double is the tool, but libc++ has it only from LLVM
// 20, and OSS-Fuzz builds with -stdlib=libc++. parse_double() is
// std::from_chars (chars_format::general) where the library has it
// (__cpp_lib_to_chars), and parse_double_strtod() otherwise, or when the
// library is compiled with DCEL_FORCE_STRTOD (to try the fallback
// everywhere). tests/test_decimal.cpp checks the fallback against
// std::from_chars directly.
//
// Both follow libstdc++'s from_chars: the longest prefix of [first, last)
// of the form -?(digits[.digits]|.digits)([eE][+-]?digits)?, or inf,
// infinity, nan, nan(chars) in any case; no leading '+', space or "0x".
// A NaN is the quiet NaN with the sign written, whatever the chars of
// nan(chars). Nothing matches: invalid_argument, ptr = first. Beyond the double range,
// and a nonzero literal whose nearest double is zero (1e-400):
// result_out_of_range, ptr past the match, value untouched.
//
// The fallback copies the match to a NUL-terminated buffer and reads it with
// strtod_l in the "C" locale, which glibc rounds correctly.
#pragma once

#include <charconv>

namespace dcel::io {

[[nodiscard]] std::from_chars_result parse_double(const char* first, const char* last, double& value);
[[nodiscard]] std::from_chars_result parse_double_strtod(const char* first, const char* last, double& value);

}  // namespace dcel::io
