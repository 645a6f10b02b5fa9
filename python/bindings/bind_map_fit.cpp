// _mdr._fit_map_file: every curve of an instrument map fitted alone with a fit case, the same C++ as `mdr fit CASE
// --map FILE` (mdr/fitcase/map_fit.hpp), its rows as documents; mdr.fit_map(case, "x.jpk-force-map") is the
// public entry. _mdr._fit_map_curve: one pixel of a stack of arrays, its row by the same builder (map_rows);
// _mdr._map_summary_json: map.json's text by the command line's writer, for every map mdr writes.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "case_tree.hpp"
#include "document_object.hpp"
#include "python_interrupt.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/instrument_curve.hpp"
#include "mdr/fitcase/map_fit.hpp"
#include "mdr/instrument/read_curves.hpp"
#include "mdr/io/document.hpp"

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
    instrument::CurveFile file(map, fitcase::read_options(fit_case.data.front()));
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

// Fits the curve (time, depth, force) of pixel (column, row), `index` in the stack, with the fit case `case_` (TOML
// text or a dict tree); returns its row of map.csv (a dict, document_object), the SI unit of each of its keys
// (MapRows::units) and the case's unit system. Bad data raise ValueError (mdr.InvalidInput): the pixel's failure.
py::tuple fit_map_curve(const py::object& case_, const std::string& source, const std::string& directory,
                        const InputArray& time, const InputArray& depth, const InputArray& force, std::size_t index,
                        std::size_t column, std::size_t row) {
    auto fit_case = fitcase::parse_fit_case(case_template(case_, source), directory);
    PythonInterrupt interrupt;
    fit_case.settings.check_interrupt = interrupt.check();
    std::vector<fitcase::PixelFit> pixels(1);
    interrupt.run([&] {
        fit::Curve curve = fit::make_curve("curve", to_vector(time), to_vector(depth), to_vector(force));
        pixels.front() = fitcase::fit_curve_pixel(fit_case, std::move(curve), index, column, row);
    });
    const fitcase::MapRows table = fitcase::map_rows(pixels, fit_case);
    py::dict units;
    for (std::size_t c = 0; c < table.columns.size(); ++c) units[py::str(table.columns[c])] = table.units[c];
    return py::make_tuple(document_object(Document{table.rows.front()}), units, fit_case.units);
}

}  // namespace

void bind_map_fit(py::module_& module) {
    module.def("_fit_map_file", &fit_map_file, py::arg("case"), py::arg("source"), py::arg("directory"),
               py::arg("map"), py::arg("workers"), py::arg("progress") = py::none(),
               "Fits every curve of an instrument map; returns its rows, columns, a writer of map.csv and map.json, "
               "the grid and the units (mdr.fit_map is the public entry).");
    module.def("_fit_map_curve", &fit_map_curve, py::arg("case"), py::arg("source"), py::arg("directory"),
               py::arg("time"), py::arg("depth"), py::arg("force"), py::arg("index"), py::arg("column"), py::arg("row"),
               "Fits one curve of a stack as a pixel of a map; returns its row of map.csv, the SI units of its keys "
               "and the case's unit system (mdr.fit_map is the public entry).");
    module.def(
        "_map_summary_json",
        [](std::size_t columns, std::size_t rows, const std::string& units, const std::string& source,
           const std::vector<std::string>& names, const std::vector<std::string>& name_units, std::size_t pixels,
           std::size_t failed) {
            const fitcase::MapLayout layout{columns, rows, 0.0, 0.0};
            return io::to_json(fitcase::map_summary(layout, units, source, names, name_units, pixels, failed), 1) +
                   "\n";
        },
        py::arg("columns"), py::arg("rows"), py::arg("units"), py::arg("source"), py::arg("names"),
        py::arg("name_units"), py::arg("pixels"), py::arg("failed"),
        "map.json's text for a grid of columns x rows pixels without positions (mdr.CurveMap.write_files).");
    module.attr("_instrument_endings") = instrument::supported_extensions();
}

}  // namespace mdr::python
