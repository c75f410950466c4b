// dcel.Dcel (the class DcelObject, dcel_object.hpp): numpy views, walks,
// queries, point location, stabbing and edits; and build() and faces().
#include <cmath>
#include <cstring>
#include <ctime>
#include <memory>

#include <pybind11/stl.h>

#include "binding.hpp"
#include "dcel/build.hpp"
#include "dcel/dump.hpp"
#include "dcel/edit.hpp"
#include "dcel/error.hpp"
#include "dcel/io/dcel_json.hpp"
#include "dcel/io/graph_json.hpp"
#include "dcel/io/svg.hpp"
#include "dcel/locate.hpp"
#include "dcel/queries.hpp"
#include "dcel/stab.hpp"
#include "dcel/to_graph.hpp"
#include "dcel/validate.hpp"
#include "dcel_object.hpp"

namespace dcel::python {
namespace {

static_assert(sizeof(VertexId) == 4 && sizeof(HalfEdgeId) == 4 && sizeof(FaceId) == 4);
static_assert(std::is_standard_layout_v<VertexId> && std::is_standard_layout_v<HalfEdgeId> &&
              std::is_standard_layout_v<FaceId>);

// A fresh read-only uint32 array of n elements, filled by fill(i).
template <class Fill>
py::array computed(std::size_t n, Fill fill) {
    py::array_t<std::uint32_t> a(static_cast<py::ssize_t>(n));
    std::uint32_t* out = a.mutable_data();
    for (std::size_t i = 0; i < n; ++i) out[i] = fill(i);
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

py::object face_record(const Dcel& d, FaceId f) {
    return value_type("Face")(f.index(), id_or_none(d.outer(f).index()), ids_to_python(d.inner(f)),
                              ids_to_python(d.isolated(f)));
}

py::object area(const Area& a) { return value_type("Area")(a.value, to_int(a.sign)); }

py::object location(const Location& l) {
    switch (l.kind) {
        case Location::Kind::Face: return value_type("Location")("face", l.face.index());
        case Location::Kind::Edge: return value_type("Location")("edge", l.edge.index());
        case Location::Kind::Vertex: return value_type("Location")("vertex", l.vertex.index());
    }
    return py::none();
}

py::list pieces(const std::vector<StabPiece>& v) {
    const py::handle piece = value_type("StabPiece");
    py::list out;
    for (const StabPiece& p : v) {
        switch (p.kind) {
            case StabPiece::Kind::Face: out.append(piece("face", p.face.index(), false)); break;
            case StabPiece::Kind::Edge: out.append(piece("edge", p.edge.index(), p.along)); break;
            case StabPiece::Kind::Vertex: out.append(piece("vertex", p.vertex.index(), false)); break;
        }
    }
    return out;
}

template <class Id>
py::object id_change(const IdChange<Id>& c) {
    return value_type("IdChange")(id_or_none(c.added.index()), id_or_none(c.added_from.index()),
                                  id_or_none(c.removed.index()), id_or_none(c.merged_into.index()),
                                  id_or_none(c.moved.index()));
}

py::object change(const Change& c) {
    return value_type("Change")(id_change(c.vertices), id_change(c.edges), id_change(c.faces));
}

// Runs an edit; a refusal carries the edit's vertex and edge arguments.
template <class Edit>
py::object edited(Edit edit, std::vector<Index> vertices, std::vector<Index> edges = {}) {
    try {
        return change(edit());
    } catch (const TopologyError& e) {
        throw EditRefused{e.what(), std::move(vertices), std::move(edges)};
    }
}

// Graph(vertices, edges) of numpy arrays: (V, 2) float64 and (E, 2) uint32.
py::object graph_as_arrays(const PlanarGraph& g) {
    py::array_t<double> vertices({static_cast<py::ssize_t>(g.vertices.size()), py::ssize_t{2}});
    if (!g.vertices.empty()) std::memcpy(vertices.mutable_data(), g.vertices.data(), g.vertices.size() * sizeof(Point));
    py::array_t<std::uint32_t> edges({static_cast<py::ssize_t>(g.edges.size()), py::ssize_t{2}});
    std::uint32_t* out = edges.mutable_data();
    for (const GraphEdge& e : g.edges) {
        *out++ = e.u.index();
        *out++ = e.v.index();
    }
    return value_type("Graph")(vertices, edges);
}

py::list cycles_to_python(const std::vector<std::vector<VertexId>>& cycles) {
    py::list out(cycles.size());
    for (std::size_t i = 0; i < cycles.size(); ++i) out[i] = ids_to_python(cycles[i]);
    return out;
}

Dcel build_released(PlanarGraph g, bool check_crossings) {
    const py::gil_scoped_release unlocked;
    return build(g, BuildOptions{check_crossings});
}

PlanarGraph graph_argument(const py::object& vertices, const py::object& edges) {
    return edges.is_none() ? graph_from(vertices) : graph_from(vertices, edges);
}

HalfEdgeId half_edge_arg(const Dcel& d, std::int64_t h, const char* what) {
    return HalfEdgeId(id_below(h, d.num_half_edges(), what));
}
FaceId face_arg(const Dcel& d, std::int64_t f, const char* what) { return FaceId(id_below(f, d.num_faces(), what)); }
VertexId vertex_arg(const Dcel& d, std::int64_t v, const char* what) {
    return VertexId(id_below(v, d.num_vertices(), what));
}
EdgeId edge_arg(const Dcel& d, std::int64_t e, const char* what) { return EdgeId(id_below(e, d.num_edges(), what)); }

constexpr const char* kDcelDoc = R"doc(The DCEL of a planar straight-line graph, as build() makes it.

Half-edge 2k runs u -> v along input edge k = (u, v), and 2k + 1 back, so
twin(h) = h ^ 1. face(h) is the face on the left of h; next(u->v) leaves v
immediately clockwise from v->u. Face 0 is the unbounded face (no outer
cycle); the other faces have one counterclockwise outer cycle and any number
of holes (the clockwise outer boundaries of the components inside them).

The arrays (points, origin, next, prev, face, out) are read-only numpy views
of the C++ structure, not copies; twin, target and outer are computed. A view
never changes: an edit made while views exist works on a copy.)doc";

}  // namespace

void bind_dcel(py::module_& m) {
    py::class_<DcelObject> cls(m, "Dcel", kDcelDoc);
    cls.attr("__module__") = "dcel";  // shown as dcel.Dcel
    cls.def_property_readonly("num_vertices", [](const DcelObject& s) { return s.get().num_vertices(); })
        .def_property_readonly("num_edges", [](const DcelObject& s) { return s.get().num_edges(); })
        .def_property_readonly("num_half_edges", [](const DcelObject& s) { return s.get().num_half_edges(); })
        .def_property_readonly("num_faces", [](const DcelObject& s) { return s.get().num_faces(); })
        .def_property_readonly(
            "points", [](const DcelObject& s) { return s.view<double>(s.get().points().data(), s.get().num_vertices(), 2); },
            "(V, 2) float64: the coordinates of each vertex, as given.")
        .def_property_readonly(
            "origin",
            [](const DcelObject& s) { return s.view<std::uint32_t>(s.get().origins().data(), s.get().num_half_edges()); },
            "(H,) uint32: origin[h], the vertex h leaves.")
        .def_property_readonly(
            "next",
            [](const DcelObject& s) { return s.view<std::uint32_t>(s.get().next_links().data(), s.get().num_half_edges()); },
            "(H,) uint32: next[h], the half-edge after h on its face's boundary.")
        .def_property_readonly(
            "prev",
            [](const DcelObject& s) { return s.view<std::uint32_t>(s.get().prev_links().data(), s.get().num_half_edges()); },
            "(H,) uint32: prev[h], the inverse permutation of next.")
        .def_property_readonly(
            "face",
            [](const DcelObject& s) { return s.view<std::uint32_t>(s.get().left_faces().data(), s.get().num_half_edges()); },
            "(H,) uint32: face[h], the face on the left of h.")
        .def_property_readonly(
            "out",
            [](const DcelObject& s) { return s.view<std::uint32_t>(s.get().out_links().data(), s.get().num_vertices()); },
            "(V,) uint32: one half-edge leaving each vertex, NULL for an isolated vertex.")
        .def_property_readonly(
            "twin",
            [](const DcelObject& s) {
                return computed(s.get().num_half_edges(), [](std::size_t h) { return static_cast<std::uint32_t>(h ^ 1U); });
            },
            "(H,) uint32: twin[h] = h ^ 1 (computed).")
        .def_property_readonly(
            "target",
            [](const DcelObject& s) {
                const auto& origin = s.get().origins();
                return computed(origin.size(), [&](std::size_t h) { return origin[h ^ 1U].index(); });
            },
            "(H,) uint32: target[h] = origin[h ^ 1] (computed).")
        .def_property_readonly(
            "outer",
            [](const DcelObject& s) {
                const Dcel& d = s.get();
                return computed(d.num_faces(),
                                [&](std::size_t f) { return d.outer(FaceId(static_cast<Index>(f))).index(); });
            },
            "(F,) uint32: one half-edge of each face's outer cycle, NULL for the unbounded face 0 (computed).")
        .def_property_readonly(
            "faces",
            [](const DcelObject& s) {
                const Dcel& d = s.get();
                py::list out(d.num_faces());
                for (Index f = 0; f < d.num_faces(); ++f) out[f] = face_record(d, FaceId(f));
                return out;
            },
            "Every face record: Face(id, outer, holes, isolated), face 0 first (outer None).")
        .def(
            "cycle",
            [](const DcelObject& s, std::int64_t h) {
                const Dcel& d = s.get();
                py::list out;
                for (const HalfEdgeId x : d.cycle(half_edge_arg(d, h, "cycle: half-edge"))) out.append(x.index());
                return out;
            },
            py::arg("h"), "The half-edges of the boundary cycle through h, in next order, from h.")
        .def(
            "cycle_vertices",
            [](const DcelObject& s, std::int64_t h) {
                const Dcel& d = s.get();
                py::list out;
                for (const HalfEdgeId x : d.cycle(half_edge_arg(d, h, "cycle_vertices: half-edge")))
                    out.append(d.origin(x).index());
                return out;
            },
            py::arg("h"), "The origins of the half-edges of the cycle through h: the cycle as `dcel faces` lists it.")
        .def(
            "around",
            [](const DcelObject& s, std::int64_t v) {
                const Dcel& d = s.get();
                py::list out;
                for (const HalfEdgeId x : d.around_origin_cw(d.out(vertex_arg(d, v, "around: vertex"))))
                    out.append(x.index());
                return out;
            },
            py::arg("v"), "The half-edges leaving v in clockwise order, from out[v]; [] for an isolated vertex.")
        .def(
            "boundary_cycles", [](const DcelObject& s) { return cycles_to_python(boundary_cycles(s.get())); },
            "Every boundary cycle as its origin vertices in next order, from its smallest half-edge; the `dcel faces` "
            "answer.")
        .def(
            "face_area",
            [](const DcelObject& s, std::int64_t f) {
                return area(face_area(s.get(), face_arg(s.get(), f, "face_area: face")));
            },
            py::arg("f"),
            "Area(value, sign) of face f: its outer cycle's area minus its holes'. Face 0: (inf, 1). The sign is exact.")
        .def(
            "cycle_area",
            [](const DcelObject& s, std::int64_t h) {
                return area(cycle_area(s.get(), half_edge_arg(s.get(), h, "cycle_area: half-edge")));
            },
            py::arg("h"), "Area(value, sign) of the cycle through h, counterclockwise positive. The sign is exact.")
        .def(
            "neighbours",
            [](const DcelObject& s, std::int64_t f) {
                return ids_to_python(neighbours(s.get(), face_arg(s.get(), f, "neighbours: face")));
            },
            py::arg("f"), "The faces across the edges of f's cycles, each once, sorted, f itself excluded.")
        .def(
            "faces_around",
            [](const DcelObject& s, std::int64_t v) {
                return ids_to_python(faces_around(s.get(), vertex_arg(s.get(), v, "faces_around: vertex")));
            },
            py::arg("v"),
            "The faces met walking counterclockwise around v (one per wedge); for an isolated vertex, its face.")
        .def(
            "count_components", [](const DcelObject& s) { return count_components(s.get()); },
            "The number of connected components, isolated vertices included.")
        .def(
            "locate",
            [](DcelObject& s, const py::object& p) { return location(s.locator().locate(point_from(p, "locate: point"))); },
            py::arg("point"),
            "Location(kind, id) of the point (x, y): kind \"vertex\", \"edge\" (inside it) or \"face\" (inside it). Exact.\n"
            "The first call builds a point locator (O(E log E) expected); later calls take O(log E) expected.")
        .def(
            "locate_many",
            [](DcelObject& s, const py::object& points) {
                const PlanarGraph g = graph_from(points, py::list());
                const PointLocator& locator = s.locator();
                std::vector<Location> found(g.vertices.size());
                for (const Point p : g.vertices) {
                    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
                        throw InvalidInput(InputErrorKind::BadCoordinate, "locate_many: coordinates must be finite");
                    }
                }
                {
                    const py::gil_scoped_release unlocked;
                    for (std::size_t i = 0; i < found.size(); ++i) found[i] = locator.locate(g.vertices[i]);
                }
                py::list out(found.size());
                for (std::size_t i = 0; i < found.size(); ++i) out[i] = location(found[i]);
                return out;
            },
            py::arg("points"), "locate() of each point of an (n, 2) array or list of pairs.")
        .def(
            "stab",
            [](const DcelObject& s, const py::object& a, const py::object& b, bool line) {
                const Point pa = point_from(a, "stab: a");
                const Point pb = point_from(b, "stab: b");
                return pieces(line ? stab_line(s.get(), pa, pb) : stab_segment(s.get(), pa, pb));
            },
            py::arg("a"), py::arg("b"), py::kw_only(), py::arg("line") = false,
            "Everything the segment from a to b meets, in order from a: StabPiece(kind, id, along) for each face\n"
            "stretch, edge crossed (along=True when running along it) and vertex passed. line=True: the whole line\n"
            "through a and b, from the unbounded face to the unbounded face.")
        .def(
            "validate", [](const DcelObject& s) { return violations_to_python(validate_all(to_dump(s.get()))); },
            "Every broken invariant (the first of each checker); [] for a DCEL built here.")
        .def(
            "split_edge",
            [](DcelObject& s, std::int64_t e, const py::object& p) {
                const EdgeId id = edge_arg(s.get(), e, "split_edge: edge");
                const Point at = point_from(p, "split_edge: point");
                return edited([&] { return split_edge(s.for_edit(), id, at); }, {}, {id.index()});
            },
            py::arg("e"), py::arg("point"),
            "Splits edge e at point (exactly on e, strictly inside). The new vertex is V, the new edge E. Returns a Change.")
        .def(
            "add_edge",
            [](DcelObject& s, std::int64_t u, std::int64_t v) {
                const VertexId a = vertex_arg(s.get(), u, "add_edge: vertex");
                const VertexId b = vertex_arg(s.get(), v, "add_edge: vertex");
                return edited([&] { return add_edge(s.for_edit(), a, b); }, {a.index(), b.index()});
            },
            py::arg("u"), py::arg("v"),
            "Adds the edge u-v (id E, half-edge 2E runs u -> v), splitting or joining faces. TopologyError when it\n"
            "would cross, overlap or pass through anything. Returns a Change.")
        .def(
            "add_edge_to_point",
            [](DcelObject& s, std::int64_t u, const py::object& p) {
                const VertexId a = vertex_arg(s.get(), u, "add_edge_to_point: vertex");
                const Point at = point_from(p, "add_edge_to_point: point");
                return edited([&] { return add_edge_to_point(s.for_edit(), a, at); }, {a.index()});
            },
            py::arg("u"), py::arg("point"), "Adds a vertex at point and the edge from u to it. Returns a Change.")
        .def(
            "add_vertex",
            [](DcelObject& s, const py::object& p) {
                const Point at = point_from(p, "add_vertex: point");
                return edited([&] { return add_vertex(s.for_edit(), at); }, {});
            },
            py::arg("point"), "Adds an isolated vertex at point, listed in the face containing it. Returns a Change.")
        .def(
            "remove_edge",
            [](DcelObject& s, std::int64_t e) {
                const EdgeId id = edge_arg(s.get(), e, "remove_edge: edge");
                return edited([&] { return remove_edge(s.for_edit(), id); }, {}, {id.index()});
            },
            py::arg("e"), "Removes edge e; the last edge moves into its id. Returns a Change.")
        .def(
            "remove_isolated_vertex",
            [](DcelObject& s, std::int64_t v) {
                const VertexId id = vertex_arg(s.get(), v, "remove_isolated_vertex: vertex");
                return edited([&] { return remove_isolated_vertex(s.for_edit(), id); }, {id.index()});
            },
            py::arg("v"), "Removes v, which has no edges; the last vertex moves into its id. Returns a Change.")
        .def(
            "merge_collinear_edges",
            [](DcelObject& s, std::int64_t v) {
                const VertexId id = vertex_arg(s.get(), v, "merge_collinear_edges: vertex");
                return edited([&] { return merge_collinear_edges(s.for_edit(), id); }, {id.index()});
            },
            py::arg("v"),
            "Removes v, which has exactly two edges a-v-b with v strictly inside a-b: the inverse of split_edge.")
        .def(
            "graph", [](const DcelObject& s) { return graph_as_arrays(to_graph(s.get())); },
            "The graph under this DCEL as Graph(vertices, edges) of numpy arrays: build() of it gives this DCEL again\n"
            "(up to face numbering). How an edited DCEL is saved.")
        .def(
            "to_json",
            [](const DcelObject& s, bool compact) {
                return io::write_dump(to_dump(s.get()), compact ? io::DumpStyle::Compact : io::DumpStyle::Lines);
            },
            py::kw_only(), py::arg("compact") = false, "The dump that `dcel build` prints (docs/formats.md).")
        .def(
            "to_dump",
            [](const DcelObject& s) {
                return imported().json_loads(io::write_dump(to_dump(s.get()), io::DumpStyle::Compact));
            },
            "The dump as a dict of lists: vertices, vertex_out, half_edges, faces (the `dcel build` format).")
        .def(
            "svg",
            [](const DcelObject& s, const std::string& title, const std::vector<std::vector<Index>>& highlight) {
                io::SvgOptions options;
                options.title = title;
                options.highlight_cycles = highlight;
                return io::render_svg(s.get(), options);
            },
            py::kw_only(), py::arg("title") = "", py::arg("highlight") = std::vector<std::vector<Index>>{},
            "An SVG picture (faces tinted, half-edges as arrows, vertex ids); highlight: vertex cycles drawn in red.")
        .def(
            "copy", [](const DcelObject& s) { return DcelObject(s.get()); }, "An independent copy.")
        .def("__copy__", [](const DcelObject& s) { return DcelObject(s.get()); })
        .def(
            "__deepcopy__", [](const DcelObject& s, const py::object&) { return DcelObject(s.get()); }, py::arg("memo"))
        .def("__repr__", [](const DcelObject& s) {
            const Dcel& d = s.get();
            return "<dcel.Dcel: " + std::to_string(d.num_vertices()) + " vertices, " + std::to_string(d.num_edges()) +
                   " edges, " + std::to_string(d.num_faces()) + " faces>";
        });

    m.def(
        "build",
        [](const py::object& vertices, const py::object& edges, bool check_crossings) {
            return DcelObject(build_released(graph_argument(vertices, edges), check_crossings));
        },
        py::arg("vertices"), py::arg("edges") = py::none(), py::kw_only(), py::arg("check_crossings") = true,
        R"doc(The DCEL of a planar straight-line graph.

vertices: (x, y) pairs (a list, or an (n, 2) array); edges: (u, v) index
pairs. Or one argument: a Graph, a pair (vertices, edges), or a mapping with
"vertices" and "edges". Raises InvalidInput, naming the offending vertices
and edges, for anything that is not a planar straight-line graph: crossings,
a vertex inside an edge, collinear overlaps, duplicate points or edges,
self-loops, bad indexes, coordinates that are not finite.
check_crossings=False skips the crossing checks (faster; you promise there
are none). O((V + E) log(V + E)).)doc");
    m.def(
        "faces",
        [](const py::object& vertices, const py::object& edges) {
            return cycles_to_python(boundary_cycles(build_released(graph_argument(vertices, edges), true)));
        },
        py::arg("vertices"), py::arg("edges") = py::none(),
        "Every boundary cycle of the graph as vertex ids in next order: what `dcel faces` prints.");
    m.def(
        "read_graph", [](const std::string& text) { return graph_as_arrays(io::read_graph(text)); }, py::arg("text"),
        "The graph in JSON text (`dcel faces` input: {\"vertices\": [[x, y], ...], \"edges\": [[u, v], ...]} or the\n"
        "positional form), read as the CLI reads it (coordinates correctly rounded), as Graph(vertices, edges) of\n"
        "numpy arrays. InvalidInput names the place of a syntax or shape error (line and column, or a JSON path).");
    m.def(
        "_build_seconds",
        [](const py::object& vertices, const py::object& edges, int repeat) {
            // For measuring the binding's overhead (python/bench): the C++
            // call alone on a graph converted once, in thread CPU seconds
            // (what time.thread_time() counts on the Python side).
            const PlanarGraph g = graph_from(vertices, edges);
            std::vector<double> seconds;
            const py::gil_scoped_release unlocked;
            const auto now = [] {
                timespec t{};
                clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
                return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
            };
            for (int i = 0; i < repeat; ++i) {
                const double start = now();
                const Dcel d = build(g);
                seconds.push_back(now() - start);
            }
            return seconds;
        },
        py::arg("vertices"), py::arg("edges"), py::arg("repeat") = 1);
}

}  // namespace dcel::python
