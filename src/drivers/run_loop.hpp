#pragma once
// The one loop of every run, on the half-space and on a [layer], as Boost.Odeint's integrate: a stepping class takes
// each step to the next node of its grid and says which state is the last (its stop rule); after each step the
// observers see the state: the standard ones (rows, the stepping's own, snapshots, progress), then the caller's.

#include <concepts>
#include <cstddef>
#include <optional>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

/// What the one loop (run_stepping) asks of a stepping class: the half-space's (ControlTraits::Stepping:
/// HistoryStepping, ImpactStepping) and a [layer]'s (LayerTingStepping, LayerImpactStepping, LayerCellsStepping,
/// LayerCellsImpactStepping), each made by its driver from the case, its numerics and what its control brings.
template <class Stepping>
concept SteppingClass = requires(Stepping stepping, ObserverList& observers, IndentationResult& result,
                                 std::size_t n) {
    stepping.add_observers(observers, result);  // its own observers (Shore readings, tangential columns, ...)
    { stepping.first_state() } -> std::same_as<StepState>;  // the state at the start (step 0)
    { stepping.step(n) } -> std::same_as<StepState>;        // the state after step n = 1, 2, ...; `last` ends the run
    stepping.add_outcomes(result);  // the outcomes that need the whole run (impact, tangential, harmonic)
};

/// Runs `stepping` from its first state to its last and fills `result` (its numerics set by the caller): the rows of
/// the case's control (RowRecorder), the stepping's own observers, the snapshots at the case's times from
/// `snapshot_source`, the progress report (each hundredth of StepState::fraction), then the caller's `observers`;
/// result.steps and result.stopped (an observer's stop ends the run with its state, and the outcomes are left out),
/// else the stepping's outcomes. With `deferred` (an empty log), the rows, the stepping's own observers and the
/// caller's see the states only once the run has ended (StateLog::replay): a stop there ends the result at its state
/// (its steps, its rows, the snapshots after it dropped) as one asked live; the snapshots and the progress are live.
template <SteppingClass Stepping>
void run_stepping(Stepping& stepping, const ContactCase& contact_case, SnapshotSource& snapshot_source,
                  const ProgressObserver& progress, const StepObservers& observers, IndentationResult& result,
                  StateLog* deferred = nullptr) {
    const std::size_t output_every = result.numerics.output_every;
    ObserverList live(output_every);
    ObserverList replayed(output_every);
    ObserverList& shown = deferred ? replayed : live;
    RowRecorder rows(result, row_columns(contact_case.control));
    shown.add(rows);
    stepping.add_observers(shown, result);
    if (deferred) live.add(*deferred);
    SnapshotRecorder snapshots(contact_case.snapshots, snapshot_source, result);
    live.add(snapshots);
    std::optional<ProgressReport> progress_report;
    if (progress) live.add(progress_report.emplace(progress));
    shown.add(observers);

    StepState state = stepping.first_state();
    bool ends = live.notify(state);
    for (std::size_t n = 1; !ends; ++n) {
        state = stepping.step(n);
        ++result.steps;
        ends = live.notify(state);
    }
    result.stopped = live.stopped();
    if (deferred) {
        const StepState end = deferred->replay(replayed);
        if (replayed.stopped()) {
            result.stopped = true;
            result.steps = end.step;
            drop_snapshots_after(result.snapshots, end);
        }
    }
    if (!result.stopped) stepping.add_outcomes(result);  // the outcomes need the whole run
}

}  // namespace mdr::drivers
