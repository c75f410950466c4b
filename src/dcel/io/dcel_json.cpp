#include "dcel/io/dcel_json.hpp"
#include "dcel/io/json_writer.hpp"
#include "dcel/io/limited_readers.hpp"

#include <array>
#include <span>

#include "dcel/io/graph_json.hpp"
#include "dcel/query/cycle_scan.hpp"

namespace dcel::io {

// From the internals of the core (dcel::detail).
using dcel::detail::for_each_boundary_cycle;

namespace {

constexpr std::string_view kDumpForm =
    R"({"vertices": [[x, y], ...], "vertex_out": [h or null, ...], "half_edges": [{"origin": v, "twin": h, )"
    R"("next": h, "prev": h, "face": f}, ...], "faces": [{"outer": h or null, "inner": [h, ...], "isolated": [v, ...]}, ...]})";
constexpr std::string_view kHalfEdgeForm = R"(a half-edge {"origin": v, "twin": h, "next": h, "prev": h, "face": f})";
constexpr std::string_view kHalfEdgeKeysForm = R"({"origin": v, "twin": h, "next": h, "prev": h, "face": f})";
constexpr std::string_view kFaceForm = R"(a face {"outer": h or null, "inner": [h, ...], "isolated": [v, ...]})";
constexpr std::string_view kFaceKeysForm = R"({"outer": h or null, "inner": [h, ...], "isolated": [v, ...]})";
constexpr std::string_view kFacesAnswerForms = R"(a faces answer {"faces": [[v, ...], ...]} or [[v, ...], ...])";

constexpr std::string_view kVertexId = "vertex id";
constexpr std::string_view kHalfEdgeId = "half-edge id";
constexpr std::string_view kFaceId = "face id";
constexpr std::string_view kVertexIndex = "vertex index";

[[noreturn]] void too_large(const JsonReader& r, std::uint64_t limit, std::string_view what) {
    r.fail(InputErrorKind::TooLarge, "more than " + std::to_string(limit) + " " + std::string(what) + ": ids are 32-bit");
}

template <class Id>
void read_id_array(JsonReader& r, std::vector<Id>& out, std::string_view expected, std::string_view noun) {
    r.begin_array(expected);
    while (r.next_element()) out.push_back(Id(r.read_index(noun)));
}

HalfEdgeRecord read_half_edge(JsonReader& r) {
    static constexpr std::array<std::string_view, 5> kKeys{"origin", "twin", "next", "prev", "face"};
    r.begin_object(kHalfEdgeForm);
    HalfEdgeRecord rec;
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        switch (k) {
            case 0: rec.origin = VertexId(r.read_index(kVertexId)); break;
            case 1: rec.twin = HalfEdgeId(r.read_index(kHalfEdgeId)); break;
            case 2: rec.next = HalfEdgeId(r.read_index(kHalfEdgeId)); break;
            case 3: rec.prev = HalfEdgeId(r.read_index(kHalfEdgeId)); break;
            default: rec.face = FaceId(r.read_index(kFaceId)); break;
        }
    }
    for (std::size_t i = 0; i < kKeys.size(); ++i) {
        if ((seen & (std::uint64_t{1} << i)) == 0) r.fail_missing_key(kKeys[i], kHalfEdgeKeysForm);
    }
    return rec;
}

FaceDump read_face(JsonReader& r) {
    static constexpr std::array<std::string_view, 3> kKeys{"outer", "inner", "isolated"};
    r.begin_object(kFaceForm);
    FaceDump face;
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        switch (k) {
            case 0: face.outer = HalfEdgeId(r.read_index_or_null(kHalfEdgeId)); break;
            case 1: read_id_array(r, face.inner, "an array of half-edge ids [h, ...]", kHalfEdgeId); break;
            default: read_id_array(r, face.isolated, "an array of vertex ids [v, ...]", kVertexId); break;
        }
    }
    if ((seen & 1U) == 0) r.fail_missing_key("outer", kFaceKeysForm);
    return face;
}

// At a value position: [[v, ...], ...].
std::vector<std::vector<Index>> read_cycles(JsonReader& r, const CountLimits& limits) {
    std::vector<std::vector<Index>> cycles;
    r.begin_array("an array of face cycles [[v, ...], ...]");
    while (r.next_element()) {
        if (cycles.size() >= limits.faces) too_large(r, limits.faces, "faces");
        std::vector<Index>& cycle = cycles.emplace_back();
        r.begin_array("a face cycle [v, ...]");
        // cycles does not grow while the reference is in use, in this loop.
        // cppcheck-suppress invalidContainerReference
        while (r.next_element()) cycle.push_back(r.read_index(kVertexIndex));
    }
    return cycles;
}

// ---- writing

void write_point(JsonWriter& w, const std::vector<Point>& vertices, std::size_t i) {
    const Point p = vertices[i];
    w.raw('[');
    if (!w.number(p.x)) fail_not_finite("vertices[" + std::to_string(i) + "][0]", p.x);
    w.raw(", ");
    if (!w.number(p.y)) fail_not_finite("vertices[" + std::to_string(i) + "][1]", p.y);
    w.raw(']');
}

void write_half_edge(JsonWriter& w, const HalfEdgeRecord& h) {
    w.raw("{\"origin\": ");
    w.index(h.origin.index());
    w.raw(", \"twin\": ");
    w.index(h.twin.index());
    w.raw(", \"next\": ");
    w.index(h.next.index());
    w.raw(", \"prev\": ");
    w.index(h.prev.index());
    w.raw(", \"face\": ");
    w.index(h.face.index());
    w.raw('}');
}

template <class Ids>
void write_id_list(JsonWriter& w, const Ids& ids) {
    w.raw('[');
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (i != 0) w.raw(", ");
        w.index(ids[i].index());
    }
    w.raw(']');
}

void write_face(JsonWriter& w, HalfEdgeId outer, const std::vector<HalfEdgeId>& inner,
                const std::vector<VertexId>& isolated) {
    w.raw("{\"outer\": ");
    w.index(outer.index());
    w.raw(", \"inner\": ");
    write_id_list(w, inner);
    w.raw(", \"isolated\": ");
    write_id_list(w, isolated);
    w.raw('}');
}

// "key": [elements], one element per line (Lines) or all on one (Compact).
template <class WriteElement>
void write_array_member(JsonWriter& w, std::string_view key, std::size_t count, DumpStyle style, bool first,
                        WriteElement write_element) {
    const bool lines = style == DumpStyle::Lines;
    if (!first) w.raw(lines ? ",\n" : ", ");
    if (lines) w.raw("  ");
    w.raw('"');
    w.raw(key);
    w.raw("\": [");
    for (std::size_t i = 0; i < count; ++i) {
        if (i != 0) w.raw(lines ? "," : ", ");
        if (lines) w.raw("\n    ");
        write_element(i);
    }
    if (lines && count != 0) w.raw("\n  ");
    w.raw(']');
}

// The records of a dump, read from a DcelDump (DumpOfDump) or straight from
// a Dcel (DumpOfDcel, what to_dump would copy): one writer for both, so that
// write_dump_of(d) is write_dump(to_dump(d)) by construction, without the
// copy (for `dcel build` on a large graph, as much memory as the DCEL).
struct DumpOfDump {
    const DcelDump& d;
    [[nodiscard]] const std::vector<Point>& points() const { return d.vertices; }
    [[nodiscard]] std::size_t vertex_out_count() const { return d.vertex_out.size(); }
    [[nodiscard]] HalfEdgeId vertex_out(std::size_t i) const { return d.vertex_out[i]; }
    [[nodiscard]] std::size_t half_edge_count() const { return d.half_edges.size(); }
    [[nodiscard]] const HalfEdgeRecord& half_edge(std::size_t i) const { return d.half_edges[i]; }
    [[nodiscard]] std::size_t face_count() const { return d.faces.size(); }
    [[nodiscard]] HalfEdgeId outer(std::size_t f) const { return d.faces[f].outer; }
    [[nodiscard]] const std::vector<HalfEdgeId>& inner(std::size_t f) const { return d.faces[f].inner; }
    [[nodiscard]] const std::vector<VertexId>& isolated(std::size_t f) const { return d.faces[f].isolated; }
};

struct DumpOfDcel {
    const Dcel& d;
    [[nodiscard]] const std::vector<Point>& points() const { return d.points(); }
    [[nodiscard]] std::size_t vertex_out_count() const { return d.num_vertices(); }
    [[nodiscard]] HalfEdgeId vertex_out(std::size_t i) const { return d.out(VertexId(static_cast<Index>(i))); }
    [[nodiscard]] std::size_t half_edge_count() const { return d.num_half_edges(); }
    [[nodiscard]] HalfEdgeRecord half_edge(std::size_t i) const {
        const HalfEdgeId h(static_cast<Index>(i));
        return {d.origin(h), Dcel::twin(h), d.next(h), d.prev(h), d.face(h)};
    }
    [[nodiscard]] std::size_t face_count() const { return d.num_faces(); }
    [[nodiscard]] HalfEdgeId outer(std::size_t f) const { return d.outer(FaceId(static_cast<Index>(f))); }
    [[nodiscard]] const std::vector<HalfEdgeId>& inner(std::size_t f) const {
        return d.inner(FaceId(static_cast<Index>(f)));
    }
    [[nodiscard]] const std::vector<VertexId>& isolated(std::size_t f) const {
        return d.isolated(FaceId(static_cast<Index>(f)));
    }
};

template <class Records>
void write_dump_records(const Records& src, DumpStyle style, const TextSink& sink) {
    JsonWriter w(sink);
    const bool lines = style == DumpStyle::Lines;
    w.raw(lines ? "{\n" : "{");
    write_array_member(w, "vertices", src.points().size(), style, true,
                       [&](std::size_t i) { write_point(w, src.points(), i); });
    write_array_member(w, "vertex_out", src.vertex_out_count(), style, false,
                       [&](std::size_t i) { w.index(src.vertex_out(i).index()); });
    write_array_member(w, "half_edges", src.half_edge_count(), style, false,
                       [&](std::size_t i) { write_half_edge(w, src.half_edge(i)); });
    write_array_member(w, "faces", src.face_count(), style, false,
                       [&](std::size_t i) { write_face(w, src.outer(i), src.inner(i), src.isolated(i)); });
    w.raw(lines ? "\n}\n" : "}\n");
    w.flush();
}

TextSink append_to(std::string& out) {
    return [&out](std::string_view text) { out.append(text); };
}

}  // namespace

std::string write_faces(const std::vector<std::vector<VertexId>>& cycles) {
    std::string out;
    JsonWriter w(out);
    w.raw("{\"faces\": [");
    for (std::size_t i = 0; i < cycles.size(); ++i) {
        if (i != 0) w.raw(", ");
        write_id_list(w, cycles[i]);
    }
    w.raw("]}\n");
    w.flush();
    return out;
}

std::string write_faces_of(const Dcel& d) {
    std::string out;
    out.reserve(16 + d.num_half_edges() * 9);  // ids of up to 7 digits and ", "
    write_faces_of(d, append_to(out));
    return out;
}

void write_faces_of(const Dcel& d, const TextSink& sink) {
    JsonWriter w(sink);
    w.raw("{\"faces\": [");
    bool first = true;
    for_each_boundary_cycle(d, [&](std::span<const VertexId> origins) {
        if (!first) w.raw(", ");
        first = false;
        write_id_list(w, origins);
    });
    w.raw("]}\n");
    w.flush();
}

std::string write_dump(const DcelDump& dump, DumpStyle style) {
    std::string out;
    out.reserve(64 + dump.vertices.size() * 40 + dump.vertex_out.size() * 12 + dump.half_edges.size() * 80 +
                dump.faces.size() * 48);
    write_dump(dump, style, append_to(out));
    return out;
}

void write_dump(const DcelDump& dump, DumpStyle style, const TextSink& sink) {
    write_dump_records(DumpOfDump{dump}, style, sink);
}

void write_dump_of(const Dcel& d, DumpStyle style, const TextSink& sink) { write_dump_records(DumpOfDcel{d}, style, sink); }

namespace detail {

DcelDump read_dump(std::string_view text, const CountLimits& limits) {
    static constexpr std::array<std::string_view, 4> kKeys{"vertices", "vertex_out", "half_edges", "faces"};
    JsonReader r(text);
    DcelDump dump;
    r.begin_object("a DCEL dump " + std::string(kDumpForm));
    std::uint64_t seen = 0;
    for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
        switch (k) {
            case 0: read_points(r, dump.vertices, limits.vertices); break;
            case 1:
                r.begin_array("an array of half-edge ids or null [h, null, ...]");
                while (r.next_element()) {
                    if (dump.vertex_out.size() >= limits.vertices) too_large(r, limits.vertices, "vertices");
                    dump.vertex_out.emplace_back(r.read_index_or_null(kHalfEdgeId));
                }
                break;
            case 2:
                r.begin_array("an array of half-edges [{\"origin\": v, ...}, ...]");
                while (r.next_element()) {
                    if (dump.half_edges.size() >= limits.half_edges) too_large(r, limits.half_edges, "half-edges");
                    dump.half_edges.push_back(read_half_edge(r));
                }
                break;
            default:
                r.begin_array("an array of faces [{\"outer\": h or null, ...}, ...]");
                while (r.next_element()) {
                    if (dump.faces.size() >= limits.faces) too_large(r, limits.faces, "faces");
                    dump.faces.push_back(read_face(r));
                }
                break;
        }
    }
    if ((seen & 1U) == 0) r.fail_missing_key("vertices", kDumpForm);
    if ((seen & 4U) == 0) r.fail_missing_key("half_edges", kDumpForm);
    if ((seen & 8U) == 0) r.fail_missing_key("faces", kDumpForm);
    r.end_document();
    return dump;
}

std::vector<std::vector<Index>> read_faces_answer(std::string_view text, const CountLimits& limits) {
    JsonReader r(text);
    std::vector<std::vector<Index>> cycles;
    const JsonType top = r.peek();
    if (top == JsonType::Object) {
        static constexpr std::array<std::string_view, 1> kKeys{"faces"};
        r.begin_object(kFacesAnswerForms);
        std::uint64_t seen = 0;
        while (r.next_known_member(kKeys, seen) >= 0) cycles = read_cycles(r, limits);
        if (seen == 0) r.fail_missing_key("faces", R"({"faces": [[v, ...], ...]})");
    } else if (top == JsonType::Array) {
        cycles = read_cycles(r, limits);
    } else {
        r.fail_type(kFacesAnswerForms);
    }
    r.end_document();
    return cycles;
}

}  // namespace detail

DcelDump read_dump(std::string_view text) { return detail::read_dump(text, CountLimits{}); }

std::vector<std::vector<Index>> read_faces_answer(std::string_view text) {
    return detail::read_faces_answer(text, CountLimits{});
}

std::variant<std::vector<std::vector<Index>>, DcelDump> read_answer(std::string_view text) {
    // A first pass over the top-level keys decides the form; it stops at
    // "half_edges". When it meets an error first, the document is not
    // recognisably a dump, and the faces reader reports that error (it skips
    // the same values) or an earlier one of its own.
    bool is_dump = false;
    try {
        JsonReader r(text);
        if (r.peek() == JsonType::Object) {
            r.begin_object("an object");
            while (r.next_member()) {
                if (r.key() == "half_edges") {
                    is_dump = true;
                    break;
                }
                r.skip_value();
            }
        }
    } catch (const InvalidInput&) {
        is_dump = false;
    }
    if (is_dump) return read_dump(text);
    return read_faces_answer(text);
}

}  // namespace dcel::io
