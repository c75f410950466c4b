// The one UTF-8 decoder: the JSON reader checks its strings with it, and the
// message formatting (format.hpp) escapes what it cannot vouch for.
#pragma once

#include <cstddef>
#include <string_view>

namespace dcel::detail {

// The length (1-4) of the well-formed UTF-8 sequence at s[i] (Unicode table
// 3-7: no overlongs, no surrogates, nothing above U+10FFFF), or 0; its code
// point in *code_point when one is given. Inline: the JSON reader calls it
// for every non-ASCII byte of every string.
inline std::size_t utf8_sequence(std::string_view s, std::size_t i, char32_t* code_point = nullptr) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b0 = byte(i);
    if (b0 < 0x80) {
        if (code_point != nullptr) *code_point = b0;
        return 1;
    }
    std::size_t len = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (b0 >= 0xC2 && b0 <= 0xDF) {
        len = 2;
    } else if (b0 >= 0xE0 && b0 <= 0xEF) {
        len = 3;
        if (b0 == 0xE0) lo = 0xA0;
        if (b0 == 0xED) hi = 0x9F;
    } else if (b0 >= 0xF0 && b0 <= 0xF4) {
        len = 4;
        if (b0 == 0xF0) lo = 0x90;
        if (b0 == 0xF4) hi = 0x8F;
    } else {
        return 0;
    }
    if (s.size() - i < len) return 0;
    const unsigned char b1 = byte(i + 1);
    if (b1 < lo || b1 > hi) return 0;
    for (std::size_t k = 2; k < len; ++k) {
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    }
    if (code_point != nullptr) {
        char32_t cp = b0 & (0xFFU >> (len + 1));
        for (std::size_t k = 1; k < len; ++k) cp = (cp << 6) | (byte(i + k) & 0x3FU);
        *code_point = cp;
    }
    return len;
}

}  // namespace dcel::detail
