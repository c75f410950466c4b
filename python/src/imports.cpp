// Everything the binding looks up in Python, looked up once, at import
// (PYBIND11_MODULE in module.cpp), and never lazily afterwards.
//
// Why at import: a lazy first-use initialisation can deadlock two threads.
// pybind11 (2.10) initialises its numpy support in a C++ function-local
// static on first use; that initialisation imports numpy, which runs Python
// code, which lets another thread take the GIL; when that thread reaches the
// same static it waits for the first one to finish, holding the GIL the
// first one needs. Two threads making their first calls at once hung so. At
// import, Python's import lock orders everything, and nothing afterwards
// waits on a C++ lock while holding the GIL.
#include <array>
#include <cstring>
#include <stdexcept>

#include "binding.hpp"

namespace dcel::python {
namespace {

// The names value_type() knows: every class of dcel._types the binding makes.
constexpr std::array kValueTypes{"Area",     "Change",    "Difference",   "Face",          "Graph",    "IdChange",
                                 "Location", "StabPiece", "InvalidInput", "TopologyError", "Violation"};

// Strong references, deliberately never released: they live as long as the
// interpreter, and the destructor of a static py::object would run after the
// interpreter is finalised.
std::array<py::handle, kValueTypes.size()> value_types;
Imported imports;

py::handle keep(py::object o) { return o.release(); }

}  // namespace

void prepare_imports() {
    const py::module_ numpy = py::module_::import("numpy");
    // pybind11's numpy C API table (the lazily initialised static above).
    static_cast<void>(py::detail::npy_api::get());
    imports.asarray = keep(numpy.attr("asarray"));
    imports.ascontiguousarray = keep(numpy.attr("ascontiguousarray"));
    imports.ndarray_tolist = keep(numpy.attr("ndarray").attr("tolist"));
    imports.json_loads = keep(py::module_::import("json").attr("loads"));
    imports.mapping = keep(py::module_::import("collections.abc").attr("Mapping"));
    // Small limits, so that a message never shows (or takes the time to
    // write) more than a few items of a huge or deeply nested value.
    py::object repr = py::module_::import("reprlib").attr("Repr")();
    repr.attr("maxlevel") = 3;
    repr.attr("maxstring") = 40;
    repr.attr("maxlong") = 40;
    repr.attr("maxother") = 40;
    imports.short_repr = keep(repr.attr("repr"));
    // dcel/__init__.py imports dcel._types before this extension.
    const py::module_ types = py::module_::import("dcel._types");
    for (std::size_t i = 0; i < kValueTypes.size(); ++i) value_types[i] = keep(types.attr(kValueTypes[i]));
}

const Imported& imported() { return imports; }

py::handle value_type(const char* name) {
    for (std::size_t i = 0; i < kValueTypes.size(); ++i) {
        if (std::strcmp(kValueTypes[i], name) == 0) return value_types[i];
    }
    throw std::logic_error(std::string("dcel._dcel: value_type(\"") + name + "\") is not in kValueTypes");
}

}  // namespace dcel::python
