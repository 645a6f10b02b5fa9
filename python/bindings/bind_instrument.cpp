#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace py = pybind11;

namespace mdr::python {

namespace {

/// The per-sample segment indices as an integer numpy array.
py::array_t<std::int64_t> segment_array(const std::vector<std::uint16_t>& segment) {
    py::array_t<std::int64_t> array(static_cast<py::ssize_t>(segment.size()));
    std::copy(segment.begin(), segment.end(), array.mutable_data());
    return array;
}

}  // namespace

void bind_instrument(py::module_& module) {
    using instrument::Curve;
    py::class_<Curve>(module, "Curve",
                      "One force curve of an instrument file, in SI units (docs/instrument-files.md); "
                      "built by mdr.read_curves.")
        .def_property_readonly("time", [](const Curve& curve) { return to_array(curve.time); },
                               "s from the start of the first segment (empty where the file records no time)")
        .def_property_readonly("force", [](const Curve& curve) { return to_array(curve.force); },
                               "N: deflection x spring constant, no baseline removed")
        .def_property_readonly("height", [](const Curve& curve) { return to_array(curve.height); },
                               "m: the height sensor, else the piezo; larger = farther from the sample")
        .def_property_readonly("deflection", [](const Curve& curve) { return to_array(curve.deflection); },
                               "m: the cantilever deflection")
        .def_property_readonly("segment", [](const Curve& curve) { return segment_array(curve.segment); },
                               "per sample, the index into segment_names")
        .def_readonly("segment_names", &Curve::segment_names, "per segment: extend, pause or retract")
        .def_readonly("spring_constant", &Curve::spring_constant, "N/m")
        .def_readonly("sensitivity", &Curve::sensitivity, "m/V (m/A for NT-MDT); 0 where the file has none")
        .def_property_readonly(
            "position",
            [](const Curve& curve) -> py::object {
                if (!curve.in_map) return py::none();
                return py::make_tuple(curve.position.x, curve.position.y);
            },
            "(x, y) in m for a curve of a map, else None")
        .def_property_readonly(
            "pixel",
            [](const Curve& curve) -> py::object {
                if (!curve.in_map) return py::none();
                return py::make_tuple(curve.position.column, curve.position.row);
            },
            "(column, row) of the map's grid from its low-x, low-y corner, else None")
        .def_readonly("height_channel", &Curve::height_channel, "the file's channel that height comes from")
        .def_readonly("metadata", &Curve::metadata, "the header values as the file states them")
        .def_readonly("source", &Curve::source, "the file, and the member or index within it")
        .def("__repr__", [](const Curve& curve) {
            return "<mdr.Curve " + curve.source + ": " + std::to_string(curve.force.size()) + " samples>";
        });
    module.def(
        "_read_curves",
        [](const std::string& path, double spring_constant, double sensitivity) {
            return instrument::read_curves(path, {.spring_constant = spring_constant, .sensitivity = sensitivity});
        },
        py::arg("path"), py::arg("spring_constant") = 0.0, py::arg("sensitivity") = 0.0,
        py::call_guard<py::gil_scoped_release>(),
        "Every curve of an instrument file (mdr::instrument::read_curves); 0 = calibration not given.");
}

}  // namespace mdr::python
