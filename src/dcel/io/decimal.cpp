#include "dcel/io/decimal.hpp"

// The C headers on purpose: newlocale and strtod_l are POSIX and glibc/BSD
// extensions that <clocale> and <cstdlib> need not declare.
#include <locale.h>  // NOLINT(modernize-deprecated-headers): newlocale
#include <stdlib.h>  // NOLINT(modernize-deprecated-headers): strtod_l

#include <cerrno>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <string>
#include <system_error>
#include <version>  // __cpp_lib_to_chars

namespace dcel::io {
namespace {

constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// Does [p, last) start with `word`, in any case?
bool starts_with_word(const char* p, const char* last, const char* word) {
    for (; *word != '\0'; ++p, ++word) {
        if (p == last || lower(*p) != *word) return false;
    }
    return true;
}

const char* skip_digits(const char* p, const char* last) {
    while (p != last && is_digit(*p)) ++p;
    return p;
}

// The end of the longest prefix from_chars would read, or `first` if none.
const char* match_end(const char* first, const char* last) {
    const char* p = first;
    if (p != last && *p == '-') ++p;
    if (starts_with_word(p, last, "nan")) {
        p += 3;
        if (p != last && *p == '(') {  // nan(n-char-sequence)
            const char* q = p + 1;
            while (q != last && (is_digit(*q) || (lower(*q) >= 'a' && lower(*q) <= 'z') || *q == '_')) ++q;
            if (q != last && *q == ')') p = q + 1;
        }
        return p;
    }
    if (starts_with_word(p, last, "inf")) return p + (starts_with_word(p + 3, last, "inity") ? 8 : 3);
    const char* const digits = p;
    p = skip_digits(p, last);
    bool any = p != digits;
    if (p != last && *p == '.') {
        const char* const fraction = p + 1;
        const char* const end = skip_digits(fraction, last);
        if (!any && end == fraction) return first;  // "." or "-." alone
        any = true;
        p = end;
    }
    if (!any) return first;
    if (p != last && (*p == 'e' || *p == 'E')) {
        const char* q = p + 1;
        if (q != last && (*q == '+' || *q == '-')) ++q;
        const char* const end = skip_digits(q, last);
        if (end != q) p = end;  // an exponent needs digits, else it is not part of the number
    }
    return p;
}

// The "C" locale always exists, so newlocale fails only for want of memory.
locale_t c_locale() {
    static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
    if (c == static_cast<locale_t>(nullptr)) throw std::bad_alloc();
    return c;
}

}  // namespace

std::from_chars_result parse_double_strtod(const char* first, const char* last, double& value) {
    const char* const end = match_end(first, last);
    if (end == first) return {first, std::errc::invalid_argument};
    const bool negative = *first == '-';
    if (starts_with_word(first + (negative ? 1 : 0), end, "nan")) {
        // from_chars reads nan(chars) but ignores the chars; glibc's strtod
        // would put them in the payload (nan(1) as 0x7ff8000000000001).
        value = std::copysign(std::numeric_limits<double>::quiet_NaN(), negative ? -1.0 : 1.0);
        return {end, std::errc()};
    }
    const std::string token(first, end);  // bounded and NUL-terminated, unlike the input
    errno = 0;
    const double v = strtod_l(token.c_str(), nullptr, c_locale());  // reads all of token: it matched the grammar
    const bool range_error = errno == ERANGE;
    // glibc sets ERANGE for overflow (+-HUGE_VAL) and for underflow; a
    // nonzero subnormal result is still the correctly rounded value.
    if (std::isinf(v) && !starts_with_word(first + (negative ? 1 : 0), end, "inf")) {
        return {end, std::errc::result_out_of_range};
    }
    if (range_error && v == 0) return {end, std::errc::result_out_of_range};
    value = v;
    return {end, std::errc()};
}

std::from_chars_result parse_double(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars) && !defined(DCEL_FORCE_STRTOD)
    return std::from_chars(first, last, value);
#else
    return parse_double_strtod(first, last, value);
#endif
}

}  // namespace dcel::io
