// _mdr._controls(), _tangential_controls(): the registries of controls (drivers/controls.hpp) as data, for the docs.

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "mdr/drivers/controls.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace mdr::python {

void bind_control_registry(py::module_& module) {
    module.def(
        "_controls",
        [] {
            py::list rows;
            for (const drivers::ControlKind& kind : drivers::controls()) {
                py::list keys;
                for (const drivers::ControlKey& key : kind.keys) {
                    keys.append(py::dict("key"_a = key.key, "unit"_a = key.unit, "documentation"_a = key.documentation,
                                         "required"_a = key.required));
                }
                rows.append(py::dict("name"_a = kind.name, "documentation"_a = kind.documentation,
                                     "column"_a = kind.column, "keys"_a = keys, "other_keys"_a = kind.other_keys));
            }
            return rows;
        },
        "The registry of controls (name, documentation, history column, `[load]` keys with units, keys of other "
        "tables), for the docs.");
    module.def(
        "_tangential_controls",
        [] {
            py::list rows;
            for (const drivers::TangentialControlKind& kind : drivers::tangential_controls()) {
                rows.append(py::dict("name"_a = kind.name, "documentation"_a = kind.documentation,
                                     "column"_a = kind.column));
            }
            return rows;
        },
        "The registry of tangential controls (name, documentation, history column; the default first), for the docs.");
}

}  // namespace mdr::python
