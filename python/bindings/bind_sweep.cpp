#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <thread>

#include "bindings.hpp"
#include "mdr/io/sweep.hpp"

namespace py = pybind11;

namespace mdr::python {

void bind_sweep(py::module_& module) {
    module.def(
        "_sweep_toml",
        [](const std::string& toml_text, const std::string& source, const std::vector<std::string>& specs,
           unsigned jobs, const py::object& progress) {
            std::vector<io::SweepAxis> axes;
            for (const auto& spec : specs) axes.push_back(io::parse_sweep_axis(spec));
            io::validate_sweep(toml_text, source, axes);
            std::vector<io::SweepRow> rows;
            {
                py::gil_scoped_release release;
                rows = io::run_sweep(toml_text, source, axes, jobs == 0 ? std::thread::hardware_concurrency() : jobs,
                                     [&progress](std::size_t done, std::size_t total) {
                                         // Ctrl-C or an exception of `progress` stops the sweep (run_sweep joins
                                         // its threads and rethrows).
                                         py::gil_scoped_acquire acquire;
                                         if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                                         if (!progress.is_none()) progress(done, total);
                                     });
            }
            py::list points, summaries, errors;
            for (const auto& row : rows) {
                points.append(py::cast(row.point));
                summaries.append(row.summary_json);
                errors.append(row.error);
            }
            py::dict out;
            out["keys"] = py::cast(specs);
            out["points"] = points;
            out["summaries"] = summaries;
            out["errors"] = errors;
            return out;
        },
        py::arg("toml_text"), py::arg("source"), py::arg("specs"), py::arg("jobs") = 0,
        py::arg("progress") = py::none(),
        "Runs a case over the cartesian product of --vary specs (use mdr.sweep).");
}

}  // namespace mdr::python
