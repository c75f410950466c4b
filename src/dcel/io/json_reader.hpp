// JsonReader: a small, strict JSON pull parser (RFC 8259) for the dcel readers.
//
// Why our own parser rather than a third-party JSON library (the library has
// no dependencies beyond the standard library, and these are the reasons it
// does not take one here):
//  - Precise errors. Every error is one line that says what is wrong, where,
//    and how to fix it: "line L, column C: ..." for syntax errors and a JSON
//    path ("edges[3][1]: ...", "half_edges[7].next: ...") for values of the
//    wrong type, arity or range. General-purpose libraries give a byte offset
//    at best, and no path.
//  - No recursion. Nesting is tracked on an explicit stack of at most
//    kMaxDepth frames; crossing that limit is a Syntax error raised at the
//    bracket that crosses it, so "[[[[..." a million levels deep costs O(1)
//    memory and no call stack. Unknown keys are skipped by the same loop.
//    The parser is fuzzed: it never reads out of bounds, never crashes, and
//    never allocates more than O(input size).
//  - Speed. It is a pull parser: the readers (graph_json, dcel_json) read
//    numbers straight into their vectors without building a DOM, and the
//    per-element steps are inline. Doubles of up to 15 digits without an
//    exponent are converted exactly in place (an exact integer divided by an
//    exact power of ten: one correctly rounded division); all others go
//    through std::from_chars, which is correctly rounded in libstdc++ >= 12
//    (or, where the library lacks it, as in libc++ before LLVM 20, through
//    strtod_l: see decimal.hpp).
//    Output uses std::to_chars (shortest round trip). The target is >= 200
//    MB/s reading a large graph document.
//
// std::from_chars and underflow: libstdc++ 12 (fast_float) parses subnormals
// exactly (4.9e-324 gives 2^-1074), but for a nonzero literal whose nearest
// double is zero (1e-400; anything up to 2^-1075, half the smallest
// subnormal) it returns result_out_of_range and leaves the value untouched,
// exactly as for overflow. read_double tells the two apart by the decimal
// exponent of the leading digit and returns a zero of the literal's sign for
// underflow, like any other rounding; only overflow (1e400) is an error.
//
// Strictness: exactly one JSON value per document (a UTF-8 BOM is skipped);
// only the four JSON whitespace characters; no comments, trailing commas,
// single quotes, NaN/Infinity, leading zeros, '+' signs or hex numbers;
// strings must be valid UTF-8 with valid escapes, no raw control characters
// and no unpaired surrogates.
//
// Protocol. The reader is always at either a value position (after '[', ',',
// ':' or at the start) or a separator position (after a value). At a value
// position call exactly one of peek() (any number of times), begin_array(),
// begin_object(), read_double(), read_index(), read_index_or_null(),
// skip_value(). In an array, next_element() moves from the separator position
// to the next value position (true) or consumes ']' (false); in an object,
// next_member() does the same for members and exposes key(). After the top
// value, end_document() checks that only whitespace remains.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "dcel/contracts.hpp"

#include "dcel/error.hpp"
#include "dcel/ids.hpp"

// The per-element fast paths below are small but called from other
// translation units in tight loops; GCC at -O2 does not always inline them.
#if defined(__GNUC__)
#define DCEL_JSON_HOT [[gnu::always_inline]]
#else
#define DCEL_JSON_HOT
#endif

namespace dcel::io {

// The type of a JSON value, as told by its first character.
enum class JsonType : unsigned char { Null, False, True, Number, String, Array, Object };

// "null", "false", "true", "a number", "a string", "an array", "an object".
[[nodiscard]] const char* describe(JsonType type);

class JsonReader {
public:
    static constexpr std::size_t kMaxDepth = 256;

    explicit JsonReader(std::string_view text);

    // ---- Structure
    // The type of the value at the current (value) position, without
    // consuming it. Syntax error on end of input or a character that cannot
    // start a value; a literal (true/false/null) is checked in full here.
    [[nodiscard]] JsonType peek();
    // Consume '[' / '{'. Shape error "expected <expected>, found ..." when the
    // value is of another type.
    void begin_array(std::string_view expected);
    void begin_object(std::string_view expected);
    // In an array: true when another element follows (now at its value
    // position); false after consuming ']'.
    [[nodiscard]] bool next_element();
    // In an object: true when another member follows (key() is its key, now at
    // its value position); false after consuming '}'.
    [[nodiscard]] bool next_member();
    // The key of the current member, unescaped. Valid until the next call.
    [[nodiscard]] std::string_view key() const { return key_; }
    // In an object whose keys are interpreted: the index in `known` of the next
    // member's key (the caller then consumes its value), skipping the values
    // of unknown keys; -1 after consuming '}'. `seen` has bit i set once
    // known[i] was returned; a known key given twice is a Shape error.
    // known.size() <= 64.
    [[nodiscard]] int next_known_member(std::span<const std::string_view> known, std::uint64_t& seen);
    // In an array, at a separator position: skip the remaining elements and
    // consume ']'. Returns the array's total number of elements.
    std::uint64_t finish_array();
    // Skip one value of any type (iteratively, under the same depth limit).
    void skip_value();
    // Only whitespace may follow the top-level value.
    void end_document();

    // ---- Scalars (each consumes one value; Shape error when it has another type)
    // A finite double, correctly rounded; an underflowing literal (1e-400)
    // rounds to (signed) zero. BadCoordinate beyond the range of a double.
    [[nodiscard]] double read_double(std::string_view expected = "a number");
    // A non-negative integer < 2^32 - 1 (1.0 and 1e0 count as integers).
    // `noun` names it in messages: "vertex index -1 is negative". BadIndex
    // when negative, not an integer, or too large.
    [[nodiscard]] Index read_index(std::string_view noun);
    // As read_index, but null reads as kNoIndex.
    [[nodiscard]] Index read_index_or_null(std::string_view noun);
    // A string, unescaped (Shape error when the value has another type).
    [[nodiscard]] std::string read_string(std::string_view expected = "a string");
    // A number's literal, as written (validated, not converted): for readers
    // that keep numbers exactly as a document has them (a uint64 seed, a
    // double's shortest form). Valid as long as the text is.
    [[nodiscard]] std::string_view read_number_text(std::string_view expected = "a number");

    // ---- Locations and errors
    // The JSON path of the current value ("edges[3][1]", "half_edges[7].next");
    // empty at the top level. path(n) uses only the outermost n levels.
    [[nodiscard]] std::string path() const { return path(depth_); }
    [[nodiscard]] std::string path(std::size_t levels) const;
    // "line L, column C" of a byte offset into the text (after the BOM).
    [[nodiscard]] std::string location(std::size_t offset) const;

    // Throws InvalidInput(kind, "<path>: <message>"), "top level" for the empty path.
    [[noreturn]] void fail(InputErrorKind kind, std::string_view message) const;
    // Shape: "<path>: expected <expected>, found <the type of the value here>".
    // A malformed scalar here is reported as the Syntax error it is.
    [[noreturn]] void fail_type(std::string_view expected);
    // Shape, after the array was consumed: "<path>: expected <expected>, found
    // an array of <count> elements".
    [[noreturn]] void fail_arity(std::string_view expected, std::uint64_t count) const;
    // Shape, after the object was consumed: "<path>: missing key "<key>":
    // expected <form>" (no path prefix at the top level).
    [[noreturn]] void fail_missing_key(std::string_view key, std::string_view form) const;
    // Shape, at the value of the current member, for a key the caller has
    // seen before in this object: "<path of the object>: duplicate key
    // "<key>" at line L, column C: give each key once".
    [[noreturn]] void fail_duplicate_key() const;
    // Syntax: "line L, column C: <message>".
    [[noreturn]] void fail_syntax(std::size_t offset, std::string_view message) const;

private:
    struct Frame {
        std::uint64_t count = 0;    // elements or members begun so far
        std::size_t key_begin = 0;  // raw (escaped) key of the current member
        std::size_t key_end = 0;
        std::size_t keys_begin = 0;   // objects: this object's keys are keys_[keys_begin, ...)
        std::size_t arena_begin = 0;  // and its escaped keys' copies arena_[arena_begin, ...)
        bool object = false;
        bool key_escaped = false;
        bool key_set = false;  // key_sets_[depth] holds this object's keys (an object of many)
    };

    static constexpr bool is_space(char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t'; }
    static constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
    // Characters that cannot directly follow a number or a literal.
    static constexpr bool is_word_char(char c) {
        return is_digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '.' || c == '+' ||
               c == '-';
    }

    DCEL_JSON_HOT void skip_whitespace() {
        while (pos_ < text_.size() && is_space(text_[pos_])) ++pos_;
    }
    void open(bool object);  // at '[' or '{': consume it, push a frame
    void close() {           // pop a frame (the bracket is consumed)
        const Frame& f = frames_[--depth_];
        last_closed_count_ = f.count;
        if (f.object) forget_keys(f);
    }
    // Duplicate keys are refused in every object, whether its caller reads
    // the member or skips it: each open object's keys are kept until it closes.
    void remember_key();
    void forget_keys(const Frame& f);

    // The out-of-line halves of the inline fast paths: they start over at pos_.
    [[nodiscard]] JsonType peek_slow();
    [[nodiscard]] double read_double_slow(std::string_view expected);
    [[nodiscard]] Index read_index_slow(std::string_view noun);

    [[nodiscard]] std::size_t scan_number();  // validate the number at pos_, return its end
    // Validate the string at pos_ ('"'); return the end (after the closing
    // quote) and whether it has escapes.
    [[nodiscard]] std::size_t scan_string(bool& escaped);
    // The steps of scan_string, each at offset p inside the string and
    // returning the offset just past what it checked.
    [[nodiscard]] std::size_t scan_escape(std::size_t p) const;          // at a backslash
    [[nodiscard]] std::size_t scan_unicode_escape(std::size_t p) const;  // at the backslash of a 'u' escape
    [[nodiscard]] std::size_t scan_utf8(std::size_t p) const;            // at a byte >= 0x80
    [[noreturn]] void fail_control_character(std::size_t p) const;
    [[noreturn]] void fail_unexpected(std::size_t offset, std::string_view expected) const;
    [[noreturn]] void fail_bad_word(std::size_t offset) const;
    [[noreturn]] void fail_index(std::string_view noun, std::size_t begin, std::size_t end) const;
    [[noreturn]] void fail_too_deep() const;

    std::string_view text_;  // without the BOM
    std::size_t pos_ = 0;
    std::array<Frame, kMaxDepth> frames_{};  // frames_[0, depth_) are open
    std::size_t depth_ = 0;
    std::uint64_t last_closed_count_ = 0;  // element count of the container closed last
    std::string_view key_;
    std::string key_buffer_;  // key_ when the raw key has escapes
    // The keys of the open objects (views into text_ or arena_), compared
    // one by one in a small object and through key_sets_[depth] in a large
    // one, so that a hostile object of n keys costs O(n), not O(n^2).
    std::vector<std::string_view> keys_;
    std::deque<std::string> arena_;  // unescaped copies of escaped keys (a deque: stable addresses)
    std::vector<std::unordered_set<std::string_view>> key_sets_;
};

// ---- Inline fast paths (the per-number and per-element work of large
// documents); every unusual case goes to the out-of-line code.

DCEL_JSON_HOT inline void JsonReader::open(bool object) {
    if (depth_ == kMaxDepth) fail_too_deep();
    ++pos_;
    Frame& f = frames_[depth_++];
    f.count = 0;
    f.object = object;
    if (object) {
        f.keys_begin = keys_.size();
        f.arena_begin = arena_.size();
        f.key_set = false;
    }
}

DCEL_JSON_HOT inline JsonType JsonReader::peek() {
    skip_whitespace();
    if (pos_ < text_.size()) {
        const char c = text_[pos_];
        if (c == '[') return JsonType::Array;
        if (c == '{') return JsonType::Object;
        if (c == '"') return JsonType::String;
        if (c == '-' || is_digit(c)) return JsonType::Number;
    }
    return peek_slow();
}

DCEL_JSON_HOT inline void JsonReader::begin_array(std::string_view expected) {
    if (peek() != JsonType::Array) fail_type(expected);
    open(false);
}

DCEL_JSON_HOT inline bool JsonReader::next_element() {
    DCEL_ASSERT(depth_ > 0 && !frames_[depth_ - 1].object);
    skip_whitespace();
    Frame& f = frames_[depth_ - 1];
    if (pos_ >= text_.size()) fail_unexpected(pos_, f.count == 0 ? "a value or ']'" : "',' or ']'");
    const char c = text_[pos_];
    if (c == ']') {
        ++pos_;
        close();
        return false;
    }
    if (f.count != 0) {
        if (c != ',') fail_unexpected(pos_, "',' or ']' after an array element");
        ++pos_;
        skip_whitespace();
        if (pos_ < text_.size() && text_[pos_] == ']') {
            fail_syntax(pos_, "unexpected ']' after ',': JSON does not allow trailing commas");
        }
    }
    ++f.count;
    return true;
}

DCEL_JSON_HOT inline double JsonReader::read_double(std::string_view expected) {
    // Fast path: -?digits(.digits)? with at most 15 digits in all, so that the
    // digits m are exact in a double, as is 10^k for k <= 15 fraction digits;
    // then m / 10^k is one correctly rounded IEEE division (Clinger's fast
    // path), the same double from_chars gives.
    static constexpr double kPow10[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                          1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    skip_whitespace();
    const char* const first = text_.data() + pos_;
    const char* const last = text_.data() + text_.size();
    const char* p = first;
    const bool negative = p != last && *p == '-';
    if (negative) ++p;
    const char* const digits = p;
    std::uint64_t m = 0;
    while (p != last && is_digit(*p)) m = m * 10 + static_cast<unsigned>(*p++ - '0');
    const auto int_digits = static_cast<std::size_t>(p - digits);
    std::size_t frac_digits = 0;
    bool dot = false;
    if (p != last && *p == '.') {
        dot = true;
        const char* const frac = ++p;
        while (p != last && is_digit(*p)) m = m * 10 + static_cast<unsigned>(*p++ - '0');
        frac_digits = static_cast<std::size_t>(p - frac);
    }
    if (int_digits != 0 && int_digits + frac_digits <= 15 && (int_digits == 1 || *digits != '0') &&
        (!dot || frac_digits != 0) && (p == last || !is_word_char(*p))) {
        pos_ += static_cast<std::size_t>(p - first);
        const double v = static_cast<double>(m) / kPow10[frac_digits];
        return negative ? -v : v;
    }
    return read_double_slow(expected);
}

DCEL_JSON_HOT inline Index JsonReader::read_index(std::string_view noun) {
    // Fast path: 1 to 10 plain digits, no leading zero, at most kNoIndex - 1.
    skip_whitespace();
    const char* const first = text_.data() + pos_;
    const char* const last = text_.data() + text_.size();
    const char* p = first;
    std::uint64_t v = 0;
    while (p != last && is_digit(*p) && p - first < 11) v = v * 10 + static_cast<unsigned>(*p++ - '0');
    const auto n = p - first;
    if (n != 0 && n <= 10 && (n == 1 || *first != '0') && v < kNoIndex && (p == last || !is_word_char(*p))) {
        pos_ += static_cast<std::size_t>(n);
        return static_cast<Index>(v);
    }
    return read_index_slow(noun);
}

}  // namespace dcel::io

#undef DCEL_JSON_HOT
