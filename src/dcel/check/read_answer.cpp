// read_answer: an answer of any kind from JSON, streamed through JsonReader
// (no DOM: an answer costs a few bytes per number read). The kind is given,
// or detected from the top-level keys or, for bare arrays, from how deep the
// first numbers sit.
#include <array>
#include <string>
#include <vector>

#include "dcel/check/answer.hpp"
#include "dcel/error.hpp"
#include "dcel/format.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/json_reader.hpp"

namespace dcel::check {

namespace {

using io::JsonReader;
using io::JsonType;

constexpr std::array<std::string_view, kAnswerKindCount> kKindNames{"faces", "dump", "polygons", "rings", "even-odd"};

constexpr std::string_view kFacesForms = R"({"faces": [[v, ...], ...]} or [[v, ...], ...])";
constexpr std::string_view kPolygonsForms =
    R"({"polygons": [{"shell": ring, "holes": [ring, ...]}, ...]}, {"polygons": [[shell, hole, ...], ...]}, )"
    R"([[shell, hole, ...], ...], or GeoJSON (Polygon, MultiPolygon, Feature, FeatureCollection, GeometryCollection))";
constexpr std::string_view kRingsForms = R"({"rings": [ring, ...]} or [ring, ...])";
constexpr std::string_view kRingForms = "a ring: [v, ...] (vertex ids) or [[x, y], ...] (coordinates)";

// ---- Faces, flat

void read_cycles(JsonReader& r, CycleList& out) {
    r.begin_array("an array of cycles [[v, ...], ...]");
    while (r.next_element()) {
        r.begin_array("a cycle: an array of vertex ids [v, ...]");
        while (r.next_element()) out.ids.push_back(r.read_index("vertex id"));
        out.end_cycle();
    }
}

CycleList read_faces(std::string_view text) {
    JsonReader r(text);
    CycleList cycles;
    const JsonType top = r.peek();
    if (top == JsonType::Object) {
        static constexpr std::array<std::string_view, 1> kKeys{"faces"};
        r.begin_object(kFacesForms);
        std::uint64_t seen = 0;
        while (r.next_known_member(kKeys, seen) >= 0) read_cycles(r, cycles);
        if (seen == 0) r.fail_missing_key("faces", R"({"faces": [[v, ...], ...]})");
    } else if (top == JsonType::Array) {
        read_cycles(r, cycles);
    } else {
        r.fail_type(kFacesForms);
    }
    r.end_document();
    return cycles;
}

// ---- Regions

class RegionReader {
public:
    explicit RegionReader(RegionAnswer& out) : out_(out) {}

    // [v, ...] or [[x, y], ...] (a third coordinate, GeoJSON's altitude, is ignored).
    void ring(JsonReader& r) {
        r.begin_array(kRingForms);
        while (r.next_element()) {
            if (r.peek() == JsonType::Array) {
                choose(r, true);
                r.begin_array("a position [x, y]");
                double xy[2] = {0, 0};
                std::uint64_t n = 0;
                while (r.next_element()) {
                    if (n < 2) {
                        xy[n] = r.read_double("a coordinate");
                    } else if (n == 2) {
                        (void)r.read_double("an altitude (a third coordinate, ignored)");
                    } else {
                        r.skip_value();
                    }
                    ++n;
                }
                if (n < 2 || n > 3) r.fail_arity("a position [x, y] (or [x, y, z])", n);
                out_.points.push_back({xy[0], xy[1]});
            } else {
                choose(r, false);
                out_.ids.push_back(r.read_index("vertex id"));
            }
        }
        out_.ring_begin.push_back(out_.by_points ? out_.points.size() : out_.ids.size());
    }
    // [shell, hole, ...]
    void ring_list(JsonReader& r) {
        r.begin_array("a polygon: an array of rings [shell, hole, ...]");
        while (r.next_element()) ring(r);
        end_polygon();
    }
    // {"shell": ring, "holes": [ring, ...]}, in either key order.
    void shell_and_holes(JsonReader& r) {
        static constexpr std::array<std::string_view, 2> kKeys{"shell", "holes"};
        r.begin_object(R"(a polygon {"shell": ring, "holes": [ring, ...]})");
        std::uint64_t seen = 0;
        // The shell must come first in the flat list, so holes wait here.
        RegionAnswer holes;
        RegionReader hole_reader(holes);
        for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
            if (k == 0) {
                ring(r);
            } else {
                hole_reader.decide_like(*this);
                r.begin_array("an array of rings");
                while (r.next_element()) hole_reader.ring(r);
                decide_like(hole_reader);
            }
        }
        if ((seen & 1U) == 0) r.fail_missing_key("shell", R"({"shell": ring, "holes": [ring, ...]})");
        for (std::size_t h = 0; h < holes.ring_count(); ++h) {
            for (std::size_t i = holes.ring_begin[h]; i < holes.ring_begin[h + 1]; ++i) {
                if (out_.by_points) {
                    out_.points.push_back(holes.points[i]);
                } else {
                    out_.ids.push_back(holes.ids[i]);
                }
            }
            out_.ring_begin.push_back(out_.by_points ? out_.points.size() : out_.ids.size());
        }
        end_polygon();
    }
    void end_polygon() { out_.polygon_begin.push_back(out_.ring_count()); }

    // GeoJSON: an object of one of the polygonal types (or a container of
    // them). `types` holds every object's "type" in document order, from a
    // first pass (a member may come before "type").
    // Recursive over GeoJSON's nesting, which JsonReader's depth limit bounds.
    // NOLINTNEXTLINE(misc-no-recursion)
    void geojson(JsonReader& r, const std::vector<std::string>& types, std::size_t& next_type) {
        if (next_type >= types.size()) r.fail_type("a GeoJSON object");
        const std::string& type = types[next_type++];
        static constexpr std::array<std::string_view, 5> kKeys{"type", "coordinates", "geometry", "features", "geometries"};
        r.begin_object("a GeoJSON object");
        std::uint64_t seen = 0;
        for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
            switch (k) {
                case 0: r.skip_value(); break;
                case 1:
                    if (type == "Polygon") {
                        ring_list(r);
                    } else if (type == "MultiPolygon") {
                        r.begin_array("MultiPolygon coordinates: an array of polygons");
                        while (r.next_element()) ring_list(r);
                    } else {
                        fail_not_polygonal(r, type);
                    }
                    break;
                case 2:
                    if (r.peek() == JsonType::Null) {
                        r.skip_value();  // a Feature without geometry
                    } else {
                        geojson(r, types, next_type);
                    }
                    break;
                default:
                    r.begin_array(k == 3 ? "an array of Features" : "an array of geometries");
                    while (r.next_element()) geojson(r, types, next_type);
                    break;
            }
        }
        if (type.empty()) r.fail_missing_key("type", "a GeoJSON object");
        const bool polygonal = type == "Polygon" || type == "MultiPolygon";
        if (polygonal && (seen & 2U) == 0) r.fail_missing_key("coordinates", "a GeoJSON " + type);
        if (!polygonal && type != "Feature" && type != "FeatureCollection" && type != "GeometryCollection") {
            fail_not_polygonal(r, type);
        }
    }

private:
    // The type is the answer's text: quoted and escaped, never echoed raw.
    [[noreturn]] static void fail_not_polygonal(const JsonReader& r, const std::string& type) {
        r.fail(InputErrorKind::Shape, "a GeoJSON object of type " + quote_for_message(type) +
                                          " is not a polygon answer (expected Polygon, MultiPolygon, Feature, "
                                          "FeatureCollection or GeometryCollection)");
    }

    void decide_like(const RegionReader& other) {
        decided_ = other.decided_;
        out_.by_points = other.out_.by_points;
    }
    // Ids or coordinates: the first ring point decides for the whole answer.
    void choose(const JsonReader& r, bool points) {
        if (!decided_) {
            decided_ = true;
            out_.by_points = points;
        } else if (out_.by_points != points) {
            mixed(r);
        }
    }
    [[noreturn]] static void mixed(const JsonReader& r) {
        r.fail(InputErrorKind::Shape,
               "rings given both as vertex ids and as coordinates; use one form for the whole answer");
    }

    RegionAnswer& out_;
    bool decided_ = false;
};

// The "type" of every object the GeoJSON walk will visit, in document order
// (objects without one get ""). Only "geometry", "features" and "geometries"
// are descended into, exactly as RegionReader::geojson does; recursive like
// it, within JsonReader's depth limit.
// NOLINTNEXTLINE(misc-no-recursion)
void collect_types(JsonReader& r, std::vector<std::string>& types) {
    const std::size_t mine = types.size();
    types.emplace_back();
    r.begin_object("a GeoJSON object");
    while (r.next_member()) {
        const std::string key(r.key());
        if (key == "type" && r.peek() == JsonType::String) {
            types[mine] = r.read_string();
        } else if (key == "geometry" && r.peek() == JsonType::Object) {
            collect_types(r, types);
        } else if ((key == "features" || key == "geometries") && r.peek() == JsonType::Array) {
            r.begin_array("an array");
            while (r.next_element()) {
                if (r.peek() == JsonType::Object) {
                    collect_types(r, types);
                } else {
                    r.skip_value();
                }
            }
        } else {
            r.skip_value();
        }
    }
}

RegionAnswer read_geojson(std::string_view text) {
    std::vector<std::string> types;
    {
        JsonReader first(text);
        collect_types(first, types);
    }
    RegionAnswer out;
    RegionReader reader(out);
    JsonReader r(text);
    std::size_t next = 0;
    reader.geojson(r, types, next);
    r.end_document();
    return out;
}

void read_polygon_list(JsonReader& r, RegionReader& reader) {
    r.begin_array("an array of polygons");
    while (r.next_element()) {
        if (r.peek() == JsonType::Object) {
            reader.shell_and_holes(r);
        } else {
            reader.ring_list(r);
        }
    }
}

RegionAnswer read_polygons(std::string_view text) {
    RegionAnswer out;
    RegionReader reader(out);
    JsonReader r(text);
    const JsonType top = r.peek();
    if (top == JsonType::Object) {
        bool geojson = false;
        {
            JsonReader scan(text);
            scan.begin_object("an object");
            while (scan.next_member()) {
                if (scan.key() == "type") geojson = true;
                scan.skip_value();
            }
        }
        if (geojson) return read_geojson(text);
        static constexpr std::array<std::string_view, 1> kKeys{"polygons"};
        r.begin_object(kPolygonsForms);
        std::uint64_t seen = 0;
        while (r.next_known_member(kKeys, seen) >= 0) read_polygon_list(r, reader);
        if (seen == 0) r.fail_missing_key("polygons", kPolygonsForms);
    } else if (top == JsonType::Array) {
        read_polygon_list(r, reader);
    } else {
        r.fail_type(kPolygonsForms);
    }
    r.end_document();
    return out;
}

RegionAnswer read_rings(std::string_view text) {
    RegionAnswer out;
    RegionReader reader(out);
    JsonReader r(text);
    auto list = [&] {
        r.begin_array("an array of rings");
        while (r.next_element()) {
            reader.ring(r);
            reader.end_polygon();
        }
    };
    const JsonType top = r.peek();
    if (top == JsonType::Object) {
        static constexpr std::array<std::string_view, 1> kKeys{"rings"};
        r.begin_object(kRingsForms);
        std::uint64_t seen = 0;
        while (r.next_known_member(kKeys, seen) >= 0) list();
        if (seen == 0) r.fail_missing_key("rings", kRingsForms);
    } else if (top == JsonType::Array) {
        list();
    } else {
        r.fail_type(kRingsForms);
    }
    r.end_document();
    return out;
}

// ---- Detection

struct Detected {
    AnswerKind kind;
    std::string from;
    std::vector<AnswerKind> fits{kind};
};

// An object: by its keys. An array: by the depth of its first number, read
// down the first elements ([[0, 1]] is faces; [[[0, 1, 2]]] polygons of id
// rings; [[[0, 0], [1, 0], [0, 1]]] rings of coordinates, since a ring of two
// ids is no ring; [[[[0, 0], ...]]] polygons of coordinate rings).
// The answer keys of a top-level object: "faces", "half_edges",
// "polygons", "rings" and GeoJSON's "type" (a dump's own "faces" member
// does not count). An object may hold one: with two, which one answers is
// anybody's guess, so it is refused rather than judged by one of them.
struct AnswerKeys {
    bool faces = false, dump = false, polygons = false, rings = false, type = false;
};

AnswerKeys answer_keys(std::string_view text) {
    AnswerKeys k;
    JsonReader r(text);
    r.begin_object("an answer");
    while (r.next_member()) {
        const std::string_view key = r.key();
        k.dump = k.dump || key == "half_edges";
        k.faces = k.faces || key == "faces";
        k.polygons = k.polygons || key == "polygons";
        k.rings = k.rings || key == "rings";
        k.type = k.type || key == "type";
        r.skip_value();
    }
    r.end_document();
    std::vector<std::string_view> present;
    if (k.dump) present.emplace_back("\"half_edges\"");
    if (k.faces && !k.dump) present.emplace_back("\"faces\"");
    if (k.polygons) present.emplace_back("\"polygons\"");
    if (k.rings) present.emplace_back("\"rings\"");
    if (k.type) present.emplace_back("GeoJSON's \"type\"");
    if (present.size() > 1) {
        std::string keys;
        for (std::size_t i = 0; i < present.size(); ++i) {
            keys += i == 0 ? "" : (i + 1 == present.size() ? " and " : ", ");
            keys += present[i];
        }
        throw InvalidInput(InputErrorKind::Shape, "top level: the object has the keys " + keys +
                                                      ", each of which is a whole answer; give one of them");
    }
    return k;
}

// An object answer: by its one answer key.
Detected detect_object(std::string_view text) {
    const AnswerKeys k = answer_keys(text);
    if (k.dump) return {AnswerKind::Dump, "an object with a \"half_edges\" key"};
    if (k.faces) return {AnswerKind::Faces, "an object with a \"faces\" key"};
    if (k.polygons) return {AnswerKind::Polygons, "an object with a \"polygons\" key"};
    if (k.rings) return {AnswerKind::Rings, "an object with a \"rings\" key"};
    if (k.type) return {AnswerKind::Polygons, "a GeoJSON object"};
    throw InvalidInput(InputErrorKind::Shape,
                       "top level: an object answer needs a \"faces\", \"half_edges\", \"polygons\" or \"rings\" "
                       "key, or a GeoJSON \"type\"");
}

// An array answer (r at it): by the depth of its first number, and, at
// depth 3, the length of the innermost array that holds it.
Detected detect_array(JsonReader& r) {
    std::size_t depth = 0;        // arrays entered before the first number
    std::size_t last_length = 0;  // elements of the innermost array that holds it
    for (;;) {
        if (r.peek() != JsonType::Array) break;
        r.begin_array("an array");
        ++depth;
        if (!r.next_element()) {  // empty: nothing deeper to see
            if (depth == 1) {
                return {AnswerKind::Faces, "an empty list", {AnswerKind::Faces, AnswerKind::Polygons, AnswerKind::Rings}};
            }
            depth = 0;
            break;
        }
    }
    if (depth == 0) {
        throw InvalidInput(InputErrorKind::Shape,
                           "top level: cannot tell the answer kind from an empty or irregular first element; pass "
                           "--answer faces|dump|polygons|rings");
    }
    if (r.peek() == JsonType::Number) {
        (void)r.read_double("a number");
        last_length = 1;
        while (r.next_element()) {
            r.skip_value();
            ++last_length;
        }
    }
    switch (depth) {
        case 2:
            return {AnswerKind::Faces,
                    "a list of id lists; --answer rings if it has one ring per bounded face",
                    {AnswerKind::Faces, AnswerKind::Rings}};
        case 3:
            // [x, y] positions; a ring of two ids would be no ring. (A bare
            // list of [x, y, z] rings is ambiguous: --answer rings.)
            if (last_length == 2) return {AnswerKind::Rings, "a list of coordinate rings"};
            return {AnswerKind::Polygons, "a list of polygons of id rings"};
        case 4: return {AnswerKind::Polygons, "a list of polygons of coordinate rings"};
        default:
            throw InvalidInput(InputErrorKind::Shape, "top level: numbers nested " + std::to_string(depth) +
                                                          " arrays deep fit no answer kind; pass --answer "
                                                          "faces|dump|polygons|rings");
    }
}

Detected detect(std::string_view text) {
    JsonReader r(text);
    const JsonType top = r.peek();
    if (top == JsonType::Object) return detect_object(text);
    if (top != JsonType::Array) r.fail_type("an answer: an object or an array");
    return detect_array(r);
}

}  // namespace

std::string_view answer_kind_name(AnswerKind k) { return kKindNames[static_cast<std::size_t>(k)]; }

std::optional<AnswerKind> answer_kind_from_name(std::string_view name) {
    for (std::size_t i = 0; i < kKindNames.size(); ++i) {
        if (kKindNames[i] == name) return static_cast<AnswerKind>(i);
    }
    return std::nullopt;
}

Answer read_answer(std::string_view text, std::optional<AnswerKind> kind) {
    Answer a;
    if (kind) {
        a.kind = *kind;
        a.fits = {*kind};
        if (JsonReader(text).peek() == JsonType::Object) (void)answer_keys(text);
    } else {
        Detected d = detect(text);
        a.kind = d.kind;
        a.detected_from = std::move(d.from);
        a.fits = std::move(d.fits);
    }
    switch (a.kind) {
        case AnswerKind::Faces: a.cycles = read_faces(text); break;
        case AnswerKind::Dump: a.dump = io::read_dump(text); break;
        case AnswerKind::Polygons:
        case AnswerKind::EvenOdd: a.regions = read_polygons(text); break;
        case AnswerKind::Rings: a.regions = read_rings(text); break;
    }
    return a;
}

}  // namespace dcel::check
