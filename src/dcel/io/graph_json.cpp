#include "dcel/io/graph_json.hpp"
#include "dcel/io/json_writer.hpp"
#include "dcel/io/limited_readers.hpp"

#include <array>

namespace dcel::io {

namespace {

constexpr std::string_view kObjectForm = R"({"vertices": [[x, y], ...], "edges": [[u, v], ...]})";
constexpr std::string_view kGraphForms =
    R"(a graph: {"vertices": [[x, y], ...], "edges": [[u, v], ...]} or [[[x, y], ...], [[u, v], ...]])";
constexpr std::string_view kEdge = "an edge [u, v]";
constexpr std::string_view kVertexIndex = "vertex index";

GraphEdge read_edge(JsonReader& r) {
    r.begin_array(kEdge);
    if (!r.next_element()) r.fail_arity(kEdge, 0);
    GraphEdge e;
    e.u = VertexId(r.read_index(kVertexIndex));
    if (!r.next_element()) r.fail_arity(kEdge, 1);
    e.v = VertexId(r.read_index(kVertexIndex));
    if (r.next_element()) {
        r.skip_value();
        r.fail_arity(kEdge, r.finish_array());
    }
    return e;
}

[[noreturn]] void too_large(const JsonReader& r, std::uint64_t limit, std::string_view what, std::string_view why) {
    r.fail(InputErrorKind::TooLarge,
           "more than " + std::to_string(limit) + " " + std::string(what) + ": " + std::string(why));
}

void read_edges(JsonReader& r, std::vector<GraphEdge>& out, const CountLimits& limits) {
    r.begin_array("an array of edges [[u, v], ...]");
    while (r.next_element()) {
        if (out.size() >= limits.edges) {
            too_large(r, limits.edges, "edges", "each edge takes two 32-bit half-edge ids");
        }
        out.push_back(read_edge(r));
    }
}

}  // namespace

namespace detail {

void read_points(JsonReader& r, std::vector<Point>& out, std::uint64_t limit) {
    r.begin_array("an array of points [[x, y], ...]");
    while (r.next_element()) {
        if (out.size() >= limit) too_large(r, limit, "vertices", "vertex ids are 32-bit");
        out.push_back(read_point(r));
    }
}

PlanarGraph read_graph(std::string_view text, const CountLimits& limits) {
    JsonReader r(text);
    PlanarGraph g;
    const JsonType top = r.peek();
    if (top == JsonType::Object) {
        static constexpr std::array<std::string_view, 2> kKeys{"vertices", "edges"};
        r.begin_object(kGraphForms);
        std::uint64_t seen = 0;
        for (int k = 0; (k = r.next_known_member(kKeys, seen)) >= 0;) {
            if (k == 0) {
                read_points(r, g.vertices, limits.vertices);
            } else {
                read_edges(r, g.edges, limits);
            }
        }
        if ((seen & 1U) == 0) r.fail_missing_key("vertices", kObjectForm);
        if ((seen & 2U) == 0) r.fail_missing_key("edges", kObjectForm);
    } else if (top == JsonType::Array) {
        constexpr std::string_view kPositional = "a graph [vertices, edges]: [[[x, y], ...], [[u, v], ...]]";
        r.begin_array(kGraphForms);
        if (!r.next_element()) r.fail_arity(kPositional, 0);
        read_points(r, g.vertices, limits.vertices);
        if (!r.next_element()) r.fail_arity(kPositional, 1);
        read_edges(r, g.edges, limits);
        if (r.next_element()) {
            r.skip_value();
            r.fail_arity(kPositional, r.finish_array());
        }
    } else {
        r.fail_type(kGraphForms);
    }
    r.end_document();
    return g;
}

}  // namespace detail

std::vector<Point> read_points(std::string_view text) {
    JsonReader r(text);
    std::vector<Point> points;
    detail::read_points(r, points, kNoIndex);
    r.end_document();
    return points;
}

PlanarGraph read_graph(std::string_view text) { return detail::read_graph(text, CountLimits{}); }

std::string write_graph(const PlanarGraph& graph) {
    std::string out;
    out.reserve(40 + graph.vertices.size() * 32 + graph.edges.size() * 16);
    write_graph(graph, [&out](std::string_view text) { out.append(text); });
    return out;
}

void write_graph(const PlanarGraph& graph, const TextSink& sink) {
    JsonWriter w(sink);
    w.raw("{\"vertices\": [");
    for (std::size_t i = 0; i < graph.vertices.size(); ++i) {
        const Point p = graph.vertices[i];
        if (i != 0) w.raw(", ");
        w.raw('[');
        if (!w.number(p.x)) fail_not_finite("vertices[" + std::to_string(i) + "][0]", p.x);
        w.raw(", ");
        if (!w.number(p.y)) fail_not_finite("vertices[" + std::to_string(i) + "][1]", p.y);
        w.raw(']');
    }
    w.raw("], \"edges\": [");
    for (std::size_t i = 0; i < graph.edges.size(); ++i) {
        const GraphEdge e = graph.edges[i];
        if (i != 0) w.raw(", ");
        w.raw('[');
        w.index(e.u.index());
        w.raw(", ");
        w.index(e.v.index());
        w.raw(']');
    }
    w.raw("]}\n");
    w.flush();
}

}  // namespace dcel::io
