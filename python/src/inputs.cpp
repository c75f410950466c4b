// Python values in: graphs, points and ids. Lists and tuples of pairs are
// read here, element by element (numpy's reading of nested lists costs about
// 1 s per 4e6 pairs, several times this); anything else (arrays of any
// numeric dtype, sequences of arrays) is read by numpy. What numpy accepts
// but a graph must not have (fractional or negative indexes, the wrong
// shape) is refused with the place named, in the JSON reader's words.
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "binding.hpp"
#include "dcel/error.hpp"

namespace dcel::python {
namespace {

constexpr Index kMaxIndex = kNoIndex - 1;  // the null id is reserved

[[noreturn]] void fail(InputErrorKind kind, const std::string& message, std::vector<EdgeId> edges = {}) {
    throw InvalidInput(kind, message, {}, std::move(edges));
}

std::string shape_of(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) {
        if (i > 0) s += ", ";
        s += std::to_string(a.shape(i));
    }
    return s + (a.ndim() == 1 ? ",)" : ")");
}

// numpy's reading of `value` as an array of `dtype` (nullptr: its own choice),
// or InvalidInput(Shape) carrying numpy's complaint.
py::array as_array(py::handle value, const char* dtype, std::string_view what) {
    try {
        if (dtype == nullptr) return imported().asarray(value);
        return imported().ascontiguousarray(value, py::arg("dtype") = dtype);
    } catch (const py::error_already_set& e) {
        // numpy says e.g. "could not convert string to float: 'a'".
        fail(InputErrorKind::Shape, std::string(what) + ": " + py::str(e.value()).cast<std::string>());
    }
}

bool empty(const py::array& a) { return a.size() == 0; }

bool is_list_or_tuple(PyObject* o) { return PyList_Check(o) || PyTuple_Check(o); }

std::string repr_of(PyObject* o) {
    std::string s = py::repr(py::handle(o)).cast<std::string>();
    return s.size() > 60 ? s.substr(0, 60) + "..." : s;
}

// Is every element of seq a list or tuple of two? A list or tuple of another
// length is refused here; false for an element of another type (numpy then
// reads the whole sequence).
bool all_pairs(PyObject* seq, const char* what, const char* expected) {
    const Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
    for (Py_ssize_t i = 0; i < n; ++i) {
        PyObject* item = PySequence_Fast_GET_ITEM(seq, i);
        if (!is_list_or_tuple(item)) return false;
        if (PySequence_Fast_GET_SIZE(item) != 2) {
            fail(InputErrorKind::Shape,
                 std::string(what) + "[" + std::to_string(i) + "]: expected " + expected + ", found " + repr_of(item));
        }
    }
    return true;
}

// The points of a list or tuple of pairs; nullopt for anything else (numpy reads it).
std::optional<std::vector<Point>> points_from_pairs(py::handle vertices) {
    PyObject* seq = vertices.ptr();
    if (!is_list_or_tuple(seq)) return std::nullopt;
    const Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
    if (!all_pairs(seq, "vertices", "a point (x, y)")) return std::nullopt;
    if (static_cast<std::uint64_t>(n) > kMaxIndex)
        fail(InputErrorKind::TooLarge, "vertices: more points than 32-bit ids can name");
    std::vector<Point> out(static_cast<std::size_t>(n));
    for (Py_ssize_t i = 0; i < n; ++i) {
        PyObject* pair = PySequence_Fast_GET_ITEM(seq, i);
        double xy[2];
        for (int c = 0; c < 2; ++c) {
            PyObject* value = PySequence_Fast_GET_ITEM(pair, c);
            xy[c] = PyFloat_AsDouble(value);
            if (xy[c] == -1.0 && PyErr_Occurred() != nullptr) {
                PyErr_Clear();
                fail(InputErrorKind::Shape, "vertices[" + std::to_string(i) + "][" + std::to_string(c) +
                                                "]: expected a number, found " + repr_of(value));
            }
        }
        out[static_cast<std::size_t>(i)] = {xy[0], xy[1]};
    }
    return out;
}

std::vector<Point> points_from(py::handle vertices) {
    if (auto pairs = points_from_pairs(vertices)) return std::move(*pairs);
    const py::array a = as_array(vertices, "float64", "vertices");
    if (empty(a)) return {};
    if (a.ndim() != 2 || a.shape(1) != 2) {
        fail(InputErrorKind::Shape,
             "vertices: expected points (x, y), an array of shape (n, 2), found shape " + shape_of(a));
    }
    if (static_cast<std::uint64_t>(a.shape(0)) > kMaxIndex) {
        fail(InputErrorKind::TooLarge, "vertices: more points than 32-bit ids can name");
    }
    std::vector<Point> out(static_cast<std::size_t>(a.shape(0)));
    std::memcpy(out.data(), a.data(), out.size() * sizeof(Point));  // C-contiguous float64 pairs
    return out;
}

[[noreturn]] void bad_index(std::size_t k, int side, const std::string& what) {
    fail(InputErrorKind::BadIndex, "edges[" + std::to_string(k) + "][" + std::to_string(side) + "]: vertex index " + what,
         {EdgeId(static_cast<Index>(k))});
}

template <class T>
std::string shown(T v) {
    if constexpr (std::is_floating_point_v<T>) {
        return py::repr(py::float_(v)).template cast<std::string>();
    } else {
        return std::to_string(v);
    }
}

// v <= kMaxIndex, compared in a type that holds both (and false for NaN).
template <class T>
bool fits_an_index(T v) {
    if constexpr (std::is_floating_point_v<T>) {
        return v <= static_cast<double>(kMaxIndex);
    } else if constexpr (std::is_signed_v<T>) {
        return static_cast<std::int64_t>(v) <= static_cast<std::int64_t>(kMaxIndex);
    } else {
        return static_cast<std::uint64_t>(v) <= kMaxIndex;
    }
}

// Edge k's pair from a C-contiguous (m, 2) array of T.
template <class T>
void read_edges(const py::array& a, std::vector<GraphEdge>& out) {
    const T* data = static_cast<const T*>(a.data());
    for (std::size_t k = 0; k < out.size(); ++k) {
        Index ends[2];
        for (int side = 0; side < 2; ++side) {
            const T v = data[2 * k + static_cast<std::size_t>(side)];
            if constexpr (std::is_floating_point_v<T>) {
                if (!(std::trunc(v) == v)) bad_index(k, side, shown(v) + " is not an integer");
            }
            if constexpr (std::is_signed_v<T>) {
                if (v < 0) bad_index(k, side, shown(v) + " is negative: ids count from 0");
            }
            if (!fits_an_index(v)) {
                bad_index(k, side, shown(v) + " is too large: ids are 32-bit, the largest is " + std::to_string(kMaxIndex));
            }
            ends[side] = static_cast<Index>(v);
        }
        out[k] = {VertexId(ends[0]), VertexId(ends[1])};
    }
}

// An index of a list edge: an int (or anything with __index__, such as a
// numpy integer) or an integral float, as in the arrays.
Index index_of(PyObject* value, std::size_t k, int side) {
    if (PyFloat_Check(value)) {
        const double v = PyFloat_AS_DOUBLE(value);
        if (!(std::trunc(v) == v)) bad_index(k, side, shown(v) + " is not an integer");
        if (v < 0) bad_index(k, side, shown(v) + " is negative: ids count from 0");
        if (!(v <= static_cast<double>(kMaxIndex)))
            bad_index(k, side, shown(v) + " is too large: ids are 32-bit, the largest is " + std::to_string(kMaxIndex));
        return static_cast<Index>(v);
    }
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value));
    if (!index) {
        PyErr_Clear();
        bad_index(k, side, repr_of(value) + " is not an integer");
    }
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    if (overflow < 0 || (overflow == 0 && v < 0))
        bad_index(k, side, repr_of(index.ptr()) + " is negative: ids count from 0");
    if (overflow > 0 || v > static_cast<long long>(kMaxIndex)) {
        bad_index(k, side,
                  repr_of(index.ptr()) + " is too large: ids are 32-bit, the largest is " + std::to_string(kMaxIndex));
    }
    return static_cast<Index>(v);
}

// The edges of a list or tuple of pairs; nullopt for anything else (numpy reads it).
std::optional<std::vector<GraphEdge>> edges_from_pairs(py::handle edges) {
    PyObject* seq = edges.ptr();
    if (!is_list_or_tuple(seq)) return std::nullopt;
    const Py_ssize_t m = PySequence_Fast_GET_SIZE(seq);
    if (!all_pairs(seq, "edges", "a pair of vertex indexes (u, v)")) return std::nullopt;
    if (static_cast<std::uint64_t>(m) > kMaxIndex / 2)
        fail(InputErrorKind::TooLarge, "edges: more edges than 32-bit half-edge ids can name");
    std::vector<GraphEdge> out(static_cast<std::size_t>(m));
    for (Py_ssize_t k = 0; k < m; ++k) {
        PyObject* pair = PySequence_Fast_GET_ITEM(seq, k);
        const auto kk = static_cast<std::size_t>(k);
        out[kk] = {VertexId(index_of(PySequence_Fast_GET_ITEM(pair, 0), kk, 0)),
                   VertexId(index_of(PySequence_Fast_GET_ITEM(pair, 1), kk, 1))};
    }
    return out;
}

std::vector<GraphEdge> edges_from(py::handle edges) {
    if (auto pairs = edges_from_pairs(edges)) return std::move(*pairs);
    py::array a = as_array(edges, nullptr, "edges");
    if (empty(a)) return {};
    if (a.ndim() != 2 || a.shape(1) != 2) {
        fail(InputErrorKind::Shape, "edges: expected pairs (u, v), an array of shape (m, 2), found shape " + shape_of(a));
    }
    if (static_cast<std::uint64_t>(a.shape(0)) > kMaxIndex / 2) {
        fail(InputErrorKind::TooLarge, "edges: more edges than 32-bit half-edge ids can name");
    }
    std::vector<GraphEdge> out(static_cast<std::size_t>(a.shape(0)));
    const char kind = a.dtype().kind();
    const py::handle contiguous = imported().ascontiguousarray;
    // Read the common dtypes in place; convert the rest once.
    if (kind == 'i') {
        if (a.dtype().itemsize() == 4) {
            read_edges<std::int32_t>(contiguous(a), out);
        } else {
            read_edges<std::int64_t>(contiguous(a, py::arg("dtype") = "int64"), out);
        }
    } else if (kind == 'u') {
        if (a.dtype().itemsize() == 4) {
            read_edges<std::uint32_t>(contiguous(a), out);
        } else {
            read_edges<std::uint64_t>(contiguous(a, py::arg("dtype") = "uint64"), out);
        }
    } else if (kind == 'f') {
        read_edges<double>(contiguous(a, py::arg("dtype") = "float64"), out);
    } else {
        fail(InputErrorKind::Shape, "edges: expected pairs of vertex indexes (integers), found numpy dtype " +
                                        py::str(a.dtype()).cast<std::string>());
    }
    return out;
}

}  // namespace

PlanarGraph graph_from(py::handle vertices, py::handle edges) {
    PlanarGraph g;
    g.vertices = points_from(vertices);
    g.edges = edges_from(edges);
    return g;
}

PlanarGraph graph_from(py::handle graph) {
    if (PyMapping_Check(graph.ptr()) != 0 && !py::isinstance<py::tuple>(graph) && !py::isinstance<py::list>(graph)) {
        const py::object m = py::reinterpret_borrow<py::object>(graph);
        if (!py::bool_(m.attr("__contains__")("vertices")) || !py::bool_(m.attr("__contains__")("edges"))) {
            fail(InputErrorKind::Shape, "graph: a mapping needs the keys \"vertices\" and \"edges\"");
        }
        return graph_from(m["vertices"], m["edges"]);
    }
    if (py::isinstance<py::sequence>(graph) && py::len(graph) == 2) {
        const py::sequence s = py::reinterpret_borrow<py::sequence>(graph);
        return graph_from(s[0], s[1]);
    }
    fail(InputErrorKind::Shape,
         "graph: expected a Graph, a pair (vertices, edges) or a mapping with \"vertices\" and "
         "\"edges\", found " +
             py::repr(graph).cast<std::string>().substr(0, 80));
}

Point point_from(py::handle p, std::string_view what) {
    const py::array a = as_array(p, "float64", what);
    if (a.ndim() != 1 || a.shape(0) != 2) {
        fail(InputErrorKind::Shape, std::string(what) + ": expected a point (x, y), found shape " + shape_of(a));
    }
    const auto* xy = static_cast<const double*>(a.data());
    const Point out{xy[0], xy[1]};
    if (!std::isfinite(out.x) || !std::isfinite(out.y)) {
        fail(InputErrorKind::BadCoordinate,
             std::string(what) + ": coordinates must be finite, found " + py::repr(p).cast<std::string>());
    }
    return out;
}

Index id_below(std::int64_t id, std::size_t count, std::string_view what) {
    if (id < 0 || static_cast<std::uint64_t>(id) >= count) {
        throw InvalidInput(InputErrorKind::BadIndex, std::string(what) + " " + std::to_string(id) +
                                                         " does not exist (ids count from 0; there are " +
                                                         std::to_string(count) + ")");
    }
    return static_cast<Index>(id);
}

py::object graph_to_python(const PlanarGraph& g) {
    py::list vertices(g.vertices.size());
    for (std::size_t i = 0; i < g.vertices.size(); ++i) vertices[i] = py::make_tuple(g.vertices[i].x, g.vertices[i].y);
    py::list edges(g.edges.size());
    for (std::size_t i = 0; i < g.edges.size(); ++i) edges[i] = py::make_tuple(g.edges[i].u.index(), g.edges[i].v.index());
    return value_type("Graph")(vertices, edges);
}

py::object id_or_none(Index id) { return id == kNoIndex ? py::object(py::none()) : py::object(py::int_(id)); }

}  // namespace dcel::python
