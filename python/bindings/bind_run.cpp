#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>
#include <vector>

#include <fmt/format.h>

#include "bindings.hpp"
#include "case_tree.hpp"
#include "document_object.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/step_observer.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/history_columns.hpp"
#include "mdr/io/profile_columns.hpp"
#include "mdr/io/summary.hpp"
#include "mdr/io/units.hpp"

namespace py = pybind11;

namespace mdr::python {
namespace {

// One state of a run as a Python observer sees it (drivers::StepState, its contact radius read out).
struct StepRecord {
    std::size_t step = 0;
    double time = 0.0, depth = 0.0, force = 0.0, load = 0.0, velocity = 0.0, contact_radius = 0.0, fraction = 0.0;
    bool settled = true;
};

// A Python callable as a drivers::StepObserver: called once per state, in time order, with its StepRecord. It is
// called when the driver asks whether to stop (a true return ends the run with this state), and from `observe`
// for a state the driver did not ask about (its own last one, or one another observer ended the run with). An
// exception it raises abandons the run and propagates.
class PythonObserver final : public drivers::StepObserver {
public:
    explicit PythonObserver(py::object callable) : callable_(std::move(callable)) {}
    bool stop(const drivers::StepState& state) override {
        asked_ = true;
        return call(state);
    }
    void observe(const drivers::StepState& state) override {
        if (!asked_) call(state);
        asked_ = false;
    }

private:
    bool call(const drivers::StepState& state) const {
        const StepRecord record{.step = state.step,
                                .time = state.time,
                                .depth = state.depth,
                                .force = state.force,
                                .load = state.load,
                                .velocity = state.velocity,
                                .contact_radius = state.contact_radius(),
                                .fraction = state.fraction,
                                .settled = state.settled};
        py::gil_scoped_acquire acquire;
        return py::bool_(callable_(record));
    }

    py::object callable_;
    bool asked_ = false;
};

// The observers given (None or a sequence of callables), each wrapped; TypeError naming `observers` else.
std::vector<PythonObserver> python_observers(const py::object& observers) {
    std::vector<PythonObserver> wrapped;
    if (observers.is_none()) return wrapped;
    if (!py::isinstance<py::sequence>(observers) || py::isinstance<py::str>(observers)) {
        throw py::type_error("observers: expected a sequence of callables, got " +
                             py::type::of(observers).attr("__name__").cast<std::string>());
    }
    for (const auto& observer : observers) {
        if (!PyCallable_Check(observer.ptr())) {
            throw py::type_error("observers: expected callables, got " +
                                 py::type::of(observer).attr("__name__").cast<std::string>());
        }
        wrapped.emplace_back(py::reinterpret_borrow<py::object>(observer));
    }
    return wrapped;
}

// Runs with the GIL released; at each report of the driver, Ctrl-C (a pending signal) stops the run with
// KeyboardInterrupt, and `progress` (None or a callable of the fraction done) is called; an exception it raises
// stops the run and propagates. `progress` is called with 1.0 once the run is done, where the driver's last report
// was less (a run an observer stopped). `observers` (None or a sequence
// of callables) see every state (PythonObserver).
py::dict run_contact_case(const drivers::ContactCase& contact_case, const py::object& progress,
                          const py::object& observers) {
    std::vector<PythonObserver> wrapped = python_observers(observers);
    drivers::StepObservers attached;
    for (PythonObserver& observer : wrapped) attached.push_back(&observer);
    drivers::IndentationResult result;
    double wall = 0.0;
    double reported = 0.0;
    {
        py::gil_scoped_release release;
        const auto start = std::chrono::steady_clock::now();
        result = drivers::run_case(
            contact_case,
            [&progress, &reported](double fraction) {
                py::gil_scoped_acquire acquire;
                if (PyErr_CheckSignals() != 0) throw py::error_already_set();
                reported = fraction;
                if (!progress.is_none()) progress(fraction);
            },
            attached);
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    if (!progress.is_none() && reported < 1.0) progress(1.0);
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

// A case given as TOML text or a dict tree, read by the case file's reader.
py::dict run_case(const py::object& case_, const std::string& source, const py::object& progress,
                  const py::object& observers) {
    return run_contact_case(case_template(case_, source).build(), progress, observers);
}

}  // namespace

void bind_run(py::module_& module) {
    py::class_<StepRecord>(module, "Step", "One state of a run, as an observer of mdr.run sees it "
                                           "(drivers::StepState).")
        .def_readonly("step", &StepRecord::step, "steps taken so far (0: the initial state)")
        .def_readonly("time", &StepRecord::time, "t [s]")
        .def_readonly("depth", &StepRecord::depth, "d [m]")
        .def_readonly("force", &StepRecord::force, "normal force F [N]")
        .def_readonly("load", &StepRecord::load,
                      "the prescribed value at t: depth [m], force [N] or base z [m] by the control; 0 in an impact")
        .def_readonly("velocity", &StepRecord::velocity, "indenter velocity dd/dt [m/s] (impact only, else 0)")
        .def_readonly("contact_radius", &StepRecord::contact_radius, "a [m]")
        .def_readonly("fraction", &StepRecord::fraction, "part of the run done, 0..1")
        .def_readonly("settled", &StepRecord::settled, "no further step follows at this time (false inside a jump)")
        .def("__repr__", [](const StepRecord& record) {
            return fmt::format("Step(step={}, time={}, depth={}, force={}, contact_radius={})", record.step,
                               record.time, record.depth, record.force, record.contact_radius);
        });
    module.def("_run_case", &run_case, py::arg("case"), py::arg("source") = "case", py::arg("progress") = py::none(),
               py::arg("observers") = py::none(),
               "Runs a case given as TOML text or as a dict tree; returns history, profiles and summary "
               "(use mdr.run).");
    module.def("_run_contact_case", &run_contact_case, py::arg("case"), py::arg("progress") = py::none(),
               py::arg("observers") = py::none(),
               "Runs an mdr.ContactCase; returns history, profiles and summary (use mdr.run).");
    module.def(
        "_check_contact_case", [](const drivers::ContactCase& contact_case) { return io::check(contact_case); },
        py::arg("case"), "Checks an mdr.ContactCase's bounds of work and memory; returns its description.");
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
