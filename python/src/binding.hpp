// The pieces of the Python extension dcel._dcel, one file per area:
// imports.cpp (everything looked up in Python, once, at import),
// args.cpp (scalar arguments in: ids, counts, strings, flags; how a Python
// value or error is shown in a message), inputs.cpp (Python values in:
// graphs, points, id lists), errors.cpp (C++ exceptions out as
// dcel.InvalidInput / dcel.TopologyError), bind_dcel.cpp (the Dcel class:
// numpy views, queries, edits), bind_check.cpp (check and validate),
// bind_gen.cpp (the generators). Only public headers of the library are
// used, as the CLI does.
//
// Hostile Python objects (docs/python.md, "Hostile objects"): a value's
// __float__, __index__, __len__, __getitem__ or __repr__ is Python code
// that may raise, lie, or change the very list being read. Every list is
// read through strong references (inputs.cpp), every argument is converted
// here rather than by pybind11 (whose refusal is a multi-line TypeError
// naming the C++ signature), and every error names its place on one line.
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
    py::handle ndarray_tolist;     // numpy.ndarray.tolist, unbound (a subclass cannot override it)
    py::handle json_loads;         // json.loads
    py::handle mapping;            // collections.abc.Mapping
    py::handle short_repr;         // reprlib.Repr(...).repr, with small limits
};
[[nodiscard]] const Imported& imported();

// ---- Arguments taken as they are and converted in the function body, where
// their place is known. pybind11's own conversion refuses a bad value with a
// multi-line TypeError that lists the C++ overloads; these accept any object
// and show the Python type named by Tag in signatures (help()).
template <class Tag>
struct Arg {
    py::object value;
};
struct IntTag {
    static constexpr auto name = py::detail::const_name("int");
};
struct TextTag {
    static constexpr auto name = py::detail::const_name("str");
};
struct FlagTag {
    static constexpr auto name = py::detail::const_name("bool");
};
struct CyclesTag {
    static constexpr auto name = py::detail::const_name("List[List[int]]");
};
using IntArg = Arg<IntTag>;
using TextArg = Arg<TextTag>;
using FlagArg = Arg<FlagTag>;
using CyclesArg = Arg<CyclesTag>;

// ---- Showing Python values and errors in messages (args.cpp). Never raises.
// A short one-line printable repr of o ("[1, 2, 3, ...]", "<R object>").
[[nodiscard]] std::string shown(py::handle o);
// The Python error being raised, as "ZeroDivisionError: boom" on one line,
// cleared. An exception that is not an Exception (KeyboardInterrupt,
// SystemExit) is not about the input: it is thrown on as it is.
[[nodiscard]] std::string take_error();
// " (ZeroDivisionError: boom)" for the error being raised, cleared; "" for a
// TypeError, which the caller's "expected ..., found ..." already says.
[[nodiscard]] std::string take_error_suffix();

// ---- Scalar arguments (args.cpp). `what` names the argument in messages
// ("cycle: half-edge"). A value of the wrong type is a one-line TypeError; a
// value out of range, InvalidInput.
// An id argument's exact int, as its __index__ gives it. Python code runs
// here, and may even edit the DCEL: convert every argument before reading
// the DCEL it is checked against.
[[nodiscard]] py::object id_value(const IntArg& id, std::string_view what);
// That id, when below count (bad-index InvalidInput when not).
[[nodiscard]] Index id_below(const py::object& id, std::size_t count, std::string_view what);
// A count from 0 to max.
[[nodiscard]] std::size_t count_from(const IntArg& n, std::size_t max, std::string_view what);
// An integer from min to max.
[[nodiscard]] std::int64_t int_from(const IntArg& n, std::int64_t min, std::int64_t max, std::string_view what);
// An unsigned 64-bit seed.
[[nodiscard]] std::uint64_t seed_from(const IntArg& seed, std::string_view what);
// True or False (also numpy.bool_, None and numbers, as pybind11 accepts).
[[nodiscard]] bool flag_from(const FlagArg& flag, std::string_view what);
// Text as UTF-8: a str (a lone surrogate, which UTF-8 cannot encode, is
// InvalidInput naming where it is), or bytes as they are.
[[nodiscard]] std::string text_from(const TextArg& text, std::string_view what);

// ---- Inputs (inputs.cpp). Every failure is InvalidInput with a message that
// names the place ("vertices[3]: ...", "edges[2][1]: ...").

// vertices: (x, y) pairs in a list, tuple or other sequence, or an (n, 2)
// array (or anything numpy reads as an array without reading Python lists);
// edges: (u, v) pairs of integers likewise (integral floats are accepted, as
// the JSON reader accepts 1.0). Copied once into the graph.
[[nodiscard]] PlanarGraph graph_from(py::handle vertices, py::handle edges);
// A graph argument: a Graph (or any pair (vertices, edges)) or a mapping with
// "vertices" and "edges".
[[nodiscard]] PlanarGraph graph_from(py::handle graph);
// Points as vertices above; `what` names them in errors ("locate_many: points").
[[nodiscard]] std::vector<Point> points_from(py::handle points, std::string_view what);
// A point (x, y); `what` names it in errors ("split_edge: point").
[[nodiscard]] Point point_from(py::handle p, std::string_view what);
// A list of lists of ids (svg's highlight cycles).
[[nodiscard]] std::vector<std::vector<Index>> cycles_from(const CyclesArg& cycles, std::string_view what);

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
// A message from the library or this binding as a str. They are UTF-8 (user
// text in them is escaped); a stray invalid byte is shown as \xNN rather
// than failing the conversion.
[[nodiscard]] py::str message_str(std::string_view message);

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

namespace pybind11::detail {

// The casters of the Arg wrappers above: every object is accepted here.
template <class Tag>
struct type_caster<dcel::python::Arg<Tag>> {
    PYBIND11_TYPE_CASTER(dcel::python::Arg<Tag>, Tag::name);
    bool load(handle src, bool /*convert*/) {
        value.value = reinterpret_borrow<object>(src);
        return true;
    }
};

}  // namespace pybind11::detail
