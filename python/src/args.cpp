// Scalar arguments in (ids, counts, seeds, flags, text) and how a Python
// value or a Python error is shown in a message: on one line, printable,
// short, whatever the value's __repr__ or the error's __str__ does.
#include <cstdio>
#include <limits>
#include <optional>

#include "binding.hpp"
#include "dcel/core/utf8.hpp"
#include "dcel/error.hpp"

namespace dcel::python {
namespace {

constexpr std::size_t kShownChars = 60;     // of a value's repr
constexpr std::size_t kReasonChars = 200;   // of an error's message
constexpr std::size_t kLargeIntBits = 128;  // longer ints are shown by their size

// Python's escape of an unprintable character: \n, \x1b, \ud800, \U000e0001.
std::string escape(Py_UCS4 c) {
    switch (c) {
        case '\n': return "\\n";
        case '\r': return "\\r";
        case '\t': return "\\t";
        default: break;
    }
    char buf[16];
    if (c < 0x100) {
        std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(c));
    } else if (c < 0x10000) {
        std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
    } else {
        std::snprintf(buf, sizeof buf, "\\U%08x", static_cast<unsigned>(c));
    }
    return buf;
}

// A str as UTF-8 on one printable line: what str.isprintable() refuses
// (newlines, control characters, lone surrogates, which UTF-8 cannot hold)
// written as Python writes it in a repr, the rest as it is; cut after
// max_chars characters, with "...".
std::string printable(PyObject* s, std::size_t max_chars) {
    const Py_ssize_t n = PyUnicode_GET_LENGTH(s);
    std::string out;
    for (Py_ssize_t i = 0; i < n; ++i) {
        if (static_cast<std::size_t>(i) == max_chars) return out + "...";
        const Py_UCS4 c = PyUnicode_READ_CHAR(s, i);
        if (Py_UNICODE_ISPRINTABLE(c)) {
            detail::append_utf8(out, c);
        } else {
            out += escape(c);
        }
    }
    return out;
}

std::string type_name(PyObject* type) {
    const std::string name = reinterpret_cast<PyTypeObject*>(type)->tp_name;
    return name.substr(name.rfind('.') + 1);  // "numpy.AxisError" -> "AxisError"
}

// An int's length in bits (int.bit_length, which a subclass cannot override here).
std::size_t bit_length(py::handle i) {
    const py::object bits = py::handle(reinterpret_cast<PyObject*>(&PyLong_Type)).attr("bit_length")(i);
    return bits.cast<std::size_t>();
}

// The exact int a value stands for (its __index__), or the TypeError that
// says it is not an integer, on one line.
py::object exact_int(py::handle value, std::string_view what, std::string_view expected) {
    PyObject* index = PyNumber_Index(value.ptr());
    if (index == nullptr) {
        const std::string suffix = take_error_suffix();
        throw py::type_error(std::string(what) + ": expected " + std::string(expected) + ", found " + shown(value) + suffix);
    }
    return py::reinterpret_steal<py::object>(index);
}

// The value of an exact int in [min, max], or nullopt.
std::optional<long long> in_range(const py::object& i, long long min, long long max) {
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
    if (overflow != 0 || v < min || v > max) return std::nullopt;
    return v;
}

}  // namespace

std::string shown(py::handle o) {
    if (PyLong_Check(o.ptr()) && !PyBool_Check(o.ptr())) {
        // repr() refuses ints of more than 4300 digits, and a long one says little.
        if (const std::size_t bits = bit_length(o); bits > kLargeIntBits) {
            return "an int of " + std::to_string(bits) + " bits";
        }
    }
    PyObject* r = PyObject_CallOneArg(imported().short_repr.ptr(), o.ptr());
    if (r != nullptr && PyUnicode_Check(r)) {
        const py::object keep = py::reinterpret_steal<py::object>(r);
        return printable(r, kShownChars);
    }
    Py_XDECREF(r);
    if (r == nullptr) static_cast<void>(take_error());
    const py::str name = py::reinterpret_steal<py::str>(PyUnicode_FromString(Py_TYPE(o.ptr())->tp_name));
    return "<" + printable(name.ptr(), kShownChars) + " object>";
}

std::string take_error() {
    py::error_already_set e;
    if (!e.matches(PyExc_Exception)) throw e;
    std::string out = type_name(e.type().ptr());
    PyObject* message = PyObject_Str(e.value().ptr());
    if (message == nullptr) {
        PyErr_Clear();  // a __str__ that raises: the type says enough
        return out;
    }
    const py::object keep = py::reinterpret_steal<py::object>(message);
    if (PyUnicode_Check(message) && PyUnicode_GET_LENGTH(message) > 0) out += ": " + printable(message, kReasonChars);
    return out;
}

std::string take_error_suffix() {
    if (PyErr_ExceptionMatches(PyExc_TypeError) != 0) {
        PyErr_Clear();
        return "";
    }
    return " (" + take_error() + ")";
}

py::object id_value(const IntArg& id, std::string_view what) { return exact_int(id.value, what, "an integer id"); }

Index id_below(const py::object& id, std::size_t count, std::string_view what) {
    const auto v = in_range(id, 0, static_cast<long long>(count) - 1);
    if (!v) {
        throw InvalidInput(InputErrorKind::BadIndex, std::string(what) + " " + shown(id) +
                                                         " does not exist (ids count from 0; there are " +
                                                         std::to_string(count) + ")");
    }
    return static_cast<Index>(*v);
}

std::size_t count_from(const IntArg& n, std::size_t max, std::string_view what) {
    const py::object i = exact_int(n.value, what, "an integer");
    const auto v = in_range(i, 0, static_cast<long long>(max));
    if (!v) {
        throw InvalidInput(InputErrorKind::TooLarge,
                           std::string(what) + " " + shown(i) + " is not from 0 to " + std::to_string(max));
    }
    return static_cast<std::size_t>(*v);
}

std::int64_t int_from(const IntArg& n, std::int64_t min, std::int64_t max, std::string_view what) {
    const py::object i = exact_int(n.value, what, "an integer");
    const auto v = in_range(i, min, max);
    if (!v) {
        throw InvalidInput(InputErrorKind::BadIndex, std::string(what) + " " + shown(i) + " is not from " +
                                                         std::to_string(min) + " to " + std::to_string(max));
    }
    return *v;
}

std::uint64_t seed_from(const IntArg& seed, std::string_view what) {
    const py::object i = exact_int(seed.value, what, "an integer");
    const unsigned long long v = PyLong_AsUnsignedLongLong(i.ptr());  // fails for negative and too large
    if (PyErr_Occurred() != nullptr) {
        PyErr_Clear();
        throw InvalidInput(InputErrorKind::BadIndex,
                           std::string(what) + " " + shown(i) + " is not an unsigned 64-bit integer");
    }
    return v;
}

bool flag_from(const FlagArg& flag, std::string_view what) {
    PyObject* o = flag.value.ptr();
    if (o == Py_True) return true;
    if (o == Py_False || o == Py_None) return false;
    // numpy.bool_ and numbers (pybind11's own conversion accepts those with __bool__ in C).
    const PyNumberMethods* number = Py_TYPE(o)->tp_as_number;
    if (number != nullptr && number->nb_bool != nullptr) {
        const int truth = PyObject_IsTrue(o);
        if (truth >= 0) return truth != 0;
        const std::string suffix = take_error_suffix();
        throw py::type_error(std::string(what) + ": expected True or False, found " + shown(o) + suffix);
    }
    throw py::type_error(std::string(what) + ": expected True or False, found " + shown(o));
}

std::string text_from(const TextArg& text, std::string_view what) {
    PyObject* o = text.value.ptr();
    if (PyBytes_Check(o)) return {PyBytes_AS_STRING(o), static_cast<std::size_t>(PyBytes_GET_SIZE(o))};
    if (PyByteArray_Check(o)) return {PyByteArray_AS_STRING(o), static_cast<std::size_t>(PyByteArray_GET_SIZE(o))};
    if (!PyUnicode_Check(o)) throw py::type_error(std::string(what) + ": expected a str, found " + shown(o));
    Py_ssize_t size = 0;
    if (const char* utf8 = PyUnicode_AsUTF8AndSize(o, &size)) return {utf8, static_cast<std::size_t>(size)};
    PyErr_Clear();  // only a lone surrogate (U+D800-U+DFFF) makes a str unencodable
    const Py_ssize_t n = PyUnicode_GET_LENGTH(o);
    std::size_t line = 1;
    std::size_t column = 1;
    for (Py_ssize_t i = 0; i < n; ++i) {
        const Py_UCS4 c = PyUnicode_READ_CHAR(o, i);
        if (c >= 0xD800 && c <= 0xDFFF) {
            const std::string where = "line " + std::to_string(line) + ", column " + std::to_string(column);
            const std::string prefix = what.empty() ? where : std::string(what) + ": " + where;
            throw InvalidInput(InputErrorKind::Syntax, prefix + ": lone surrogate '" + escape(c) +
                                                           "' in a str: it is not a character, and UTF-8 cannot encode it");
        }
        if (c == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    throw InvalidInput(InputErrorKind::Syntax, std::string(what) + ": the str cannot be encoded as UTF-8");
}

py::str message_str(std::string_view message) {
    PyObject* s = PyUnicode_DecodeUTF8(message.data(), static_cast<Py_ssize_t>(message.size()), "backslashreplace");
    if (s == nullptr) throw py::error_already_set();
    return py::reinterpret_steal<py::str>(s);
}

}  // namespace dcel::python
