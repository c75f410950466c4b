#include "dcel/io/json_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>
#include "dcel/contracts.hpp"
#include "dcel/core/utf8.hpp"

#include "dcel/format.hpp"
#include "dcel/io/decimal.hpp"

namespace dcel::io {

namespace {

constexpr Index kMaxIndex = kNoIndex - 1;  // 4294967294: the largest id that is not null
constexpr std::size_t kMaxShown = 40;      // longest piece of input echoed in a message

// (Member functions use JsonReader's own is_digit, is_space and is_word_char.)
[[nodiscard]] constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
[[nodiscard]] constexpr bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
[[nodiscard]] constexpr int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

constexpr char kHexDigits[] = "0123456789ABCDEF";

std::string hex_byte(unsigned char b) { return {kHexDigits[b >> 4], kHexDigits[b & 15]}; }

std::string code_point_name(std::uint32_t cp) {
    std::string s = "U+";
    char buf[8];
    int n = 0;
    do {
        buf[n++] = kHexDigits[cp & 15];
        cp >>= 4;
    } while (cp != 0 || n < 4);
    while (n > 0) s += buf[--n];
    return s;
}

std::uint32_t hex4(std::string_view s, std::size_t i) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = (v << 4) | static_cast<std::uint32_t>(hex_value(s[i + k]));
    return v;
}

// Unescape a string body that scan_string() has validated.
std::string unescape(std::string_view raw) {
    std::string out;
    out.reserve(raw.size());
    for (std::size_t i = 0; i < raw.size();) {
        if (raw[i] != '\\') {
            out += raw[i++];
            continue;
        }
        const char e = raw[i + 1];
        i += 2;
        switch (e) {
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                std::uint32_t cp = hex4(raw, i);
                i += 4;
                if (cp >= 0xD800 && cp <= 0xDBFF) {
                    const std::uint32_t low = hex4(raw, i + 2);
                    i += 6;
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                }
                detail::append_utf8(out, cp);
                break;
            }
            default: out += e; break;  // " \ /
        }
    }
    return out;
}

// A piece of input (ASCII word characters) for a message, cut to kMaxShown.
std::string shown(std::string_view word) {
    if (word.size() <= kMaxShown) return std::string(word);
    return std::string(word.substr(0, kMaxShown)) + "...";
}

// The same in single quotes. (Built with append: GCC 12 gives a false
// -Wrestrict warning at -O3 for "'" + std::string&&, GCC bug 105329.)
std::string single_quoted(std::string_view word) {
    std::string out(1, '\'');
    out += shown(word);
    out += '\'';
    return out;
}

// A key for a message or path: printable, one line, at most kMaxShown bytes.
bool is_identifier(std::string_view key) {
    if (key.empty() || is_digit(key[0])) return false;
    return std::all_of(key.begin(), key.end(), [](char c) { return is_digit(c) || is_alpha(c) || c == '_'; });
}

// A key for a message or path: quoted, escaped, at most kMaxShown bytes.
std::string quoted_key(std::string_view key) { return quote_for_message(key, kMaxShown); }

// "character 'x'", "control character U+0001", "character U+00E9", "byte 0xFF".
std::string describe_char(std::string_view s, std::size_t i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == '\'') return "character \"'\"";
    if (c >= 0x20 && c < 0x7F) return std::string("character '") + static_cast<char>(c) + "'";
    if (c < 0x80) return "control character " + code_point_name(c);
    char32_t cp = 0;
    if (detail::utf8_sequence(s, i, &cp) != 0) return "character " + code_point_name(cp);
    return "byte 0x" + hex_byte(c) + " (not valid UTF-8)";
}

bool equals_lowercase(std::string_view word, std::string_view lower) {
    if (word.size() != lower.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i) {
        char c = word[i];
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
        if (c != lower[i]) return false;
    }
    return true;
}

bool is_nan_or_infinity(std::string_view word) {
    if (!word.empty() && (word[0] == '-' || word[0] == '+')) word.remove_prefix(1);
    return equals_lowercase(word, "nan") || equals_lowercase(word, "inf") || equals_lowercase(word, "infinity");
}

// A validated JSON number, taken apart for the slow paths: the value is
// 0.d1 d2 d3 ... (the integer digits then the fraction digits) scaled so
// that the digit at index i has place value 10^(int_digits.size() - 1 - i + exponent).
struct DecimalParts {
    bool negative = false;
    bool zero = true;
    // Place values (powers of ten) of the first and last nonzero digits.
    std::int64_t lead_exp = 0;
    std::int64_t last_exp = 0;
    std::string_view int_digits;
    std::string_view frac_digits;
    std::int64_t first_nonzero = 0;  // index into the concatenated digits
    std::int64_t last_nonzero = 0;

    [[nodiscard]] char digit(std::int64_t i) const {
        const auto n = static_cast<std::int64_t>(int_digits.size());
        return i < n ? int_digits[static_cast<std::size_t>(i)] : frac_digits[static_cast<std::size_t>(i - n)];
    }
};

DecimalParts decompose(std::string_view tok) {
    DecimalParts d;
    std::size_t i = 0;
    if (tok[i] == '-') {
        d.negative = true;
        ++i;
    }
    std::size_t b = i;
    while (i < tok.size() && is_digit(tok[i])) ++i;
    d.int_digits = tok.substr(b, i - b);
    if (i < tok.size() && tok[i] == '.') {
        b = ++i;
        while (i < tok.size() && is_digit(tok[i])) ++i;
        d.frac_digits = tok.substr(b, i - b);
    }
    std::int64_t exponent = 0;
    if (i < tok.size() && (tok[i] == 'e' || tok[i] == 'E')) {
        ++i;
        bool negative_exponent = false;
        if (i < tok.size() && (tok[i] == '+' || tok[i] == '-')) negative_exponent = tok[i++] == '-';
        constexpr std::int64_t kCap = std::int64_t{1} << 50;  // far beyond any double, far below overflow
        for (; i < tok.size(); ++i) exponent = std::min(kCap, exponent * 10 + (tok[i] - '0'));
        if (negative_exponent) exponent = -exponent;
    }
    const auto n = static_cast<std::int64_t>(d.int_digits.size() + d.frac_digits.size());
    const auto int_n = static_cast<std::int64_t>(d.int_digits.size());
    std::int64_t k = 0;
    while (k < n && d.digit(k) == '0') ++k;
    if (k == n) return d;
    std::int64_t m = n - 1;
    while (d.digit(m) == '0') --m;
    d.zero = false;
    d.first_nonzero = k;
    d.last_nonzero = m;
    d.lead_exp = int_n - 1 - k + exponent;
    d.last_exp = int_n - 1 - m + exponent;
    return d;
}

}  // namespace

const char* describe(JsonType type) {
    switch (type) {
        case JsonType::Null: return "null";
        case JsonType::False: return "false";
        case JsonType::True: return "true";
        case JsonType::Number: return "a number";
        case JsonType::String: return "a string";
        case JsonType::Array: return "an array";
        case JsonType::Object: return "an object";
    }
    return "a value";
}

JsonReader::JsonReader(std::string_view text) : text_(text) {
    if (text_.size() >= 3 && text_.substr(0, 3) == "\xEF\xBB\xBF") text_.remove_prefix(3);
}

// ---------------------------------------------------------------- locations

std::string JsonReader::location(std::size_t offset) const {
    offset = std::min(offset, text_.size());
    const std::string_view before = text_.substr(0, offset);
    const auto line = 1 + std::count(before.begin(), before.end(), '\n');
    const std::size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
    // Columns count characters, not bytes: skip UTF-8 continuation bytes.
    const auto column = 1 + std::count_if(before.begin() + static_cast<std::ptrdiff_t>(line_start), before.end(),
                                          [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::string JsonReader::path(std::size_t levels) const {
    std::string out;
    for (std::size_t i = 0; i < std::min(levels, depth_); ++i) {
        const Frame& f = frames_[i];
        if (f.count == 0) break;
        if (!f.object) {
            out += '[';
            out += std::to_string(f.count - 1);
            out += ']';
            continue;
        }
        const std::string_view raw = text_.substr(f.key_begin, f.key_end - f.key_begin);
        const std::string key = f.key_escaped ? unescape(raw) : std::string(raw);
        if (is_identifier(key) && key.size() <= kMaxShown) {
            if (!out.empty()) out += '.';
            out += key;
        } else {
            out += '[';
            out += quoted_key(key);
            out += ']';
        }
    }
    return out;
}

void JsonReader::fail(InputErrorKind kind, std::string_view message) const {
    std::string p = path();
    if (p.empty()) p = "top level";
    throw InvalidInput(kind, p + ": " + std::string(message));
}

void JsonReader::fail_syntax(std::size_t offset, std::string_view message) const {
    throw InvalidInput(InputErrorKind::Syntax, location(offset) + ": " + std::string(message));
}

void JsonReader::fail_type(std::string_view expected) {
    const JsonType t = peek();
    if (t == JsonType::Number) static_cast<void>(scan_number());  // a malformed number is a syntax error first
    if (t == JsonType::String) {
        bool escaped = false;
        static_cast<void>(scan_string(escaped));
    }
    fail(InputErrorKind::Shape, "expected " + std::string(expected) + ", found " + describe(t));
}

void JsonReader::fail_arity(std::string_view expected, std::uint64_t count) const {
    std::string found = count == 0 ? "an empty array"
                                   : "an array of " + std::to_string(count) + (count == 1 ? " element" : " elements");
    fail(InputErrorKind::Shape, "expected " + std::string(expected) + ", found " + found);
}

void JsonReader::fail_missing_key(std::string_view key, std::string_view form) const {
    const std::string p = path();
    throw InvalidInput(InputErrorKind::Shape,
                       (p.empty() ? "" : p + ": ") + "missing key " + quoted_key(key) + ": expected " + std::string(form));
}

void JsonReader::fail_duplicate_key() const {
    DCEL_ASSERT(depth_ > 0 && frames_[depth_ - 1].object);
    std::string where = path(depth_ - 1);
    if (where.empty()) where = "top level";
    const std::size_t key_quote = frames_[depth_ - 1].key_begin - 1;
    throw InvalidInput(InputErrorKind::Shape, where + ": duplicate key " + quoted_key(key_) + " at " + location(key_quote) +
                                                  ": give each key once");
}

void JsonReader::fail_unexpected(std::size_t offset, std::string_view expected) const {
    if (offset >= text_.size()) {
        fail_syntax(offset, "unexpected end of input: expected " + std::string(expected) + " (is the document truncated?)");
    }
    fail_syntax(offset, "unexpected " + describe_char(text_, offset) + ": expected " + std::string(expected));
}

// At a value position, text_[offset] cannot start a value (or starts a
// malformed literal): say what it looks like.
void JsonReader::fail_bad_word(std::size_t offset) const {
    const char c = text_[offset];
    if (c == '\'') fail_syntax(offset, "unexpected single quote: JSON strings are written in double quotes");
    if (c == '/') fail_syntax(offset, "unexpected '/': JSON has no comments");
    if (!is_word_char(c)) fail_unexpected(offset, "a JSON value");
    std::size_t end = offset;
    while (end < text_.size() && is_word_char(text_[end])) ++end;
    const std::string_view word = text_.substr(offset, end - offset);
    const std::string w = single_quoted(word);
    if (is_nan_or_infinity(word)) {
        fail_syntax(offset, "invalid literal " + w + ": JSON has no NaN or Infinity; coordinates must be finite numbers");
    }
    if (c == '+') fail_syntax(offset, "invalid number " + w + ": JSON numbers have no '+' sign; drop it");
    if (c == '.') fail_syntax(offset, "invalid number " + w + ": write a digit before the decimal point (0.5, not .5)");
    if (equals_lowercase(word, "true") || equals_lowercase(word, "false") || equals_lowercase(word, "null")) {
        fail_syntax(offset, "invalid literal " + w + ": JSON literals are lowercase (true, false, null)");
    }
    fail_syntax(offset, "invalid literal " + w +
                            ": expected a JSON value (a number, a string in double quotes, an array, an object, "
                            "true, false or null)");
}

void JsonReader::fail_index(std::string_view noun, std::size_t begin, std::size_t end) const {
    const std::string_view tok = text_.substr(begin, end - begin);
    const DecimalParts d = decompose(tok);
    const std::string what = std::string(noun) + " " + shown(tok);
    if (!d.zero && d.negative) fail(InputErrorKind::BadIndex, what + " is negative: ids count from 0");
    if (!d.zero && d.last_exp < 0) fail(InputErrorKind::BadIndex, what + " is not an integer");
    fail(InputErrorKind::BadIndex, what + " is too large: ids are 32-bit, the largest is " + std::to_string(kMaxIndex));
}

// ---------------------------------------------------------------- scanning

// The rest of peek(): the end of input, the literals, and anything else.
JsonType JsonReader::peek_slow() {
    skip_whitespace();
    if (pos_ >= text_.size()) {
        if (depth_ == 0) fail_syntax(pos_, "empty input: expected a JSON document");
        fail_unexpected(pos_, "a JSON value");
    }
    const auto literal = [&](std::string_view word, JsonType type) {
        if (text_.substr(pos_, word.size()) == word &&
            (pos_ + word.size() == text_.size() || !is_word_char(text_[pos_ + word.size()]))) {
            return type;
        }
        fail_bad_word(pos_);
    };
    // peek() has already answered for '[', '{', '"', '-' and digits.
    switch (text_[pos_]) {
        case 't': return literal("true", JsonType::True);
        case 'f': return literal("false", JsonType::False);
        case 'n': return literal("null", JsonType::Null);
        default: fail_bad_word(pos_);
    }
}

std::size_t JsonReader::scan_number() {
    const std::size_t n = text_.size();
    const std::size_t begin = pos_;
    std::size_t p = pos_;
    const auto word = [&] {
        std::size_t e = begin;
        while (e < n && is_word_char(text_[e])) ++e;
        return single_quoted(text_.substr(begin, e - begin));
    };
    if (text_[p] == '-') {
        ++p;
        if (p >= n || !is_digit(text_[p])) {
            if (p < n && is_alpha(text_[p])) fail_bad_word(begin);  // -Infinity, -NaN
            if (p < n && text_[p] == '.') {
                fail_syntax(begin, "invalid number " + word() + ": write a digit before the decimal point (-0.5, not -.5)");
            }
            fail_syntax(begin, "invalid number " + word() + ": a minus sign must be followed by a digit");
        }
    }
    if (text_[p] == '0') {
        ++p;
        if (p < n && is_digit(text_[p])) fail_syntax(begin, "invalid number " + word() + ": leading zeros are not allowed");
        if (p < n && (text_[p] == 'x' || text_[p] == 'X')) {
            fail_syntax(begin, "invalid number " + word() + ": hexadecimal numbers are not allowed; write it in decimal");
        }
    } else {
        while (p < n && is_digit(text_[p])) ++p;
    }
    if (p < n && text_[p] == '.') {
        ++p;
        if (p >= n || !is_digit(text_[p])) {
            fail_syntax(begin, "invalid number " + word() + ": a digit must follow the decimal point (1.0 or 1, not 1.)");
        }
        while (p < n && is_digit(text_[p])) ++p;
    }
    if (p < n && (text_[p] == 'e' || text_[p] == 'E')) {
        ++p;
        if (p < n && (text_[p] == '+' || text_[p] == '-')) ++p;
        if (p >= n || !is_digit(text_[p])) {
            fail_syntax(begin, "invalid number " + word() + ": the exponent has no digits (write 1e5, not 1e)");
        }
        while (p < n && is_digit(text_[p])) ++p;
    }
    if (p < n && is_word_char(text_[p])) {
        fail_syntax(begin, "invalid number " + word() + ": a number must be followed by ',', ']', '}' or whitespace");
    }
    return p;
}

// The hot loop runs over plain ASCII; everything else (escapes, control
// characters, UTF-8 sequences, the end) is a step of its own.
std::size_t JsonReader::scan_string(bool& escaped) {
    const std::size_t n = text_.size();
    std::size_t p = pos_ + 1;
    escaped = false;
    for (;;) {
        while (p < n) {
            const auto c = static_cast<unsigned char>(text_[p]);
            if (c == '"' || c == '\\' || c < 0x20 || c >= 0x80) break;
            ++p;
        }
        if (p >= n) {
            fail_syntax(pos_, "unterminated string: no closing '\"' before the end of input (is the document truncated?)");
        }
        const auto c = static_cast<unsigned char>(text_[p]);
        if (c == '"') return p + 1;
        if (c == '\\') {
            escaped = true;
            p = scan_escape(p);
        } else if (c < 0x20) {
            fail_control_character(p);
        } else {
            p = scan_utf8(p);
        }
    }
}

std::size_t JsonReader::scan_escape(std::size_t p) const {
    const std::size_t n = text_.size();
    if (p + 1 >= n) fail_syntax(pos_, "unterminated string: the input ends inside an escape");
    const char e = text_[p + 1];
    if (e == '"' || e == '\\' || e == '/' || e == 'b' || e == 'f' || e == 'n' || e == 'r' || e == 't') return p + 2;
    if (e != 'u') {
        const auto ec = static_cast<unsigned char>(e);
        const std::string shown_escape = ec > 0x20 && ec < 0x7F && e != '\''
                                             ? "'\\" + std::string(1, e) + "'"
                                             : "'\\' followed by " + describe_char(text_, p + 1);
        fail_syntax(p, "invalid escape " + shown_escape +
                           " in a string: the escapes are \\\" \\\\ \\/ \\b \\f \\n \\r \\t and \\uXXXX");
    }
    return scan_unicode_escape(p);
}

// A 'u' escape of 4 hex digits, or a surrogate pair of two (a high
// surrogate D800-DBFF must be followed by a low one, DC00-DFFF).
std::size_t JsonReader::scan_unicode_escape(std::size_t p) const {
    const std::size_t n = text_.size();
    const auto is_hex4 = [&](std::size_t at) {
        if (n - at < 4) return false;
        for (std::size_t k = 0; k < 4; ++k) {
            if (hex_value(text_[at + k]) < 0) return false;
        }
        return true;
    };
    if (!is_hex4(p + 2)) fail_syntax(p, "invalid escape in a string: \\u must be followed by 4 hex digits");
    const std::uint32_t cp = hex4(text_, p + 2);
    const std::string esc = single_quoted(text_.substr(p, 6));
    if (cp >= 0xDC00 && cp <= 0xDFFF) {
        fail_syntax(p, "unpaired surrogate " + esc + " in a string: a low surrogate must follow a high one");
    }
    if (cp < 0xD800 || cp > 0xDBFF) return p + 6;
    const bool paired = n - p >= 12 && text_[p + 6] == '\\' && text_[p + 7] == 'u' && is_hex4(p + 8) &&
                        hex4(text_, p + 8) >= 0xDC00 && hex4(text_, p + 8) <= 0xDFFF;
    if (!paired) {
        fail_syntax(
            p, "unpaired surrogate " + esc + " in a string: a high surrogate must be followed by a \\uDC00-\\uDFFF escape");
    }
    return p + 12;
}

void JsonReader::fail_control_character(std::size_t p) const {
    const auto c = static_cast<unsigned char>(text_[p]);
    std::string fix;
    switch (c) {
        case '\n': fix = "\\n"; break;
        case '\r': fix = "\\r"; break;
        case '\t': fix = "\\t"; break;
        case '\b': fix = "\\b"; break;
        case '\f': fix = "\\f"; break;
        default: fix = "\\u00" + hex_byte(c); break;
    }
    fail_syntax(p, "control character " + code_point_name(c) + " in a string: escape it as " + fix +
                       (c == '\n' ? " (or is a closing '\"' missing?)" : ""));
}

// One UTF-8 sequence (a byte >= 0x80 starts it): its end, or an error.
std::size_t JsonReader::scan_utf8(std::size_t p) const {
    const std::size_t len = detail::utf8_sequence(text_, p);
    if (len == 0) {
        const auto c = static_cast<unsigned char>(text_[p]);
        fail_syntax(p, "invalid UTF-8 in a string (byte 0x" + hex_byte(c) + "): the document must be UTF-8");
    }
    return p + len;
}

// ---------------------------------------------------------------- structure

void JsonReader::fail_too_deep() const {
    fail_syntax(pos_, "nesting deeper than " + std::to_string(kMaxDepth) +
                          " levels: arrays and objects may be nested at most that deep");
}

void JsonReader::begin_object(std::string_view expected) {
    if (peek() != JsonType::Object) fail_type(expected);
    open(true);
}

bool JsonReader::next_member() {
    DCEL_ASSERT(depth_ > 0 && frames_[depth_ - 1].object);
    Frame& f = frames_[depth_ - 1];
    skip_whitespace();
    if (pos_ >= text_.size()) fail_unexpected(pos_, f.count == 0 ? "a key in double quotes or '}'" : "',' or '}'");
    if (text_[pos_] == '}') {
        ++pos_;
        close();
        return false;
    }
    if (f.count != 0) {
        if (text_[pos_] != ',') fail_unexpected(pos_, "',' or '}' after an object member");
        ++pos_;
        skip_whitespace();
        if (pos_ < text_.size() && text_[pos_] == '}') {
            fail_syntax(pos_, "unexpected '}' after ',': JSON does not allow trailing commas");
        }
    }
    if (pos_ >= text_.size()) fail_unexpected(pos_, "a key in double quotes");
    if (text_[pos_] != '"') {
        if (text_[pos_] == '\'') fail_syntax(pos_, "unexpected single quote: JSON keys are written in double quotes");
        if (is_alpha(text_[pos_]))
            fail_syntax(pos_, "unexpected " + describe_char(text_, pos_) + ": JSON keys must be in double quotes");
        fail_unexpected(pos_, "a key in double quotes");
    }
    bool escaped = false;
    const std::size_t end = scan_string(escaped);
    f.key_begin = pos_ + 1;
    f.key_end = end - 1;
    f.key_escaped = escaped;
    ++f.count;
    const std::string_view raw = text_.substr(f.key_begin, f.key_end - f.key_begin);
    if (escaped) {
        key_buffer_ = unescape(raw);
        key_ = key_buffer_;
    } else {
        key_ = raw;
    }
    pos_ = end;
    skip_whitespace();
    if (pos_ >= text_.size() || text_[pos_] != ':') {
        fail_unexpected(pos_, "':' after the key " + quoted_key(key_));
    }
    ++pos_;
    remember_key();
    return true;
}

namespace {
// Up to this many keys an object's keys are compared one by one; past it
// they go into a hash set.
constexpr std::size_t kLinearKeys = 16;
}  // namespace

void JsonReader::remember_key() {
    Frame& f = frames_[depth_ - 1];
    std::string_view k = key_;
    if (f.key_escaped) k = arena_.emplace_back(key_);
    const auto mine = keys_.begin() + static_cast<std::ptrdiff_t>(f.keys_begin);
    if (f.key_set) {
        if (!key_sets_[depth_ - 1].insert(k).second) fail_duplicate_key();
    } else {
        if (std::find(mine, keys_.end(), k) != keys_.end()) fail_duplicate_key();
        if (static_cast<std::size_t>(keys_.end() - mine) == kLinearKeys) {
            if (key_sets_.size() < depth_) key_sets_.resize(depth_);
            key_sets_[depth_ - 1].insert(mine, keys_.end());
            key_sets_[depth_ - 1].insert(k);
            f.key_set = true;
        }
    }
    keys_.push_back(k);
}

void JsonReader::forget_keys(const Frame& f) {
    keys_.resize(f.keys_begin);
    while (arena_.size() > f.arena_begin) arena_.pop_back();
    if (f.key_set) key_sets_[depth_].clear();  // depth_ is already this frame's index
}

int JsonReader::next_known_member(std::span<const std::string_view> known, std::uint64_t& seen) {
    while (next_member()) {
        for (std::size_t i = 0; i < known.size(); ++i) {
            if (key_ != known[i]) continue;
            const std::uint64_t bit = std::uint64_t{1} << i;
            if ((seen & bit) != 0) fail_duplicate_key();
            seen |= bit;
            return static_cast<int>(i);
        }
        skip_value();
    }
    return -1;
}

std::uint64_t JsonReader::finish_array() {
    while (next_element()) skip_value();
    return last_closed_count_;
}

std::string JsonReader::read_string(std::string_view expected) {
    if (peek() != JsonType::String) fail_type(expected);
    bool escaped = false;
    const std::size_t end = scan_string(escaped);
    const std::string_view raw = text_.substr(pos_ + 1, end - pos_ - 2);
    std::string value = escaped ? unescape(raw) : std::string(raw);
    pos_ = end;
    return value;
}

std::string_view JsonReader::read_number_text(std::string_view expected) {
    if (peek() != JsonType::Number) fail_type(expected);
    const std::size_t begin = pos_;
    pos_ = scan_number();
    return text_.substr(begin, pos_ - begin);
}

void JsonReader::skip_value() {
    const std::size_t base = depth_;
    for (;;) {
        switch (const JsonType t = peek()) {
            case JsonType::Array: open(false); break;
            case JsonType::Object: open(true); break;
            case JsonType::Number: pos_ = scan_number(); break;
            case JsonType::String: {
                bool escaped = false;
                pos_ = scan_string(escaped);
                break;
            }
            default: pos_ += t == JsonType::False ? 5 : 4; break;  // true, null
        }
        // Find the next value position, or return once the value is done.
        for (;;) {
            if (depth_ == base) return;
            if (frames_[depth_ - 1].object ? next_member() : next_element()) break;
        }
    }
}

void JsonReader::end_document() {
    skip_whitespace();
    if (pos_ < text_.size()) {
        fail_syntax(pos_, "unexpected content after the end of the JSON document (" + describe_char(text_, pos_) +
                              "): the input must hold exactly one JSON value");
    }
}

// ---------------------------------------------------------------- scalars

double JsonReader::read_double_slow(std::string_view expected) {
    if (peek() != JsonType::Number) fail_type(expected);
    const std::size_t begin = pos_;
    const std::size_t end = scan_number();
    double value = 0;
    const auto [ptr, ec] = parse_double(text_.data() + begin, text_.data() + end, value);  // from_chars, or strtod_l
    if (ec == std::errc() && ptr == text_.data() + end) {
        pos_ = end;
        return value;
    }
    const std::string_view tok = text_.substr(begin, end - begin);
    if (ec == std::errc::result_out_of_range) {
        // libstdc++ (fast_float) reports result_out_of_range, leaving `value`
        // untouched, both for overflow and for a nonzero literal that rounds
        // to zero. Underflow is not an error: the nearest double is (signed)
        // zero, as for every other decimal. Tell the two apart by the place
        // value of the leading digit.
        const DecimalParts d = decompose(tok);
        if (d.lead_exp < 0) {
            pos_ = end;
            return d.negative ? -0.0 : 0.0;
        }
        fail(InputErrorKind::BadCoordinate,
             shown(tok) + " is beyond the range of a double (magnitudes up to about 1.8e308)");
    }
    fail_syntax(begin, "invalid number '" + shown(tok) + "'");  // not reached: the token is valid JSON
}

Index JsonReader::read_index_slow(std::string_view noun) {
    if (peek() != JsonType::Number) fail_type("a " + std::string(noun) + " (a non-negative integer)");
    const std::size_t begin = pos_;
    const std::size_t end = scan_number();
    // A sign, a fraction or an exponent, or too many digits. Decide exactly, in decimal.
    const DecimalParts d = decompose(text_.substr(begin, end - begin));
    if (d.zero) {
        pos_ = end;
        return 0;
    }
    if (d.negative || d.last_exp < 0 || d.lead_exp >= 10) fail_index(noun, begin, end);
    std::uint64_t v = 0;
    for (std::int64_t i = d.first_nonzero; i <= d.last_nonzero; ++i) v = v * 10 + static_cast<unsigned>(d.digit(i) - '0');
    for (std::int64_t i = 0; i < d.last_exp; ++i) v *= 10;
    if (v > kMaxIndex) fail_index(noun, begin, end);
    pos_ = end;
    return static_cast<Index>(v);
}

Index JsonReader::read_index_or_null(std::string_view noun) {
    const JsonType t = peek();
    if (t == JsonType::Null) {
        pos_ += 4;
        return kNoIndex;
    }
    if (t != JsonType::Number) fail_type("a " + std::string(noun) + " (a non-negative integer) or null");
    return read_index(noun);
}

// ---------------------------------------------------------------- writing

}  // namespace dcel::io
