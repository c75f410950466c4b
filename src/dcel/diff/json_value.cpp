#include "dcel/diff/json_value.hpp"

#include <charconv>

#include "dcel/error.hpp"

namespace dcel::diff {
namespace {

// Recursion is bounded by the reader's depth limit (kMaxDepth levels).
JsonValue read_value(io::JsonReader& r) {  // NOLINT(misc-no-recursion)
    JsonValue v;
    v.type = r.peek();
    switch (v.type) {
        case io::JsonType::Null:
        case io::JsonType::False:
        case io::JsonType::True: r.skip_value(); break;
        case io::JsonType::Number: v.text = r.read_number_text(); break;
        case io::JsonType::String: v.text = r.read_string(); break;
        case io::JsonType::Array:
            r.begin_array("an array");
            while (r.next_element()) v.items.push_back(read_value(r));
            break;
        case io::JsonType::Object:
            r.begin_object("an object");
            while (r.next_member()) {
                std::string key(r.key());
                v.members.push_back({std::move(key), read_value(r)});
            }
            break;
    }
    return v;
}

}  // namespace

const JsonValue* JsonValue::find(std::string_view key) const {
    if (type != io::JsonType::Object) return nullptr;
    for (const auto& [k, value] : members) {
        if (k == key) return &value;
    }
    return nullptr;
}

std::string JsonValue::string_or(std::string_view fallback) const {
    return type == io::JsonType::String ? text : std::string(fallback);
}

bool JsonValue::bool_or(bool fallback) const {
    if (type == io::JsonType::True) return true;
    if (type == io::JsonType::False) return false;
    return fallback;
}

std::optional<std::uint64_t> JsonValue::count() const {
    if (type != io::JsonType::Number) return std::nullopt;
    std::uint64_t n = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    return n;
}

std::optional<double> JsonValue::number() const {
    if (type != io::JsonType::Number) return std::nullopt;
    try {
        io::JsonReader r(text);
        return r.read_double();
    } catch (const InvalidInput&) {
        return std::nullopt;  // beyond the range of a double (1e400)
    }
}

JsonValue parse_json(std::string_view text) {
    io::JsonReader r(text);
    JsonValue v = read_value(r);
    r.end_document();
    return v;
}

}  // namespace dcel::diff
