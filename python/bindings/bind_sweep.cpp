#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <thread>

#include "bindings.hpp"
#include "summary_dict.hpp"
#include "mdr/error.hpp"
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
                summaries.append(summary_dict(row.summary));
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
    module.def(
        "_sweep_size",
        [](const std::vector<std::string>& specs) {
            std::vector<io::SweepAxis> axes;
            for (const auto& spec : specs) axes.push_back(io::parse_sweep_axis(spec));
            return io::sweep_size(axes);
        },
        py::arg("specs"), "The number of grid points of --vary specs (mdr.sweep bounds its threads by it).");
    module.def(
        "_sweep_grid",
        [](const std::vector<std::string>& specs) {
            std::vector<io::SweepAxis> axes;
            for (const auto& spec : specs) axes.push_back(io::parse_sweep_axis(spec));
            py::list keys;
            for (const auto& axis : axes) keys.append(axis.key);
            const auto points = io::sweep_points(axes);
            py::array_t<double> array({points.size(), axes.size()});
            auto view = array.mutable_unchecked<2>();
            for (std::size_t r = 0; r < points.size(); ++r) {
                for (std::size_t a = 0; a < axes.size(); ++a) view(r, a) = points[r][a];
            }
            return py::make_tuple(keys, array);
        },
        py::arg("specs"), "The keys and the grid points (rows x keys) of --vary specs, in row order (mdr.sweep).");
    module.def(
        "_sweep_points",
        [](const std::string& toml_text, const std::string& source, const std::vector<std::string>& keys,
           const py::array_t<double, py::array::c_style | py::array::forcecast>& points, unsigned jobs) {
            if (points.ndim() != 2 || static_cast<std::size_t>(points.shape(1)) != keys.size()) {
                throw InvalidInput("points", "array", "must have one column per key");
            }
            std::vector<io::SweepAxis> axes;
            for (const auto& key : keys) axes.push_back({key, {}});
            io::validate_sweep(toml_text, source, axes);
            const auto view = points.unchecked<2>();
            std::vector<std::vector<double>> rows_in(static_cast<std::size_t>(points.shape(0)));
            for (std::size_t r = 0; r < rows_in.size(); ++r) {
                for (std::size_t a = 0; a < keys.size(); ++a) rows_in[r].push_back(view(r, a));
            }
            std::vector<io::SweepRow> rows;
            {
                py::gil_scoped_release release;
                rows = io::run_sweep_points(toml_text, source, keys, std::move(rows_in), std::max(jobs, 1u), {});
            }
            py::list summaries, errors;
            for (const auto& row : rows) {
                summaries.append(summary_dict(row.summary));
                errors.append(row.error);
            }
            return py::make_tuple(summaries, errors);
        },
        py::arg("toml_text"), py::arg("source"), py::arg("keys"), py::arg("points"), py::arg("jobs") = 1,
        "Runs a case at the given points (rows x keys); returns (summaries, errors) in row order, a summary a dict "
        "({} where the point failed). The rows are those "
        "of _sweep_toml, bit for bit (mdr.distributed runs chunks of a sweep with it).");
}

}  // namespace mdr::python
