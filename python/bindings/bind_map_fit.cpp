// _mdr._fit_map_file: every curve of an instrument map fitted alone with a fit case, the same C++ as `mdr fit CASE
// --map FILE` (mdr/fit/map_fit.hpp); mdr.fit_map(case, "x.jpk-force-map") is the public entry.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>


#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "case_tree.hpp"
#include "python_interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

// Fits every curve of `map` with the fit case `case_` (TOML text or a dict tree, case_tree.hpp) and writes map.csv
// and map.json into `folder`; returns the grid (columns, rows, size_x, size_y in the case's length unit) and the
// case's unit system. `progress(done, total)` after each pixel, if given.
py::tuple fit_map_file(const py::object& case_, const std::string& source, const std::string& directory,
                       const std::string& map, const std::filesystem::path& folder, const py::object& progress) {
    auto fit_case = io::parse_fit_case(case_template(case_, source), directory);
    fit::require_map_case(fit_case);
    PythonInterrupt interrupt;
    fit_case.settings.check_interrupt = interrupt.check();
    instrument::CurveFile file(map);
    const fit::MapLayout layout = fit::map_layout(file, fit_case);
    std::vector<fit::PixelFit> pixels;
    for (std::size_t i = 0; i < file.size(); ++i) {
        interrupt.run([&] { pixels.push_back(fit::fit_map_pixel(fit_case, map, file, i)); });
        if (!progress.is_none()) progress(i + 1, file.size());
    }
    fit::write_map_table(folder / "map.csv", pixels);
    fit::write_map_summary(folder / "map.json", layout, fit_case.units, map, pixels);
    return py::make_tuple(layout.columns, layout.rows, layout.size_x, layout.size_y, fit_case.units);
}

}  // namespace

void bind_map_fit(py::module_& module) {
    module.def("_fit_map_file", &fit_map_file, py::arg("case"), py::arg("source"), py::arg("directory"),
               py::arg("map"), py::arg("folder"), py::arg("progress") = py::none(),
               "Fits every curve of an instrument map and writes map.csv and map.json into folder (mdr.fit_map is "
               "the public entry).");
    module.attr("_instrument_endings") = instrument::supported_extensions();
}

}  // namespace mdr::python
