#include "support/json_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

namespace dcel::fuzz {
namespace {

using Json = nlohmann::json;

// Is a JSON number literal, exactly, an integer? Its value is the digits
// (integer and fraction parts, trailing zeros dropped) times ten to the
// exponent less the fraction's length plus the zeros dropped.
bool literal_is_integer(std::string_view s) {
    std::size_t i = s.empty() || s[0] != '-' ? 0 : 1;
    std::string digits;
    std::size_t fraction = 0;
    bool in_fraction = false;
    for (; i < s.size() && s[i] != 'e' && s[i] != 'E'; ++i) {
        if (s[i] == '.') {
            in_fraction = true;
            continue;
        }
        digits += s[i];
        fraction += in_fraction ? 1 : 0;
    }
    long long exponent = 0;  // clamped: far beyond any digit count
    if (i < s.size()) {
        ++i;
        const bool negative = i < s.size() && s[i] == '-';
        if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
        for (; i < s.size(); ++i) exponent = std::min(exponent * 10 + (s[i] - '0'), 1000000000LL);
        if (negative) exponent = -exponent;
    }
    const std::size_t last = digits.find_last_not_of('0');
    if (last == std::string::npos) return true;  // zero
    const auto zeros = static_cast<long long>(digits.size() - 1 - last);
    return exponent - static_cast<long long>(fraction) + zeros >= 0;
}

// A SAX handler for nlohmann::json::sax_parse that builds nothing: it
// records the nesting depth and whether an object repeats a key, so that
// documents nested too deep for a tree are judged without one.
class FactsHandler {
public:
    explicit FactsHandler(JsonFacts& facts) : facts_(facts) {}
    bool null() { return true; }
    bool boolean(bool) { return true; }
    bool number_integer(Json::number_integer_t) { return true; }
    bool number_unsigned(Json::number_unsigned_t) { return true; }
    bool number_float(Json::number_float_t v, const Json::string_t& literal) {
        if (std::floor(v) == v && !literal_is_integer(literal)) facts_.rounded_to_integer = true;
        return true;
    }
    bool string(Json::string_t&) { return true; }
    template <class Binary>
    bool binary(Binary&) {  // a template: older nlohmann versions have no binary type
        return true;
    }
    bool start_object(std::size_t) {
        keys_.emplace_back();
        return open();
    }
    bool key(Json::string_t& k) {
        if (!keys_.back().insert(k).second) facts_.duplicate_key = true;
        return true;
    }
    bool end_object() {
        keys_.pop_back();
        return close();
    }
    bool start_array(std::size_t) { return open(); }
    bool end_array() { return close(); }
    template <class Exception>
    bool parse_error(std::size_t, const std::string&, const Exception& e) {
        facts_.error = e.what();
        facts_.number_overflow = facts_.error.find("number overflow") != std::string::npos;
        return false;
    }

private:
    bool open() {
        facts_.depth = std::max(facts_.depth, ++depth_);
        return true;
    }
    bool close() {
        --depth_;
        return true;
    }
    JsonFacts& facts_;
    std::size_t depth_ = 0;
    std::vector<std::set<std::string>> keys_;  // of each object open, innermost last
};

Json tree(std::string_view text) { return Json::parse(text.begin(), text.end(), nullptr, false); }

std::optional<double> coordinate(const Json& v) {
    if (v.is_number_unsigned()) return static_cast<double>(v.get<std::uint64_t>());
    if (v.is_number_integer()) return static_cast<double>(v.get<std::int64_t>());
    if (v.is_number_float()) return v.get<double>();
    return std::nullopt;
}

// A non-negative integer below 2^32 - 1 (the null id); 1.0 and 1e0 count.
std::optional<Index> index(const Json& v) {
    if (v.is_number_unsigned()) {
        const auto u = v.get<std::uint64_t>();
        if (u < kNoIndex) return static_cast<Index>(u);
    } else if (v.is_number_integer()) {
        const auto i = v.get<std::int64_t>();
        if (i >= 0 && i < kNoIndex) return static_cast<Index>(i);
    } else if (v.is_number_float()) {
        const double d = v.get<double>();
        if (d >= 0 && d < kNoIndex && std::floor(d) == d) return static_cast<Index>(d);
    }
    return std::nullopt;
}

std::optional<Index> index_or_null(const Json& v) { return v.is_null() ? std::optional<Index>(kNoIndex) : index(v); }

// [a, b]: exactly two elements.
bool is_pair(const Json& v) { return v.is_array() && v.size() == 2; }

// [[a, b], ...], each pair made into a T by make (nothing when one is not).
template <class T, class Make>
std::optional<std::vector<T>> pairs(const Json& v, Make make) {
    if (!v.is_array()) return std::nullopt;
    std::vector<T> out;
    for (const Json& p : v) {
        if (!is_pair(p)) return std::nullopt;
        const std::optional<T> t = make(p[0], p[1]);
        if (!t) return std::nullopt;
        out.push_back(*t);
    }
    return out;
}

std::optional<std::vector<Point>> points(const Json& v) {
    return pairs<Point>(v, [](const Json& a, const Json& b) -> std::optional<Point> {
        const auto x = coordinate(a), y = coordinate(b);
        if (!x || !y) return std::nullopt;
        return Point{*x, *y};
    });
}

std::optional<std::vector<GraphEdge>> edges(const Json& v) {
    return pairs<GraphEdge>(v, [](const Json& a, const Json& b) -> std::optional<GraphEdge> {
        const auto u = index(a), w = index(b);
        if (!u || !w) return std::nullopt;
        return GraphEdge{VertexId(*u), VertexId(*w)};
    });
}

std::optional<std::vector<std::vector<Index>>> cycles(const Json& v) {
    if (!v.is_array()) return std::nullopt;
    std::vector<std::vector<Index>> out;
    for (const Json& c : v) {
        if (!c.is_array()) return std::nullopt;
        std::vector<Index>& cycle = out.emplace_back();
        for (const Json& x : c) {
            const auto i = index(x);
            if (!i) return std::nullopt;
            cycle.push_back(*i);
        }
    }
    return out;
}

bool same_points(const std::vector<Point>& a, const std::vector<Point>& b) {
    // ==, not bitwise: nlohmann reads the integer -0 as 0.
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

template <class Id>
bool id_is(const Json& v, Id id, bool nullable) {
    const std::optional<Index> i = nullable ? index_or_null(v) : index(v);
    return i && *i == id.index();
}

template <class Id>
bool ids_are(const Json* v, const std::vector<Id>& ids) {  // v absent: the default []
    if (v == nullptr) return ids.empty();
    if (!v->is_array() || v->size() != ids.size()) return false;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!id_is((*v)[i], ids[i], false)) return false;
    }
    return true;
}

const Json* member(const Json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

}  // namespace

JsonFacts json_facts(std::string_view text) {
    JsonFacts facts;
    facts.has_nul = text.find('\0') != std::string_view::npos;
    if (facts.has_nul) return facts;
    FactsHandler handler(facts);
    facts.accepted = Json::sax_parse(text.begin(), text.end(), &handler);
    return facts;
}

std::optional<PlanarGraph> expected_graph(std::string_view text) {
    const Json j = tree(text);
    std::optional<std::vector<Point>> vs;
    std::optional<std::vector<GraphEdge>> es;
    if (j.is_object()) {
        if (!j.contains("vertices") || !j.contains("edges")) {
            return std::nullopt;
        }
        vs = points(j["vertices"]);
        es = edges(j["edges"]);
    } else if (is_pair(j)) {
        vs = points(j[0]);
        es = edges(j[1]);
    }
    if (!vs || !es) return std::nullopt;
    return PlanarGraph{std::move(*vs), std::move(*es)};
}

std::optional<std::vector<Point>> expected_points(std::string_view text) { return points(tree(text)); }

std::optional<std::vector<std::vector<Index>>> expected_faces(std::string_view text) {
    const Json j = tree(text);
    if (j.is_object()) {
        if (!j.contains("faces")) return std::nullopt;
        return cycles(j["faces"]);
    }
    return cycles(j);
}

bool dump_matches(std::string_view text, const DcelDump& d) {
    const Json j = tree(text);
    if (!j.is_object() || !j.contains("vertices") || !j.contains("half_edges") || !j.contains("faces")) return false;
    const auto vs = points(j["vertices"]);
    if (!vs || !same_points(*vs, d.vertices)) return false;
    if (const Json* out = member(j, "vertex_out")) {
        if (!out->is_array() || out->size() != d.vertex_out.size()) return false;
        for (std::size_t v = 0; v < d.vertex_out.size(); ++v) {
            if (!id_is((*out)[v], d.vertex_out[v], true)) return false;
        }
    } else if (!d.vertex_out.empty()) {
        return false;
    }
    const Json& hs = j["half_edges"];
    if (!hs.is_array() || hs.size() != d.half_edges.size()) return false;
    for (std::size_t h = 0; h < hs.size(); ++h) {
        const Json& r = hs[h];
        const HalfEdgeRecord& x = d.half_edges[h];
        if (!r.is_object() || !r.contains("origin") || !r.contains("twin") || !r.contains("next") || !r.contains("prev") ||
            !r.contains("face")) {
            return false;
        }
        if (!id_is(r["origin"], x.origin, false) || !id_is(r["twin"], x.twin, false) || !id_is(r["next"], x.next, false) ||
            !id_is(r["prev"], x.prev, false) || !id_is(r["face"], x.face, false)) {
            return false;
        }
    }
    const Json& fs = j["faces"];
    if (!fs.is_array() || fs.size() != d.faces.size()) return false;
    for (std::size_t f = 0; f < fs.size(); ++f) {
        const Json& r = fs[f];
        const FaceDump& x = d.faces[f];
        if (!r.is_object() || !r.contains("outer") || !id_is(r["outer"], x.outer, true)) return false;
        if (!ids_are(member(r, "inner"), x.inner) || !ids_are(member(r, "isolated"), x.isolated)) return false;
    }
    return true;
}

}  // namespace dcel::fuzz
