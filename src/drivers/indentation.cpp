#include "mdr/drivers/indentation.hpp"

#include <cstddef>
#include <optional>
#include <vector>

#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "every_control.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"

namespace mdr::drivers {
namespace {

// The one loop of every control on the half-space, as Boost.Odeint's integrate: the stepping class of the control
// (its ControlTraits' Stepping: HistoryStepping over a step class of normal_control.hpp, ImpactStepping) takes each
// step to the next node of its grid and says which state is the last (its stop rule); after each step the observers
// see the state: the standard ones (rows, the control's own, snapshots, progress), then the caller's. A stepping
// class has a constructor (contact_case, numerics, foundation, its control's data),
// add_observers(observers, result), shear_stress(), first_state(), step(n) and add_outcomes(result), the outcomes
// that need the whole run.
template <class Stepping, class Control>
IndentationResult run_control(const ContactCase& contact_case, const ProgressObserver& progress,
                              const StepObservers& extra_observers, const Control& control) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    foundation::Foundation foundation(contact_case.material, *contact_case.indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    Stepping stepping(contact_case, numerics, foundation, control);

    // The standard observers fill the result; the caller's follow them.
    ObserverList observers(numerics.output_every);
    RowRecorder rows(result, ControlTraits<Control>::columns(control));
    observers.add(rows);
    stepping.add_observers(observers, result);
    FoundationSnapshots snapshot_source(*contact_case.indenter, stepping.shear_stress());
    SnapshotRecorder snapshots(contact_case.snapshots, snapshot_source, result);
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

}  // namespace

std::vector<GridNode> indentation_grid(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    return visit_control(contact_case.control, [&](auto traits, const auto& control) {
        return traits.grid(contact_case, numerics, control);
    });
}

IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                  const StepObservers& extra_observers) {
    return visit_control(contact_case.control, [&](auto traits, const auto& control) {
        return run_control<typename decltype(traits)::Stepping>(contact_case, progress, extra_observers, control);
    });
}

IndentationResult run_case(const ContactCase& contact_case, const ProgressObserver& progress,
                           const StepObservers& observers) {
    auto result = contact_case.layer ? run_layer_indentation(contact_case, progress, observers)
                                     : run_indentation(contact_case, progress, observers);
    require_finite_result(result);
    return result;
}

}  // namespace mdr::drivers
