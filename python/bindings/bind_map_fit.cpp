// _mdr._fit_map_file: every curve of an instrument map fitted alone with a fit case, the same C++ as `mdr fit CASE
// --map FILE` (mdr/fitcase/map_fit.hpp), its rows as documents; mdr.fit_map(case, "x.jpk-force-map") is the
// public entry.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "case_tree.hpp"
#include "document_object.hpp"
#include "python_interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/instrument_curve.hpp"
#include "mdr/fitcase/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

// Fits every curve of `map` with the fit case `case_` (TOML text or a dict tree, case_tree.hpp) on
// `workers(curves)` threads (mdr._jobs.local_workers); returns the rows of map.csv (dicts, document_object), its
// columns, a function that writes map.csv and map.json into the folder it is given, the grid (columns, rows, size_x,
// size_y in the case's length unit) and the case's unit system. `progress(done, total)` at least every 0.2 s, if
// given; Ctrl-C is seen there, on this thread, which holds the GIL only then.
py::tuple fit_map_file(const py::object& case_, const std::string& source, const std::string& directory,
                       const std::string& map, const py::object& workers, const py::object& progress) {
    auto fit_case = fitcase::parse_fit_case(case_template(case_, source), directory);
    fitcase::require_map_case(fit_case);
    instrument::CurveFile file(map, fit::read_options(fit_case.data.front()));
    fitcase::require_map_time(file, fit_case, map);
    const fitcase::MapLayout layout = fitcase::map_layout(file, fit_case);
    const auto threads = workers(file.size()).cast<unsigned>();
    std::vector<fitcase::PixelFit> pixels;
    PythonInterrupt interrupt;
    const auto check = interrupt.check();
    interrupt.run([&] {
        pixels = fitcase::fit_map_pixels(fit_case, map, file.size(), threads, [&](std::size_t done, std::size_t total) {
            check();
            if (progress.is_none()) return;
            const py::gil_scoped_acquire acquire;
            progress(done, total);
        });
    });
    auto table = std::make_shared<const fitcase::MapRows>(fitcase::map_rows(pixels, fit_case));
    py::list rows;
    for (const auto& row : table->rows) rows.append(document_object(Document{row}));
    const auto write = [table, layout, fit_case, map](const std::filesystem::path& folder) {
        fitcase::write_map_table(folder / "map.csv", *table);
        fitcase::write_map_summary(folder / "map.json", layout, fit_case, map, *table);
    };
    return py::make_tuple(rows, table->columns, py::cpp_function(write, py::arg("folder")),
                          py::make_tuple(layout.columns, layout.rows, layout.size_x, layout.size_y), fit_case.units);
}

}  // namespace

void bind_map_fit(py::module_& module) {
    module.def("_fit_map_file", &fit_map_file, py::arg("case"), py::arg("source"), py::arg("directory"),
               py::arg("map"), py::arg("workers"), py::arg("progress") = py::none(),
               "Fits every curve of an instrument map; returns its rows, columns, a writer of map.csv and map.json, "
               "the grid and the units (mdr.fit_map is the public entry).");
    module.attr("_instrument_endings") = instrument::supported_extensions();
}

}  // namespace mdr::python
