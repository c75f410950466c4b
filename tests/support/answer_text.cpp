#include "support/answer_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace dcel::test_support {
namespace {

constexpr std::array<std::string_view, 6> kSpaces{"", " ", "\n", "\t", "\r\n", "  "};

// Members no reader gives a meaning to anywhere (not "type", which makes an
// object GeoJSON, nor any answer, dump or GeoJSON key), with values that
// exercise the skipping: nesting, escapes, a surrogate pair, literals.
struct Ignored {
    std::string_view key;
    std::string_view value;
};
constexpr std::array<Ignored, 6> kIgnored{{
    {"comment", R"("caf\u00e9 \ud83d\ude00 \"quoted\" \\ \/ \n\t")"},
    {"bbox", "[-1e300, 0, 1E+2, 5e-324]"},
    {"meta", R"({"a": [1, {"b": null, "c": [true, false]}], "d": {}, "e": []})"},
    {"id", "7"},
    {"properties", R"({"name": "\u0000x", "type": "not a GeoJSON type here"})"},
    {"\u00fcber", "false"},
}};

std::string shortest(double x, std::chars_format format) {
    std::array<char, 64> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), x, format);
    return {buf.data(), r.ptr};
}

}  // namespace

AnswerText::AnswerText(Choices& choices) : choices_(choices) {
    spacing_ = choices_.below(4);  // ", " / "," / newlines / mixed
    ids_ = choices_.below(7);      // 3 / 3.0 / 3e0 / 3E+00 / 0.3e1 / 30e-1 / mixed
    doubles_ = choices_.below(5);  // shortest / %.17g / scientific / x.0 for integers / mixed
    keys_ = choices_.below(3);     // plain / first letter \u-escaped / every letter escaped
    flip_zeros_ = choices_.one_in(3);
}

void AnswerText::space() {
    switch (spacing_) {
        case 0: out_ += ' '; break;
        case 1: break;
        case 2: out_ += "\n  "; break;
        default: out_ += kSpaces[choices_.below(kSpaces.size())]; break;
    }
}

void AnswerText::before_value() {
    if (after_key_) {
        after_key_ = false;
        return;
    }
    if (levels_.empty()) return;
    if (levels_.back().count++ != 0) {
        out_ += ',';
        space();
    }
}

void AnswerText::begin_object() {
    before_value();
    out_ += '{';
    levels_.push_back({true, 0, {}});
    if (spacing_ >= 2) space();
}

void AnswerText::end_object() {
    levels_.pop_back();
    if (spacing_ >= 2) space();
    out_ += '}';
}

void AnswerText::begin_array() {
    before_value();
    out_ += '[';
    levels_.push_back({false, 0, {}});
}

void AnswerText::end_array() {
    levels_.pop_back();
    out_ += ']';
}

void AnswerText::key(std::string_view k) {
    levels_.back().keys.emplace_back(k);
    if (levels_.back().count++ != 0) {
        out_ += ',';
        space();
    }
    out_ += '"';
    for (std::size_t i = 0; i < k.size(); ++i) {
        const auto c = static_cast<unsigned char>(k[i]);
        const bool letter = (c >= 'a' && c <= 'z') || c == '_';
        if (letter && (keys_ == 2 || (keys_ == 1 && i == 0))) {
            std::array<char, 8> esc{};
            std::snprintf(esc.data(), esc.size(), i % 2 == 0 ? "\\u%04x" : "\\u%04X", c);
            out_ += esc.data();
        } else {
            out_ += k[i];
        }
    }
    out_ += "\":";
    if (spacing_ != 1) out_ += ' ';
    after_key_ = true;
}

void AnswerText::id(Index v) {
    before_value();
    const std::size_t style = ids_ == 6 ? choices_.below(6) : ids_;
    const std::string digits = std::to_string(v);
    switch (style) {
        case 0: out_ += digits; break;
        case 1: out_ += digits + ".0"; break;
        case 2: out_ += digits + "e0"; break;
        case 3: out_ += digits + "E+00"; break;
        case 4: out_ += "0." + digits + "e" + std::to_string(digits.size()); break;  // 0.37e2 = 37
        default: out_ += (v == 0 ? "0" : digits + "0") + "e-1"; break;               // 370e-1 = 37 (no leading zero: 0e-1)
    }
}

void AnswerText::number(double x) {
    before_value();
    if (x == 0 && flip_zeros_) x = std::signbit(x) ? 0.0 : -0.0;  // -0.0 and 0.0 are one point
    const std::size_t style = doubles_ == 4 ? choices_.below(4) : doubles_;
    switch (style) {
        case 0: out_ += shortest(x, std::chars_format::general); break;
        case 1: {
            std::array<char, 40> buf{};
            std::snprintf(buf.data(), buf.size(), "%.17g", x);  // 17 significant digits read back exactly
            out_ += buf.data();
            break;
        }
        case 2: out_ += shortest(x, std::chars_format::scientific); break;  // 1.5e+00: leading zeros in the exponent
        default:
            // An integer below 2^53 as "3.0"; anything else in full decimal
            // when that stays short, else the shortest form with "E0" added
            // when it has no exponent.
            if (std::trunc(x) == x && std::fabs(x) < 0x1p53) {
                out_ += shortest(x, std::chars_format::fixed) + ".0";
            } else if (const std::string s = shortest(x, std::chars_format::general); s.find('e') == std::string::npos) {
                out_ += s + "E0";
            } else {
                out_ += s;
            }
            break;
    }
}

void AnswerText::literal(std::string_view json) {
    before_value();
    out_ += json;
}

void AnswerText::maybe_ignored_member(const std::vector<std::string_view>& taken) {
    if (!choices_.one_in(4)) return;
    const Ignored& m = kIgnored[choices_.below(kIgnored.size())];
    for (const std::string_view t : taken) {
        if (t == m.key) return;
    }
    for (const std::string& k : levels_.back().keys) {
        if (k == m.key) return;
    }
    key(m.key);
    literal(m.value);
}

}  // namespace dcel::test_support
