#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "mdr/io/result_directory.hpp"

namespace py = pybind11;

namespace mdr::python {

void bind_result_directory(py::module_& module) {
    py::class_<io::ResultDirectory>(module, "_ResultDirectory",
                                    "A result directory with the rules of --out (include/mdr/io/result_directory.hpp): "
                                    "checked when constructed, written atomically by write().")
        .def(py::init<const std::filesystem::path&, std::string, std::vector<std::filesystem::path>>(),
             py::arg("directory"), py::arg("key"), py::arg("inputs") = std::vector<std::filesystem::path>{})
        .def(
            "write",
            [](const io::ResultDirectory& directory, const std::function<void(const std::string&)>& write_files) {
                // The files are written by Python (with the GIL held); Ctrl-C inside write_files raises
                // KeyboardInterrupt there, which removes the temporary directory on its way out.
                directory.write([&](const std::filesystem::path& temporary) { write_files(temporary.string()); },
                                [] {
                                    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                                    return false;
                                });
            },
            py::arg("write_files"),
            "Calls write_files(temporary_directory), records its files in the manifest and puts the directory in place.")
        .def_property_readonly("shown", &io::ResultDirectory::shown);
}

}  // namespace mdr::python
