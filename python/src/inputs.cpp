// Python values in: graphs, points and lists of ids.
//
// Lists, tuples and other sequences are read here, element by element
// (numpy's reading of nested lists costs about 1 s per 4e6 pairs, several
// times this); numpy reads only arrays and array-likes (buffers, __array__),
// never a Python list. What numpy accepts but a graph must not have
// (fractional or negative indexes, the wrong shape) is refused with the
// place named, in the JSON reader's words.
//
// Hostile values: a coordinate's __float__ or an id's __index__ is Python
// code, which may change the list being read (clear it, shrink it, replace
// its items) and so free the very item being converted. Every sequence is
// therefore read from a tuple that holds its items (a snapshot), and a
// pair's two items are held before either is converted. numpy (1.24) reads
// nested lists through borrowed pointers and crashes when a __float__
// clears one: that is why no list goes to numpy.
#include <array>
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

// Where a value is, for messages: "vertices", "vertices[3]", "vertices[3][0]".
// Written out only for a message.
struct Place {
    std::string_view what;
    std::size_t i = npos;
    std::size_t j = npos;

    static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

    [[nodiscard]] std::string str() const {
        std::string s(what);
        if (i != npos) s += "[" + std::to_string(i) + "]";
        if (j != npos) s += "[" + std::to_string(j) + "]";
        return s;
    }
    [[nodiscard]] Place operator[](std::size_t k) const { return i == npos ? Place{what, k} : Place{what, i, k}; }
};

// The error being raised, as InvalidInput at `place` ("vertices[3]: IndexError: ...").
[[noreturn]] void fail_with_error(const Place& place) {
    const std::string reason = take_error();
    fail(InputErrorKind::Shape, place.str() + ": " + reason);
}

std::string shape_of(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) {
        if (i > 0) s += ", ";
        s += std::to_string(a.shape(i));
    }
    return s + (a.ndim() == 1 ? ",)" : ")");
}

bool is_text(PyObject* o) { return PyUnicode_Check(o) || PyBytes_Check(o) || PyByteArray_Check(o); }

py::object call(py::handle f, py::handle arg, const Place& place) {
    PyObject* r = PyObject_CallOneArg(f.ptr(), arg.ptr());
    if (r == nullptr) fail_with_error(place);
    return py::reinterpret_steal<py::object>(r);
}

// numpy's reading of an array (or array-like) as an array of `dtype`, C-contiguous.
py::array as_array(py::handle value, const char* dtype, const Place& place) {
    PyObject* r = PyObject_Call(imported().ascontiguousarray.ptr(), py::make_tuple(value).ptr(),
                                py::dict(py::arg("dtype") = dtype).ptr());
    // numpy says e.g. "could not convert string to float: 'a'".
    if (r == nullptr) fail(InputErrorKind::Shape, place.str() + ": " + take_error());
    return py::reinterpret_steal<py::array>(r);
}

// o as an ndarray, when it is one or numpy can read it as one without
// reading a Python list (the buffer protocol, __array__,
// __array_interface__, __array_struct__); nullopt for anything else.
std::optional<py::array> array_like(py::handle o, const Place& place) {
    PyObject* p = o.ptr();
    if (py::isinstance<py::array>(o)) return py::reinterpret_borrow<py::array>(o);
    if (PyList_Check(p) || PyTuple_Check(p) || is_text(p)) return std::nullopt;
    if (PyObject_CheckBuffer(p) == 0 && PyObject_HasAttrString(p, "__array__") == 0 &&
        PyObject_HasAttrString(p, "__array_interface__") == 0 && PyObject_HasAttrString(p, "__array_struct__") == 0) {
        return std::nullopt;
    }
    const py::object a = call(imported().asarray, o, place);
    if (!py::isinstance<py::array>(a)) fail(InputErrorKind::Shape, place.str() + ": numpy.asarray gave no array");
    return py::reinterpret_borrow<py::array>(a);
}

py::tuple tuple_of(PyObject* t, const Place& place) {
    if (t == nullptr) fail_with_error(place);
    return py::reinterpret_steal<py::tuple>(t);
}

// The items of a list, tuple or other sequence (not a str, bytes or dict),
// held by a tuple that the reading cannot change; nullopt for anything
// else. A list or tuple is copied as it is, without calling methods a
// subclass may override (as PySequence_Fast reads it); another sequence is
// read by len() and indexing, as far as len() says.
std::optional<py::tuple> items_of(py::handle o, const Place& place) {
    PyObject* p = o.ptr();
    if (PyList_Check(p)) return tuple_of(PyList_AsTuple(p), place);
    if (PyTuple_Check(p)) return tuple_of(PyTuple_GetSlice(p, 0, PyTuple_GET_SIZE(p)), place);
    if (is_text(p) || PyDict_Check(p) || PySequence_Check(p) == 0) return std::nullopt;
    const Py_ssize_t n = PySequence_Size(p);
    if (n < 0) fail_with_error(place);
    if (static_cast<std::uint64_t>(n) > kMaxIndex) {
        fail(InputErrorKind::TooLarge, place.str() + ": len() is " + std::to_string(n) + ", more than 32-bit ids can name");
    }
    py::tuple out(n);
    for (Py_ssize_t i = 0; i < n; ++i) {
        PyObject* item = PySequence_GetItem(p, i);
        if (item == nullptr) fail_with_error(place[static_cast<std::size_t>(i)]);
        PyTuple_SET_ITEM(out.ptr(), i, item);  // steals the new reference
    }
    return out;
}

// The items of an array (by tolist(): Python values in a new list) or of a sequence.
std::optional<py::tuple> sequence_items(py::handle o, const Place& place) {
    if (const auto a = array_like(o, place)) return items_of(call(imported().ndarray_tolist, *a, place), place);
    return items_of(o, place);
}

using Pair = std::array<py::object, 2>;

// The two items of a pair, held before either is converted: a list or tuple
// of two, an array of shape (2,), another sequence of length two; nullopt
// for anything else.
std::optional<Pair> pair_of(py::handle item, const Place& place) {
    PyObject* p = item.ptr();
    if (PyList_Check(p) || PyTuple_Check(p)) {
        // Nothing runs between the size check and the new references.
        if (PySequence_Fast_GET_SIZE(p) != 2) return std::nullopt;
        return Pair{py::reinterpret_borrow<py::object>(PySequence_Fast_GET_ITEM(p, 0)),
                    py::reinterpret_borrow<py::object>(PySequence_Fast_GET_ITEM(p, 1))};
    }
    if (is_text(p) || PyDict_Check(p)) return std::nullopt;
    if (const auto a = array_like(item, place)) return pair_of(call(imported().ndarray_tolist, *a, place), place);
    if (PySequence_Check(p) == 0) return std::nullopt;
    const Py_ssize_t n = PySequence_Size(p);
    if (n < 0) fail_with_error(place);
    if (n != 2) return std::nullopt;
    Pair out;
    for (Py_ssize_t k = 0; k < 2; ++k) {
        PyObject* x = PySequence_GetItem(p, k);
        if (x == nullptr) fail_with_error(place[static_cast<std::size_t>(k)]);
        out[static_cast<std::size_t>(k)] = py::reinterpret_steal<py::object>(x);
    }
    return out;
}

double coordinate(const py::object& value, const Place& place) {
    PyObject* v = value.ptr();
    if (PyFloat_Check(v)) return PyFloat_AS_DOUBLE(v);
    const double x = PyFloat_AsDouble(v);  // __float__ or __index__: any Python code
    if (x == -1.0 && PyErr_Occurred() != nullptr) {
        const std::string suffix = take_error_suffix();
        fail(InputErrorKind::Shape, place.str() + ": expected a number, found " + shown(value) + suffix);
    }
    return x;
}

std::vector<Point> points_from_items(const py::tuple& items, const Place& place) {
    const std::size_t n = items.size();
    if (n > kMaxIndex) fail(InputErrorKind::TooLarge, place.str() + ": more points than 32-bit ids can name");
    std::vector<Point> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const py::handle item = PyTuple_GET_ITEM(items.ptr(), static_cast<Py_ssize_t>(i));
        const auto xy = pair_of(item, place[i]);
        if (!xy) fail(InputErrorKind::Shape, place[i].str() + ": expected a point (x, y), found " + shown(item));
        out[i] = {coordinate((*xy)[0], place[i][0]), coordinate((*xy)[1], place[i][1])};
    }
    return out;
}

std::vector<Point> points_from_array(const py::array& given, const Place& place) {
    if (given.dtype().kind() == 'O') {  // Python objects: read as a list, not cast by numpy
        if (const auto items = items_of(call(imported().ndarray_tolist, given, place), place)) {
            return points_from_items(*items, place);
        }
    }
    // numpy would cast complex numbers (dropping the imaginary part, with a
    // warning) and parse strings; a list of them is refused, and so is this.
    if (const char kind = given.dtype().kind(); kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f') {
        fail(InputErrorKind::Shape,
             place.str() + ": expected numbers, found numpy dtype " + py::str(given.dtype()).cast<std::string>());
    }
    const py::array a = as_array(given, "float64", place);
    if (a.size() == 0) return {};
    if (a.ndim() != 2 || a.shape(1) != 2) {
        fail(InputErrorKind::Shape,
             place.str() + ": expected points (x, y), an array of shape (n, 2), found shape " + shape_of(a));
    }
    if (static_cast<std::uint64_t>(a.shape(0)) > kMaxIndex) {
        fail(InputErrorKind::TooLarge, place.str() + ": more points than 32-bit ids can name");
    }
    std::vector<Point> out(static_cast<std::size_t>(a.shape(0)));
    std::memcpy(out.data(), a.data(), out.size() * sizeof(Point));  // C-contiguous float64 pairs
    return out;
}

constexpr std::size_t kNoEdge = Place::npos;

// `edge`: the input edge InvalidInput names, or kNoEdge.
[[noreturn]] void bad_index(const Place& place, const std::string& what, std::size_t edge) {
    std::vector<EdgeId> edges;
    if (edge != kNoEdge) edges.emplace_back(static_cast<Index>(edge));
    fail(InputErrorKind::BadIndex, place.str() + ": vertex index " + what, std::move(edges));
}

template <class T>
std::string shown_number(T v) {
    if constexpr (std::is_floating_point_v<T>) {
        return py::repr(py::float_(v)).template cast<std::string>();
    } else {
        return std::to_string(v);
    }
}

const std::string kTooLarge = " is too large: ids are 32-bit, the largest is " + std::to_string(kMaxIndex);

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

// An index given as a number of type T, of input edge `edge` (or kNoEdge).
template <class T>
Index index_of_number(T v, const Place& place, std::size_t edge) {
    if constexpr (std::is_floating_point_v<T>) {
        if (!(std::trunc(v) == v)) bad_index(place, shown_number(v) + " is not an integer", edge);
    }
    if constexpr (std::is_signed_v<T>) {
        if (v < 0) bad_index(place, shown_number(v) + " is negative: ids count from 0", edge);
    }
    if (!fits_an_index(v)) bad_index(place, shown_number(v) + kTooLarge, edge);
    return static_cast<Index>(v);
}

// Edge k's pair from a C-contiguous (m, 2) array of T.
template <class T>
void read_edges(const py::array& a, std::vector<GraphEdge>& out) {
    const T* data = static_cast<const T*>(a.data());
    for (std::size_t k = 0; k < out.size(); ++k) {
        const Place place{"edges", k};
        out[k] = {VertexId(index_of_number(data[2 * k], place[0], k)),
                  VertexId(index_of_number(data[2 * k + 1], place[1], k))};
    }
}

// An index given as a Python value: an int (or anything with __index__,
// such as a numpy integer) or an integral float, as in the arrays.
Index index_of(const py::object& value, const Place& place, std::size_t edge) {
    PyObject* v = value.ptr();
    if (PyFloat_Check(v)) return index_of_number(PyFloat_AS_DOUBLE(v), place, edge);
    PyObject* index = PyNumber_Index(v);  // __index__: any Python code
    if (index == nullptr) {
        const std::string suffix = take_error_suffix();
        bad_index(place, shown(value) + " is not an integer" + suffix, edge);
    }
    const py::object held = py::reinterpret_steal<py::object>(index);
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(index, &overflow);
    if (overflow < 0 || (overflow == 0 && i < 0)) bad_index(place, shown(held) + " is negative: ids count from 0", edge);
    if (overflow > 0 || i > static_cast<long long>(kMaxIndex)) bad_index(place, shown(held) + kTooLarge, edge);
    return static_cast<Index>(i);
}

std::vector<GraphEdge> edges_from_items(const py::tuple& items) {
    const std::size_t m = items.size();
    if (m > kMaxIndex / 2) fail(InputErrorKind::TooLarge, "edges: more edges than 32-bit half-edge ids can name");
    std::vector<GraphEdge> out(m);
    const Place edges{"edges"};
    for (std::size_t k = 0; k < m; ++k) {
        const py::handle item = PyTuple_GET_ITEM(items.ptr(), static_cast<Py_ssize_t>(k));
        const auto uv = pair_of(item, edges[k]);
        if (!uv) {
            fail(InputErrorKind::Shape, edges[k].str() + ": expected a pair of vertex indexes (u, v), found " + shown(item));
        }
        out[k] = {VertexId(index_of((*uv)[0], edges[k][0], k)), VertexId(index_of((*uv)[1], edges[k][1], k))};
    }
    return out;
}

std::vector<GraphEdge> edges_from_array(const py::array& a) {
    const Place place{"edges"};
    if (a.dtype().kind() == 'O') {  // Python objects: read as a list, not cast by numpy
        if (const auto items = items_of(call(imported().ndarray_tolist, a, place), place)) return edges_from_items(*items);
    }
    if (a.size() == 0) return {};
    if (a.ndim() != 2 || a.shape(1) != 2) {
        fail(InputErrorKind::Shape, "edges: expected pairs (u, v), an array of shape (m, 2), found shape " + shape_of(a));
    }
    if (static_cast<std::uint64_t>(a.shape(0)) > kMaxIndex / 2) {
        fail(InputErrorKind::TooLarge, "edges: more edges than 32-bit half-edge ids can name");
    }
    std::vector<GraphEdge> out(static_cast<std::size_t>(a.shape(0)));
    const char kind = a.dtype().kind();
    const bool narrow = a.dtype().itemsize() == 4;
    // Read the common dtypes in place; convert the rest once.
    if (kind == 'i') {
        narrow ? read_edges<std::int32_t>(as_array(a, "int32", place), out)
               : read_edges<std::int64_t>(as_array(a, "int64", place), out);
    } else if (kind == 'u') {
        narrow ? read_edges<std::uint32_t>(as_array(a, "uint32", place), out)
               : read_edges<std::uint64_t>(as_array(a, "uint64", place), out);
    } else if (kind == 'f') {
        read_edges<double>(as_array(a, "float64", place), out);
    } else {
        fail(InputErrorKind::Shape, "edges: expected pairs of vertex indexes (integers), found numpy dtype " +
                                        py::str(a.dtype()).cast<std::string>());
    }
    return out;
}

std::vector<GraphEdge> edges_from(py::handle edges) {
    const Place place{"edges"};
    if (const auto a = array_like(edges, place)) return edges_from_array(*a);
    if (const auto items = items_of(edges, place)) return edges_from_items(*items);
    fail(InputErrorKind::Shape,
         "edges: expected pairs (u, v): a list of pairs or an array of shape (m, 2), found " + shown(edges));
}

// graph["vertices"] of a mapping, as `key in graph` and `graph[key]` say.
py::object member(py::handle mapping, const char* key) {
    const py::str name(key);
    const int has = PySequence_Contains(mapping.ptr(), name.ptr());
    if (has < 0) fail(InputErrorKind::Shape, std::string("graph: `\"") + key + "\" in graph` failed: " + take_error());
    if (has == 0) fail(InputErrorKind::Shape, "graph: a mapping needs the keys \"vertices\" and \"edges\"");
    PyObject* value = PyObject_GetItem(mapping.ptr(), name.ptr());
    if (value == nullptr) fail(InputErrorKind::Shape, std::string("graph[\"") + key + "\"]: " + take_error());
    return py::reinterpret_steal<py::object>(value);
}

bool is_mapping(py::handle o) {
    if (PyDict_Check(o.ptr())) return true;
    const int is = PyObject_IsInstance(o.ptr(), imported().mapping.ptr());  // may run __class__ or __instancecheck__
    if (is < 0) fail(InputErrorKind::Shape, "graph: " + take_error());
    return is != 0;
}

}  // namespace

std::vector<Point> points_from(py::handle points, std::string_view what) {
    const Place place{what};
    if (const auto a = array_like(points, place)) return points_from_array(*a, place);
    if (const auto items = items_of(points, place)) return points_from_items(*items, place);
    const std::string expected = ": expected points (x, y): a list of pairs or an array of shape (n, 2), found ";
    fail(InputErrorKind::Shape, std::string(what) + expected + shown(points));
}

PlanarGraph graph_from(py::handle vertices, py::handle edges) {
    PlanarGraph g;
    g.vertices = points_from(vertices, "vertices");
    g.edges = edges_from(edges);
    return g;
}

PlanarGraph graph_from(py::handle graph) {
    if (!is_text(graph.ptr())) {
        if (is_mapping(graph)) {
            const py::object vertices = member(graph, "vertices");
            const py::object edges = member(graph, "edges");
            return graph_from(vertices, edges);
        }
        if (const auto pair = pair_of(graph, Place{"graph"})) return graph_from((*pair)[0], (*pair)[1]);
    }
    fail(InputErrorKind::Shape,
         "graph: expected a Graph, a pair (vertices, edges) or a mapping with \"vertices\" and \"edges\", found " +
             shown(graph));
}

Point point_from(py::handle p, std::string_view what) {
    const Place place{what};
    std::optional<Pair> xy;
    if (const auto a = array_like(p, place)) {
        if (a->ndim() != 1 || a->shape(0) != 2) {
            fail(InputErrorKind::Shape, std::string(what) + ": expected a point (x, y), found shape " + shape_of(*a));
        }
        xy = pair_of(*a, place);
    } else if (!is_text(p.ptr())) {
        xy = pair_of(p, place);
    }
    if (!xy) fail(InputErrorKind::Shape, std::string(what) + ": expected a point (x, y), found " + shown(p));
    const Point out{coordinate((*xy)[0], place[0]), coordinate((*xy)[1], place[1])};
    if (!std::isfinite(out.x) || !std::isfinite(out.y)) {
        fail(InputErrorKind::BadCoordinate, std::string(what) + ": coordinates must be finite, found " + shown(p));
    }
    return out;
}

std::vector<std::vector<Index>> cycles_from(const CyclesArg& cycles, std::string_view what) {
    const Place place{what};
    const auto all = sequence_items(cycles.value, place);
    if (!all) {
        throw py::type_error(std::string(what) + ": expected a list of cycles (lists of vertex ids), found " +
                             shown(cycles.value));
    }
    std::vector<std::vector<Index>> out(all->size());
    for (std::size_t c = 0; c < out.size(); ++c) {
        const py::handle cycle = PyTuple_GET_ITEM(all->ptr(), static_cast<Py_ssize_t>(c));
        const auto ids = sequence_items(cycle, place[c]);
        if (!ids) {
            fail(InputErrorKind::Shape, place[c].str() + ": expected a cycle (a list of vertex ids), found " + shown(cycle));
        }
        for (std::size_t k = 0; k < ids->size(); ++k) {
            const auto id = py::reinterpret_borrow<py::object>(PyTuple_GET_ITEM(ids->ptr(), static_cast<Py_ssize_t>(k)));
            out[c].push_back(index_of(id, place[c][k], kNoEdge));
        }
    }
    return out;
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
