// TokenReader: reads a fuzz input as readable text, never throwing.
//
// The structured harnesses (nonplanar, check) take text such as
//   points 0 0, 4 0, 0 4  edges 0 1, 1 2
// so that seeds and minimized crashes can be read and written by hand. Every
// byte string is a valid input: words are runs of letters and '_', numbers
// are whatever std::from_chars reads as a double at a digit, '-' or '.'
// (through dcel::io::parse_double, which also works on libc++)
// (so 1e15, -0, 5e-324 and 0x-free decimals all work; "inf" and "nan" are
// numbers too), '#' starts a comment that runs to the end of the line, and
// every other byte separates tokens. A mutation that
// breaks a number merely splits or drops it, so the fuzzer keeps making
// meaningful inputs. At the end, next() keeps returning an End token.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "dcel/io/decimal.hpp"

namespace dcel::fuzz {

struct Token {
    enum class Kind { End, Word, Number };
    Kind kind = Kind::End;
    std::string_view word;  // for Word: the letters as written
    double number = 0;      // for Number

    [[nodiscard]] bool is_word(std::string_view w) const { return kind == Kind::Word && word == w; }
};

// A number read from the input as an index into n > 0 elements, whatever the
// number is (negative, fractional, huge, NaN): commands always land.
inline std::size_t wrap_index(double v, std::size_t n) {
    if (!std::isfinite(v) || std::fabs(v) > 1e18) return 0;
    return static_cast<std::size_t>(std::llabs(static_cast<long long>(v))) % n;
}

class TokenReader {
public:
    explicit TokenReader(std::string_view text) : text_(text) { advance(); }

    [[nodiscard]] const Token& peek() const { return current_; }
    Token next() {
        Token t = current_;
        advance();
        return t;
    }
    [[nodiscard]] bool at_end() const { return current_.kind == Token::Kind::End; }

    // The next token as a number if it is one (consumed), else nothing consumed
    // and `fallback` returned.
    double number_or(double fallback) {
        if (current_.kind != Token::Kind::Number) return fallback;
        return next().number;
    }

private:
    static bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
    static bool starts_number(char c) { return (c >= '0' && c <= '9') || c == '-' || c == '.'; }
    static bool is_special_number(std::string_view w) {
        return w == "inf" || w == "nan" || w == "infinity" || w == "INF" || w == "NAN";
    }

    void advance() {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '#') {
                while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
                continue;
            }
            if (is_letter(c)) {
                const std::size_t begin = pos_;
                while (pos_ < text_.size() && is_letter(text_[pos_])) ++pos_;
                const std::string_view w = text_.substr(begin, pos_ - begin);
                if (is_special_number(w)) {  // "-inf" is read by from_chars below
                    const double v = (w[0] == 'n' || w[0] == 'N') ? std::numeric_limits<double>::quiet_NaN()
                                                                  : std::numeric_limits<double>::infinity();
                    current_ = Token{Token::Kind::Number, {}, v};
                } else {
                    current_ = Token{Token::Kind::Word, w, 0};
                }
                return;
            }
            if (starts_number(c)) {
                double v = 0;
                const char* first = text_.data() + pos_;
                const auto [ptr, ec] = io::parse_double(first, text_.data() + text_.size(), v);
                if (ec == std::errc() && ptr != first) {
                    pos_ += static_cast<std::size_t>(ptr - first);
                    current_ = Token{Token::Kind::Number, {}, v};
                    return;
                }
            }
            ++pos_;  // a separator, or a number that does not parse (e.g. 1e999)
        }
        current_ = Token{};
    }

    std::string_view text_;
    std::size_t pos_ = 0;
    Token current_;
};

}  // namespace dcel::fuzz
