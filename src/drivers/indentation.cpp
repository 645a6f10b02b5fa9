#include "mdr/drivers/indentation.hpp"

#include <cstddef>
#include <optional>
#include <utility>
#include <variant>
#include <vector>

#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "history_stepping.hpp"
#include "impact_stepping.hpp"
#include "normal_control.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"

namespace mdr::drivers {
namespace {

// The one loop of every control on the half-space, as Boost.Odeint's integrate: the stepping class of the control
// (HistoryStepping over a class of normal_control.hpp, ImpactStepping) takes each step to the next node of its grid
// and says which state is the last (its stop rule); after each step the observers see the state: the standard ones
// (rows, the control's own, snapshots, progress), then the caller's. A stepping class has a constructor
// (contact_case, numerics, foundation, its control's data...), columns(), add_observers(observers, result),
// shear_stress(), first_state(), step(n) and add_outcomes(result), the outcomes that need the whole run.
template <class Stepping, class... ControlData>
IndentationResult run_control(const ContactCase& contact_case, const ProgressObserver& progress,
                              const StepObservers& extra_observers, ControlData&&... control_data) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    foundation::Foundation foundation(contact_case.material, *contact_case.indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    Stepping stepping(contact_case, numerics, foundation, std::forward<ControlData>(control_data)...);

    // The standard observers fill the result; the caller's follow them.
    ObserverList observers(numerics.output_every);
    RowRecorder rows(result, stepping.columns());
    observers.add(rows);
    stepping.add_observers(observers, result);
    SnapshotRecorder snapshots(contact_case.snapshots, *contact_case.indenter, result, stepping.shear_stress());
    observers.add(snapshots);
    std::optional<ProgressReport> progress_report;
    if (progress) observers.add(progress_report.emplace(progress));
    observers.add(extra_observers);

    StepState state = stepping.first_state();
    bool stopped = observers.notify(state);
    for (std::size_t n = 1; !stopped; ++n) {
        state = stepping.step(n);
        ++result.steps;
        stopped = observers.notify(state);
    }
    result.stopped = observers.stopped();
    if (!result.stopped) stepping.add_outcomes(result);  // the outcomes need the whole run
    return result;
}

// The stepping class of each control.
struct ControlRun {
    const ContactCase& contact_case;
    const ProgressObserver& progress;
    const StepObservers& observers;

    IndentationResult operator()(const DisplacementControl&) const {
        return run_control<HistoryStepping<DisplacementStepping>>(contact_case, progress, observers,
                                                                 DisplacementStepping{});
    }
    IndentationResult operator()(const ForceControl&) const {
        return run_control<HistoryStepping<ForceStepping>>(contact_case, progress, observers, ForceStepping{});
    }
    IndentationResult operator()(const SpringControl& spring) const {
        return run_control<HistoryStepping<SpringStepping>>(contact_case, progress, observers,
                                                           SpringStepping(spring));
    }
    IndentationResult operator()(const ImpactControl& impact) const {
        return run_control<ImpactStepping>(contact_case, progress, observers, impact);
    }
};

// The grid of each history-driven control (indentation_grid); an impact has no history grid.
struct HistoryGrid {
    const ContactCase& contact_case;
    const ResolvedNumerics& numerics;

    std::vector<GridNode> operator()(const DisplacementControl&) const {
        return history_grid(contact_case, numerics, DisplacementStepping{});
    }
    std::vector<GridNode> operator()(const ForceControl&) const {
        return history_grid(contact_case, numerics, ForceStepping{});
    }
    std::vector<GridNode> operator()(const SpringControl& spring) const {
        return history_grid(contact_case, numerics, SpringStepping(spring));
    }
    std::vector<GridNode> operator()(const ImpactControl&) const {
        throw InvalidInput("load.control", "\"impact\"", "has no history grid (its steps end at the contact's end)");
    }
};

}  // namespace

std::vector<GridNode> indentation_grid(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    return std::visit(HistoryGrid{contact_case, numerics}, contact_case.control);
}

IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                  const StepObservers& extra_observers) {
    return std::visit(ControlRun{contact_case, progress, extra_observers}, contact_case.control);
}

IndentationResult run_case(const ContactCase& contact_case, const ProgressObserver& progress,
                           const StepObservers& observers) {
    auto result = contact_case.layer ? run_layer_indentation(contact_case, progress, observers)
                                     : run_indentation(contact_case, progress, observers);
    require_finite_result(result);
    return result;
}

}  // namespace mdr::drivers
