// A small JSON document tree, for reading a whole report back (the HTML page
// is rendered from the JSON report alone).
// Read with io::JsonReader, so the syntax, the depth limit, duplicate keys
// and UTF-8 are checked as everywhere else. Numbers keep their literal text:
// a uint64 seed and a double's shortest form survive unchanged.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dcel/io/json_reader.hpp"

namespace dcel::diff {

// A tree: a value holds values (hence NOLINT: its copy is recursive, as
// deep as the reader's depth limit lets a document be).
struct JsonValue {  // NOLINT(misc-no-recursion)
    struct Member;  // a key and its value (a pair of an incomplete type would not compile with every library)

    io::JsonType type = io::JsonType::Null;
    std::string text;              // a string's value, unescaped; a number's literal
    std::vector<JsonValue> items;  // an array's elements
    std::vector<Member> members;   // an object's members, in document order

    // The member `key` of an object, or null when this is no object or has no such key.
    [[nodiscard]] const JsonValue* find(std::string_view key) const;

    // Lenient accessors for a known document: the value when it has the
    // type, otherwise `fallback`.
    [[nodiscard]] std::string string_or(std::string_view fallback = {}) const;
    [[nodiscard]] bool bool_or(bool fallback) const;
    // A non-negative integer literal (no fraction, no exponent, < 2^64).
    [[nodiscard]] std::optional<std::uint64_t> count() const;
    // A number as a double, rounded as io::JsonReader::read_double rounds it.
    [[nodiscard]] std::optional<double> number() const;
};

struct JsonValue::Member {  // NOLINT(misc-no-recursion): see JsonValue
    std::string key;
    JsonValue value;
};

// The whole text as one value; InvalidInput (with a location or a JSON path)
// when it is not exactly one JSON document.
[[nodiscard]] JsonValue parse_json(std::string_view text);

}  // namespace dcel::diff
