#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>

#include "bindings.hpp"
#include "case_tree.hpp"
#include "document_object.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/history_columns.hpp"
#include "mdr/io/profile_columns.hpp"
#include "mdr/io/summary.hpp"
#include "mdr/io/units.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

// Runs with the GIL released; at each report of the driver, Ctrl-C (a pending signal) stops the run with
// KeyboardInterrupt, and `progress` (None or a callable of the fraction done) is called; an exception it raises
// stops the run and propagates. `progress` is called with 1.0 once the run is done.
py::dict run_case(const py::object& case_, const std::string& source, const py::object& progress) {
    const auto contact_case = case_template(case_, source).build();
    drivers::IndentationResult result;
    double wall = 0.0;
    {
        py::gil_scoped_release release;
        const auto start = std::chrono::steady_clock::now();
        result = drivers::run_case(contact_case, [&progress](double fraction) {
            py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0) throw py::error_already_set();
            if (!progress.is_none()) progress(fraction);
        });
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    if (!progress.is_none()) progress(1.0);
    py::dict history;
    for (const io::HistoryColumn& column : io::history_columns(result)) {
        py::array_t<double> values(static_cast<py::ssize_t>(result.time.size()));
        auto* data = values.mutable_data();
        for (std::size_t i = 0; i < result.time.size(); ++i) data[i] = column.value(result, i);
        history[py::str(column.name.data(), column.name.size())] = values;
    }
    py::dict profiles;
    std::size_t profile_rows = 0;
    for (const auto& snapshot : result.snapshots) profile_rows += snapshot.radius.size();
    for (const io::ProfileColumn& column : io::profile_columns(result)) {
        py::array_t<double> values(static_cast<py::ssize_t>(profile_rows));
        auto* data = values.mutable_data();
        for (const auto& snapshot : result.snapshots)
            for (std::size_t j = 0; j < snapshot.radius.size(); ++j) *data++ = column.value(snapshot, j);
        profiles[py::str(column.name.data(), column.name.size())] = values;
    }
    py::dict out;
    out["history"] = history;
    out["profiles"] = profiles;
    out["summary"] = document_object(Document{io::summarize(contact_case, result, wall)});
    out["description"] = io::describe(contact_case);
    return out;
}

}  // namespace

void bind_run(py::module_& module) {
    module.def("_run_case", &run_case, py::arg("case"), py::arg("source") = "case", py::arg("progress") = py::none(),
               "Runs a case given as TOML text or as a dict tree; returns history, profiles and summary "
               "(use mdr.run).");
    module.def(
        "_check_case",
        [](const py::object& case_, const std::string& source) {
            return io::check(case_template(case_, source).build());
        },
        py::arg("case"), py::arg("source") = "case",
        "Validates a case given as TOML text or as a dict tree; returns its description.");
    module.def(
        "_unreadable_case",
        [](const std::string& path) { throw unreadable_file("case", path); },
        py::arg("path"), "Raises the command line's error for a case file that cannot be read (mdr/error.hpp).");
    module.def(
        "_unit_system",
        [](const std::string& name) {
            const io::UnitSystem& units = io::unit_system(name);
            py::dict names;
            names["length"] = units.length;
            names["force"] = units.force;
            names["time"] = units.time;
            names["pressure"] = units.pressure;
            names["mass"] = units.mass;
            names["energy"] = units.energy;
            names["velocity"] = units.velocity();
            names["viscosity"] = units.viscosity();
            names["compliance"] = units.compliance();
            return names;
        },
        py::arg("name") = "SI", "The unit names of a declared unit system (`units` of a case; mdr/io/units.hpp).");
    module.def(
        "_unit_systems",
        [] {
            py::list names;
            for (const io::UnitSystem& units : io::unit_systems()) names.append(std::string(units.name));
            return names;
        },
        "The names of the declared unit systems, SI (the default) first, for the docs.");
}

}  // namespace mdr::python
