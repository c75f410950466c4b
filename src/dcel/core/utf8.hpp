// The one UTF-8 decoder and encoder: the JSON reader checks its strings with
// the decoder and turns \u escapes into UTF-8 with the encoder, the message formatting
// (format.hpp) escapes what the decoder cannot vouch for, and the Python
// binding writes a str's code points with the encoder.
#pragma once

#include <cstddef>
#include <string>
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

// Code point cp (at most U+10FFFF) in UTF-8, appended to out. A surrogate
// is written as its three bytes: callers that must not write one check first.
inline void append_utf8(std::string& out, char32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

}  // namespace dcel::detail
