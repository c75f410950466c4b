// The pieces of the Python extension dcel._dcel, one file per area:
// imports.cpp (everything looked up in Python, once, at import),
// inputs.cpp (Python values in: graphs, points, ids), errors.cpp (C++
// exceptions out as dcel.InvalidInput / dcel.TopologyError),
// bind_dcel.cpp (the Dcel class: numpy views, queries, edits),
// bind_check.cpp (check and validate), bind_gen.cpp (the generators).
// Only public headers of the library are used, as the CLI does.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "dcel/graph.hpp"
#include "dcel/ids.hpp"

namespace dcel {
struct Violation;
}

namespace dcel::python {

namespace py = pybind11;

// Points are copied and viewed as (n, 2) float64 arrays: x then y, nothing else.
static_assert(sizeof(Point) == 2 * sizeof(double) && std::is_standard_layout_v<Point>);

// ---- Imports (imports.cpp), all made by prepare_imports() at import time.
void prepare_imports();
// A value type or exception class of dcel._types (Graph, Face, Location, ...).
[[nodiscard]] py::handle value_type(const char* name);
struct Imported {
    py::handle asarray;            // numpy.asarray
    py::handle ascontiguousarray;  // numpy.ascontiguousarray
    py::handle json_loads;         // json.loads
};
[[nodiscard]] const Imported& imported();

// ---- Inputs (inputs.cpp). Every failure is InvalidInput with a message that
// names the place ("vertices[3]: ...", "edges[2][1]: ...").

// vertices: anything numpy can read as an (n, 2) float64 array (lists of
// pairs, arrays); edges: an (m, 2) array of integers (integral floats are
// accepted, as the JSON reader accepts 1.0). Copied once into the graph.
[[nodiscard]] PlanarGraph graph_from(py::handle vertices, py::handle edges);
// A graph argument: a Graph (or any pair (vertices, edges)) or a mapping with
// "vertices" and "edges".
[[nodiscard]] PlanarGraph graph_from(py::handle graph);
// A point (x, y); `what` names it in errors ("split_edge: point").
[[nodiscard]] Point point_from(py::handle p, std::string_view what);
// An id argument that must be below `count`; `what` is e.g. "split_edge: edge".
[[nodiscard]] Index id_below(std::int64_t id, std::size_t count, std::string_view what);

// ---- Outputs.
// Graph(vertices=[(x, y), ...], edges=[(u, v), ...]) of plain Python values.
[[nodiscard]] py::object graph_to_python(const PlanarGraph& g);
// [id, ...] of typed ids.
template <class Id>
[[nodiscard]] py::list ids_to_python(const std::vector<Id>& v) {
    py::list out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[i].index();
    return out;
}
// [Violation(invariant, message, vertices, half_edges, faces), ...]
[[nodiscard]] py::list violations_to_python(const std::vector<Violation>& all);
// An id, or None when null.
[[nodiscard]] py::object id_or_none(Index id);

// A refused edit (TopologyError from the library) with the edit's own
// arguments, which the Python TopologyError carries as its ids.
struct EditRefused {
    std::string message;
    std::vector<Index> vertices;
    std::vector<Index> edges;
};

// ---- Registration.
void register_errors(py::module_& m);
void bind_dcel(py::module_& m);
void bind_check(py::module_& m);
void bind_gen(py::module_& m);

}  // namespace dcel::python
