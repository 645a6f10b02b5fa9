#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

#include "bindings.hpp"
#include "case_tree.hpp"
#include "document_object.hpp"
#include "mdr/error.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/io/case_objects.hpp"
#include "mdr/io/sweep.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

// The axes of mdr.sweep: each a `--vary` spec (str) or a (key, values) pair whose numbers come as they are.
std::vector<io::SweepAxis> sweep_axes(const py::list& specs) {
    std::vector<io::SweepAxis> axes;
    for (const auto& spec : specs) {
        if (py::isinstance<py::str>(spec)) {
            axes.push_back(io::parse_sweep_axis(spec.cast<std::string>()));
            continue;
        }
        auto axis = spec.cast<std::pair<std::string, std::vector<double>>>();
        for (const double value : axis.second) {
            if (!std::isfinite(value)) {
                throw InvalidInput("vary['" + axis.first + "']", std::to_string(value), "must be finite numbers");
            }
        }
        axes.push_back({std::move(axis.first), std::move(axis.second)});
    }
    return axes;
}

// The table of a sweep of `model` (an io::CaseTemplate or io::SweepCase) over the axes `specs` on `jobs` threads (0:
// every core), as _sweep_case returns it.
template <class Model>
py::dict sweep_table(const Model& model, const py::list& specs, unsigned jobs, const py::object& progress) {
    const auto axes = sweep_axes(specs);
    io::validate_sweep(model, axes);
    std::vector<io::SweepRow> rows;
    {
        py::gil_scoped_release release;
        rows = io::run_sweep(model, axes, jobs == 0 ? std::thread::hardware_concurrency() : jobs,
                             [&progress](std::size_t done, std::size_t total) {
                                 // Ctrl-C or an exception of `progress` stops the sweep (run_sweep joins its
                                 // threads and rethrows).
                                 py::gil_scoped_acquire acquire;
                                 if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                                 if (!progress.is_none()) progress(done, total);
                             });
    }
    py::list points, summaries, errors;
    for (const auto& row : rows) {
        points.append(py::cast(row.point));
        summaries.append(document_object(Document{row.summary}));
        errors.append(row.error);
    }
    py::dict out;
    out["keys"] = specs;
    out["points"] = points;
    out["summaries"] = summaries;
    out["errors"] = errors;
    out["columns"] = io::sweep_columns(rows);
    return out;
}

using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The rows (summaries, errors) of `model` (an io::CaseTemplate or io::SweepCase) at the points (rows x keys) on `jobs`
// threads, as _sweep_points returns them; the keys checked first (validate_sweep).
template <class Model>
py::tuple points_rows(const Model& model, const std::vector<std::string>& keys, const Points& points, unsigned jobs) {
    if (points.ndim() != 2 || static_cast<std::size_t>(points.shape(1)) != keys.size()) {
        throw InvalidInput("points", "array", "must have one column per key");
    }
    std::vector<io::SweepAxis> axes;
    for (const auto& key : keys) axes.push_back({key, {}});
    io::validate_sweep(model, axes);
    const auto view = points.unchecked<2>();
    std::vector<std::vector<double>> rows_in(static_cast<std::size_t>(points.shape(0)));
    for (std::size_t r = 0; r < rows_in.size(); ++r) {
        for (std::size_t a = 0; a < keys.size(); ++a) rows_in[r].push_back(view(r, a));
    }
    std::vector<io::SweepRow> rows;
    {
        py::gil_scoped_release release;
        rows = io::run_sweep_points(model, keys, std::move(rows_in), std::max(jobs, 1u), {});
    }
    py::list summaries, errors;
    for (const auto& row : rows) {
        summaries.append(document_object(Document{row.summary}));
        errors.append(row.error);
    }
    return py::make_tuple(summaries, errors);
}

}  // namespace

void bind_sweep(py::module_& module) {
    module.def(
        "_sweep_case",
        [](const py::object& case_, const std::string& source, const py::list& specs, unsigned jobs,
           const py::object& progress) {
            const auto model = case_template(case_, source);
            return sweep_table(model, specs, jobs, progress);
        },
        py::arg("case"), py::arg("source"), py::arg("specs"), py::arg("jobs") = 0, py::arg("progress") = py::none(),
        "Runs a case (TOML text or a dict tree) over the cartesian product of axes, each a --vary spec or a "
        "(key, values) pair (use mdr.sweep).");
    module.def(
        "_sweep_contact_case",
        [](const drivers::ContactCase& contact_case, const py::list& specs, unsigned jobs,
           const py::object& progress) {
            return sweep_table(io::CaseObjects(contact_case), specs, jobs, progress);
        },
        py::arg("case"), py::arg("specs"), py::arg("jobs") = 0, py::arg("progress") = py::none(),
        "Runs an mdr.ContactCase over the cartesian product of axes as _sweep_case, on its objects (use mdr.sweep).");
    module.def(
        "_sweep_columns",
        [](const py::list& summaries) {
            std::vector<io::SweepRow> rows(summaries.size());
            for (std::size_t r = 0; r < rows.size(); ++r) {
                if (!py::isinstance<py::dict>(summaries[r])) throw py::type_error("a sweep row's summary is a dict");
                rows[r].summary = std::get<Document::Table>(document_of(summaries[r]).value);
            }
            return io::sweep_columns(rows);
        },
        py::arg("summaries"),
        "The numeric columns of a sweep's table from its rows' summaries (dicts), as sweep.csv has them "
        "(mdr.sweep on a scheduler).");
    module.def(
        "_sweep_size",
        [](const py::list& specs) { return io::sweep_size(sweep_axes(specs)); }, py::arg("specs"),
        "The number of grid points of the axes of _sweep_case (mdr.sweep bounds its threads by it).");
    module.def(
        "_sweep_grid",
        [](const py::list& specs) {
            const auto axes = sweep_axes(specs);
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
        py::arg("specs"), "The keys and the grid points (rows x keys) of the axes of _sweep_case, in row order.");
    module.def(
        "_sweep_points",
        [](const py::object& case_, const std::string& source, const std::vector<std::string>& keys,
           const Points& points, unsigned jobs) {
            return points_rows(case_template(case_, source), keys, points, jobs);
        },
        py::arg("case"), py::arg("source"), py::arg("keys"), py::arg("points"), py::arg("jobs") = 1,
        "Runs a case (TOML text or a dict tree) at the given points (rows x keys); returns (summaries, errors) in "
        "row order, a summary a dict ({} where the point failed). The rows are those of _sweep_case, bit for bit "
        "(mdr.distributed runs chunks of a sweep with it).");
    module.def(
        "_sweep_contact_case_points",
        [](const drivers::ContactCase& contact_case, const std::vector<std::string>& keys, const Points& points,
           unsigned jobs) { return points_rows(io::CaseObjects(contact_case), keys, points, jobs); },
        py::arg("case"), py::arg("keys"), py::arg("points"), py::arg("jobs") = 1,
        "_sweep_points of an mdr.ContactCase, on its objects: the rows of _sweep_contact_case, bit for bit "
        "(mdr.distributed runs chunks of a sweep of a case's objects with it, the case pickled).");
}

}  // namespace mdr::python
