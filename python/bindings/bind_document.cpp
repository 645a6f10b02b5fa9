// _mdr._to_json: the one JSON writer of results (mdr/io/document.hpp) for what Python writes, so that a file or a
// message mdr writes from Python has the layout the command line gives it (null for a number that is not finite).

#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "document_object.hpp"
#include "mdr/io/document.hpp"

namespace py = pybind11;

namespace mdr::python {

void bind_document(py::module_& module) {
    module.def(
        "_to_json", [](const py::handle& object, int indent) { return io::to_json(document_of(object), indent); },
        py::arg("document"), py::arg("indent") = 2,
        "JSON text of a document given as dicts, lists, numbers, texts and None (indent -1: one line).");
}

}  // namespace mdr::python
