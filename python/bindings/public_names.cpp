// _mdr.__all__: the public classes of the core, which the mdr package exports as they are bound.

#include <string>

#include "bindings.hpp"

namespace py = pybind11;

namespace mdr::python {

void list_public_names(py::module_& module) {
    py::list names;
    for (const auto& [name, value] : module.attr("__dict__").cast<py::dict>()) {
        if (name.cast<std::string>().rfind('_', 0) != 0) names.append(name);
    }
    module.attr("__all__") = names;
}

}  // namespace mdr::python
