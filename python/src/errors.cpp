// The library's exceptions as Python exceptions of dcel._types:
// InvalidInput (a ValueError with kind, vertices and edges) and TopologyError
// (a ValueError naming the ids its message names).
#include <pybind11/stl.h>

#include "binding.hpp"
#include "dcel/error.hpp"

namespace dcel::python {
namespace {

template <class Id>
py::list indexes(const std::vector<Id>& ids) {
    py::list out;
    for (const Id id : ids) out.append(id.index());
    return out;
}

void raise(py::handle cls, const py::object& instance) { PyErr_SetObject(cls.ptr(), instance.ptr()); }

}  // namespace

void register_errors(py::module_& /*m*/) {
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InvalidInput& e) {
            const py::handle cls = value_type("InvalidInput");
            raise(cls, cls(message_str(e.what()), to_string(e.kind()), indexes(e.vertices()), indexes(e.edges())));
        } catch (const TopologyError& e) {
            const py::handle cls = value_type("TopologyError");
            raise(cls, cls(message_str(e.what())));
        } catch (const EditRefused& e) {
            const py::handle cls = value_type("TopologyError");
            raise(cls, cls(message_str(e.message), py::cast(e.vertices), py::cast(e.edges)));
        }
    });
}

}  // namespace dcel::python
