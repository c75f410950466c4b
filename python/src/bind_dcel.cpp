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
#include "dcel/format.hpp"
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

Dcel build_released(const PlanarGraph& g, bool check_crossings) {
    const py::gil_scoped_release unlocked;
    return build(g, BuildOptions{check_crossings});
}

PlanarGraph graph_argument(const py::object& vertices, const py::object& edges) {
    return edges.is_none() ? graph_from(vertices) : graph_from(vertices, edges);
}

// An id argument of s: its __index__ first (Python code, which may even edit
// s), then the check against s as it is then.
HalfEdgeId half_edge_arg(const DcelObject& s, const IntArg& h, const char* what) {
    const py::object id = id_value(h, what);
    return HalfEdgeId(id_below(id, s.get()->num_half_edges(), what));
}
FaceId face_arg(const DcelObject& s, const IntArg& f, const char* what) {
    const py::object id = id_value(f, what);
    return FaceId(id_below(id, s.get()->num_faces(), what));
}
VertexId vertex_arg(const DcelObject& s, const IntArg& v, const char* what) {
    const py::object id = id_value(v, what);
    return VertexId(id_below(id, s.get()->num_vertices(), what));
}
EdgeId edge_arg(const DcelObject& s, const IntArg& e, const char* what) {
    const py::object id = id_value(e, what);
    return EdgeId(id_below(id, s.get()->num_edges(), what));
}

// A query of s with one id argument: the id converted first, then the query
// run on the state, held while its answer is made into Python values.
template <class Id, class Query>
py::object query(const DcelObject& s, Id id, Query q) {
    const std::shared_ptr<const Dcel> held = s.get();
    return q(*held, id);
}

// locate() of each point, with the GIL released: the locator is held (an
// edit made meanwhile by another thread builds a new one).
py::list locate_all(DcelObject& s, const py::object& points) {
    constexpr const char* what = "locate_many: points";
    const std::vector<Point> all = points_from(points, what);
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (!std::isfinite(all[i].x) || !std::isfinite(all[i].y)) {
            throw InvalidInput(InputErrorKind::BadCoordinate, std::string(what) + "[" + std::to_string(i) +
                                                                  "]: coordinates must be finite, found " +
                                                                  format_point(all[i]));
        }
    }
    const std::shared_ptr<const PointLocator> locator = s.locator();  // after the points: their code may edit s
    std::vector<Location> found(all.size());
    {
        const py::gil_scoped_release unlocked;
        for (std::size_t i = 0; i < found.size(); ++i) found[i] = locator->locate(all[i]);
    }
    py::list out(found.size());
    for (std::size_t i = 0; i < found.size(); ++i) out[i] = location(found[i]);
    return out;
}

constexpr const char* kDcelDoc = R"doc(The DCEL of a planar straight-line graph, as build() makes it.

Half-edge 2k runs u -> v along input edge k = (u, v), and 2k + 1 back, so
twin(h) = h ^ 1. face(h) is the face on the left of h; next(u->v) leaves v
immediately clockwise from v->u. Face 0 is the unbounded face (no outer
cycle); the other faces have one counterclockwise outer cycle and any number
of holes (the clockwise outer boundaries of the components inside them).

The arrays (points, origin, next, prev, face, out) are read-only numpy views
of the C++ structure, not copies; twin, target and outer are computed. A view
never changes: an edit made while views exist works on a copy.)doc";

using DcelClass = py::class_<DcelObject>;

// The sizes and the stored arrays: numpy views of the C++ structure.
void bind_arrays(DcelClass& cls) {
    cls.def_property_readonly("num_vertices", [](const DcelObject& s) { return s.get()->num_vertices(); })
        .def_property_readonly("num_edges", [](const DcelObject& s) { return s.get()->num_edges(); })
        .def_property_readonly("num_half_edges", [](const DcelObject& s) { return s.get()->num_half_edges(); })
        .def_property_readonly("num_faces", [](const DcelObject& s) { return s.get()->num_faces(); })
        .def_property_readonly(
            "points",
            [](const DcelObject& s) {
                const auto d = s.get();
                return DcelObject::view<double>(d, d->points().data(), d->num_vertices(), 2);
            },
            "(V, 2) float64: the coordinates of each vertex, as given.")
        .def_property_readonly(
            "origin",
            [](const DcelObject& s) {
                const auto d = s.get();
                return DcelObject::view<std::uint32_t>(d, d->origins().data(), d->num_half_edges());
            },
            "(H,) uint32: origin[h], the vertex h leaves.")
        .def_property_readonly(
            "next",
            [](const DcelObject& s) {
                const auto d = s.get();
                return DcelObject::view<std::uint32_t>(d, d->next_links().data(), d->num_half_edges());
            },
            "(H,) uint32: next[h], the half-edge after h on its face's boundary.")
        .def_property_readonly(
            "prev",
            [](const DcelObject& s) {
                const auto d = s.get();
                return DcelObject::view<std::uint32_t>(d, d->prev_links().data(), d->num_half_edges());
            },
            "(H,) uint32: prev[h], the inverse permutation of next.")
        .def_property_readonly(
            "face",
            [](const DcelObject& s) {
                const auto d = s.get();
                return DcelObject::view<std::uint32_t>(d, d->left_faces().data(), d->num_half_edges());
            },
            "(H,) uint32: face[h], the face on the left of h.")
        .def_property_readonly(
            "out",
            [](const DcelObject& s) {
                const auto d = s.get();
                return DcelObject::view<std::uint32_t>(d, d->out_links().data(), d->num_vertices());
            },
            "(V,) uint32: one half-edge leaving each vertex, NULL for an isolated vertex.");
}

// The arrays computed on each call (twin, target, outer) and the face records.
void bind_computed_arrays(DcelClass& cls) {
    cls.def_property_readonly(
           "twin",
           [](const DcelObject& s) {
               return computed(s.get()->num_half_edges(), [](std::size_t h) { return static_cast<std::uint32_t>(h ^ 1U); });
           },
           "(H,) uint32: twin[h] = h ^ 1 (computed).")
        .def_property_readonly(
            "target",
            [](const DcelObject& s) {
                const auto d = s.get();
                const auto& origin = d->origins();
                return computed(origin.size(), [&](std::size_t h) { return origin[h ^ 1U].index(); });
            },
            "(H,) uint32: target[h] = origin[h ^ 1] (computed).")
        .def_property_readonly(
            "outer",
            [](const DcelObject& s) {
                const auto d = s.get();
                return computed(d->num_faces(),
                                [&](std::size_t f) { return d->outer(FaceId(static_cast<Index>(f))).index(); });
            },
            "(F,) uint32: one half-edge of each face's outer cycle, NULL for the unbounded face 0 (computed).")
        .def_property_readonly(
            "faces",
            [](const DcelObject& s) {
                const auto d = s.get();
                py::list out(d->num_faces());
                for (Index f = 0; f < d->num_faces(); ++f) out[f] = face_record(*d, FaceId(f));
                return out;
            },
            "Every face record: Face(id, outer, holes, isolated), face 0 first (outer None).");
}

// Walks: the half-edges of a cycle or around a vertex, every cycle.
void bind_queries(DcelClass& cls) {
    cls.def(
           "cycle",
           [](const DcelObject& s, const IntArg& h) {
               return query(s, half_edge_arg(s, h, "cycle: half-edge"), [](const Dcel& d, HalfEdgeId x) {
                   py::list out;
                   for (const HalfEdgeId y : d.cycle(x)) out.append(y.index());
                   return out;
               });
           },
           py::arg("h"), "The half-edges of the boundary cycle through h, in next order, from h.")
        .def(
            "cycle_vertices",
            [](const DcelObject& s, const IntArg& h) {
                return query(s, half_edge_arg(s, h, "cycle_vertices: half-edge"), [](const Dcel& d, HalfEdgeId x) {
                    py::list out;
                    for (const HalfEdgeId y : d.cycle(x)) out.append(d.origin(y).index());
                    return out;
                });
            },
            py::arg("h"), "The origins of the half-edges of the cycle through h: the cycle as `dcel faces` lists it.")
        .def(
            "around",
            [](const DcelObject& s, const IntArg& v) {
                return query(s, vertex_arg(s, v, "around: vertex"), [](const Dcel& d, VertexId x) {
                    py::list out;
                    for (const HalfEdgeId y : d.around_origin_cw(d.out(x))) out.append(y.index());
                    return out;
                });
            },
            py::arg("v"), "The half-edges leaving v in clockwise order, from out[v]; [] for an isolated vertex.")
        .def(
            "boundary_cycles", [](const DcelObject& s) { return cycles_to_python(boundary_cycles(*s.get())); },
            "Every boundary cycle as its origin vertices in next order, from its smallest half-edge; the `dcel faces` "
            "answer.");
}

// Areas, neighbours and components.
void bind_measures(DcelClass& cls) {
    cls.def(
           "face_area",
           [](const DcelObject& s, const IntArg& f) {
               return query(s, face_arg(s, f, "face_area: face"),
                            [](const Dcel& d, FaceId x) { return area(face_area(d, x)); });
           },
           py::arg("f"),
           "Area(value, sign) of face f: its outer cycle's area minus its holes'. Face 0: (inf, 1). The sign is exact.")
        .def(
            "cycle_area",
            [](const DcelObject& s, const IntArg& h) {
                return query(s, half_edge_arg(s, h, "cycle_area: half-edge"),
                             [](const Dcel& d, HalfEdgeId x) { return area(cycle_area(d, x)); });
            },
            py::arg("h"), "Area(value, sign) of the cycle through h, counterclockwise positive. The sign is exact.")
        .def(
            "neighbours",
            [](const DcelObject& s, const IntArg& f) {
                return query(s, face_arg(s, f, "neighbours: face"),
                             [](const Dcel& d, FaceId x) { return ids_to_python(neighbours(d, x)); });
            },
            py::arg("f"), "The faces across the edges of f's cycles, each once, sorted, f itself excluded.")
        .def(
            "faces_around",
            [](const DcelObject& s, const IntArg& v) {
                return query(s, vertex_arg(s, v, "faces_around: vertex"),
                             [](const Dcel& d, VertexId x) { return ids_to_python(faces_around(d, x)); });
            },
            py::arg("v"),
            "The faces met walking counterclockwise around v (one per wedge); for an isolated vertex, its face.")
        .def(
            "count_components", [](const DcelObject& s) { return count_components(*s.get()); },
            "The number of connected components, isolated vertices included.");
}

// Point location, stabbing and validation.
void bind_location(DcelClass& cls) {
    cls.def(
           "locate",
           [](DcelObject& s, const py::object& p) {
               const Point at = point_from(p, "locate: point");  // first: its code may edit s
               return location(s.locator()->locate(at));
           },
           py::arg("point"),
           "Location(kind, id) of the point (x, y): kind \"vertex\", \"edge\" (inside it) or \"face\" (inside it). Exact.\n"
           "The first call builds a point locator (O(E log E) expected); later calls take O(log E) expected.")
        .def("locate_many", &locate_all, py::arg("points"), "locate() of each point of an (n, 2) array or list of pairs.")
        .def(
            "stab",
            [](const DcelObject& s, const py::object& a, const py::object& b, const FlagArg& line) {
                const Point pa = point_from(a, "stab: a");
                const Point pb = point_from(b, "stab: b");
                const bool whole_line = flag_from(line, "stab: line");
                const auto d = s.get();
                return pieces(whole_line ? stab_line(*d, pa, pb) : stab_segment(*d, pa, pb));
            },
            py::arg("a"), py::arg("b"), py::kw_only(), py::arg("line") = false,
            "Everything the segment from a to b meets, in order from a: StabPiece(kind, id, along) for each face\n"
            "stretch, edge crossed (along=True when running along it) and vertex passed. line=True: the whole line\n"
            "through a and b, from the unbounded face to the unbounded face.")
        .def(
            "validate", [](const DcelObject& s) { return violations_to_python(validate_all(to_dump(*s.get()))); },
            "Every broken invariant (the first of each checker); [] for a DCEL built here.");
}

// The edits that split and add: each converts its arguments first (their
// code may edit the DCEL), then edits.
void bind_edits(DcelClass& cls) {
    cls.def(
           "split_edge",
           [](DcelObject& s, const IntArg& e, const py::object& p) {
               const Point at = point_from(p, "split_edge: point");
               const EdgeId id = edge_arg(s, e, "split_edge: edge");
               return edited([&] { return split_edge(s.for_edit(), id, at); }, {}, {id.index()});
           },
           py::arg("e"), py::arg("point"),
           "Splits edge e at point (exactly on e, strictly inside). The new vertex is V, the new edge E. Returns a Change.")
        .def(
            "add_edge",
            [](DcelObject& s, const IntArg& u, const IntArg& v) {
                constexpr const char* what = "add_edge: vertex";
                const py::object ui = id_value(u, what);
                const py::object vi = id_value(v, what);
                const VertexId a(id_below(ui, s.get()->num_vertices(), what));
                const VertexId b(id_below(vi, s.get()->num_vertices(), what));
                return edited([&] { return add_edge(s.for_edit(), a, b); }, {a.index(), b.index()});
            },
            py::arg("u"), py::arg("v"),
            "Adds the edge u-v (id E, half-edge 2E runs u -> v), splitting or joining faces. TopologyError when it\n"
            "would cross, overlap or pass through anything. Returns a Change.")
        .def(
            "add_edge_to_point",
            [](DcelObject& s, const IntArg& u, const py::object& p) {
                const Point at = point_from(p, "add_edge_to_point: point");
                const VertexId a = vertex_arg(s, u, "add_edge_to_point: vertex");
                return edited([&] { return add_edge_to_point(s.for_edit(), a, at); }, {a.index()});
            },
            py::arg("u"), py::arg("point"), "Adds a vertex at point and the edge from u to it. Returns a Change.")
        .def(
            "add_vertex",
            [](DcelObject& s, const py::object& p) {
                const Point at = point_from(p, "add_vertex: point");
                return edited([&] { return add_vertex(s.for_edit(), at); }, {});
            },
            py::arg("point"), "Adds an isolated vertex at point, listed in the face containing it. Returns a Change.");
}

// The edits that remove: each converts its argument first, then edits.
void bind_removals(DcelClass& cls) {
    cls.def(
           "remove_edge",
           [](DcelObject& s, const IntArg& e) {
               const EdgeId id = edge_arg(s, e, "remove_edge: edge");
               return edited([&] { return remove_edge(s.for_edit(), id); }, {}, {id.index()});
           },
           py::arg("e"), "Removes edge e; the last edge moves into its id. Returns a Change.")
        .def(
            "remove_isolated_vertex",
            [](DcelObject& s, const IntArg& v) {
                const VertexId id = vertex_arg(s, v, "remove_isolated_vertex: vertex");
                return edited([&] { return remove_isolated_vertex(s.for_edit(), id); }, {id.index()});
            },
            py::arg("v"), "Removes v, which has no edges; the last vertex moves into its id. Returns a Change.")
        .def(
            "merge_collinear_edges",
            [](DcelObject& s, const IntArg& v) {
                const VertexId id = vertex_arg(s, v, "merge_collinear_edges: vertex");
                return edited([&] { return merge_collinear_edges(s.for_edit(), id); }, {id.index()});
            },
            py::arg("v"),
            "Removes v, which has exactly two edges a-v-b with v strictly inside a-b: the inverse of split_edge.");
}

// The graph, the dump, the picture, copies and the repr.
void bind_output(DcelClass& cls) {
    cls.def(
           "graph", [](const DcelObject& s) { return graph_as_arrays(to_graph(*s.get())); },
           "The graph under this DCEL as Graph(vertices, edges) of numpy arrays: build() of it gives this DCEL again\n"
           "(up to face numbering). How an edited DCEL is saved.")
        .def(
            "to_json",
            [](const DcelObject& s, const FlagArg& compact) {
                const bool one_line = flag_from(compact, "to_json: compact");
                return io::write_dump(to_dump(*s.get()), one_line ? io::DumpStyle::Compact : io::DumpStyle::Lines);
            },
            py::kw_only(), py::arg("compact") = false, "The dump that `dcel build` prints (docs/formats.md).")
        .def(
            "to_dump",
            [](const DcelObject& s) {
                return imported().json_loads(io::write_dump(to_dump(*s.get()), io::DumpStyle::Compact));
            },
            "The dump as a dict of lists: vertices, vertex_out, half_edges, faces (the `dcel build` format).")
        .def(
            "svg",
            [](const DcelObject& s, const TextArg& title, const CyclesArg& highlight) {
                io::SvgOptions options;
                options.title = text_from(title, "svg: title");
                options.highlight_cycles = cycles_from(highlight, "svg: highlight");
                return io::render_svg(*s.get(), options);
            },
            py::kw_only(), py::arg("title") = "", py::arg("highlight") = py::list(),
            "An SVG picture (faces tinted, half-edges as arrows, vertex ids); highlight: vertex cycles drawn in red.")
        .def(
            "copy", [](const DcelObject& s) { return DcelObject(*s.get()); }, "An independent copy.")
        .def("__copy__", [](const DcelObject& s) { return DcelObject(*s.get()); })
        .def(
            "__deepcopy__", [](const DcelObject& s, const py::object&) { return DcelObject(*s.get()); }, py::arg("memo"))
        .def("__repr__", [](const DcelObject& s) {
            const auto d = s.get();
            return "<dcel.Dcel: " + std::to_string(d->num_vertices()) + " vertices, " + std::to_string(d->num_edges()) +
                   " edges, " + std::to_string(d->num_faces()) + " faces>";
        });
}

// The module functions that build: build(), faces() and read_graph().
void bind_build_functions(py::module_& m) {
    m.def(
        "build",
        [](const py::object& vertices, const py::object& edges, const FlagArg& check_crossings) {
            const bool check = flag_from(check_crossings, "build: check_crossings");
            return DcelObject(build_released(graph_argument(vertices, edges), check));
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
        "read_graph", [](const TextArg& text) { return graph_as_arrays(io::read_graph(text_from(text, ""))); },
        py::arg("text"),
        "The graph in JSON text (`dcel faces` input: {\"vertices\": [[x, y], ...], \"edges\": [[u, v], ...]} or the\n"
        "positional form), read as the CLI reads it (coordinates correctly rounded), as Graph(vertices, edges) of\n"
        "numpy arrays. InvalidInput names the place of a syntax or shape error (line and column, or a JSON path).");
}

// For measuring the binding's overhead (python/bench).
void bind_timing(py::module_& m) {
    m.def(
        "_build_seconds",
        [](const py::object& vertices, const py::object& edges, const IntArg& repeat_arg) {
            // For measuring the binding's overhead (python/bench): the C++
            // call alone on a graph converted once, in thread CPU seconds
            // (what time.thread_time() counts on the Python side).
            const PlanarGraph g = graph_from(vertices, edges);
            const std::size_t repeat = count_from(repeat_arg, 1000, "_build_seconds: repeat");
            std::vector<double> seconds;
            const py::gil_scoped_release unlocked;
            const auto now = [] {
                timespec t{};
                clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
                return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
            };
            for (std::size_t i = 0; i < repeat; ++i) {
                const double start = now();
                const Dcel d = build(g);
                seconds.push_back(now() - start);
            }
            return seconds;
        },
        py::arg("vertices"), py::arg("edges"), py::arg("repeat") = 1);
}

}  // namespace

void bind_dcel(py::module_& m) {
    DcelClass cls(m, "Dcel", kDcelDoc);
    cls.attr("__module__") = "dcel";  // shown as dcel.Dcel
    bind_arrays(cls);
    bind_computed_arrays(cls);
    bind_queries(cls);
    bind_measures(cls);
    bind_location(cls);
    bind_edits(cls);
    bind_removals(cls);
    bind_output(cls);
    bind_build_functions(m);
    bind_timing(m);
}

}  // namespace dcel::python
