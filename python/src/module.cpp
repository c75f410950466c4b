// dcel._dcel: the C++ half of the Python package dcel (python/dcel/).
// The package's __init__ imports it and adds check(), validate() and the
// value types (python/dcel/_types.py, which these functions create by name).
#include "binding.hpp"

PYBIND11_MODULE(_dcel, m) {
    m.doc() = "The exact reference DCEL of planar straight-line graphs (the C++ library dcel, bound).";
    m.attr("NULL") = dcel::kNoIndex;
    // First: nothing may be looked up lazily later (imports.cpp says why).
    dcel::python::prepare_imports();
    dcel::python::register_errors(m);
    dcel::python::bind_dcel(m);
    dcel::python::bind_check(m);
    dcel::python::bind_gen(m);
}
