#pragma once
/// \file
/// Observers of a run. The drivers own the time loop and hand the state after every step to a list of observers,
/// as Boost.Odeint's integrate_const hands it to its observer: the result's rows, the snapshots, the Shore readings,
/// the harmonic cycle measure, the tangential columns and the progress reports are observers, and a caller attaches
/// its own through run_case (include/mdr/drivers/indentation.hpp) without touching the driver.

#include <cstddef>
#include <vector>

namespace mdr::foundation {
class Foundation;
}

namespace mdr::drivers {

/// The state of a run at one time, as the driver hands it to its observers.
struct StepState {
    std::size_t step = 0;   ///< steps taken so far (0: the initial state)
    double time = 0.0;      ///< t [s]
    double depth = 0.0;     ///< d [m] as recorded (force control at zero force: where the recovering surface touches)
    double force = 0.0;     ///< normal force F [N]
    double load = 0.0;      ///< the prescribed value at t: depth [m], force [N] or base z [m] by the control (with
                            ///< its harmonic part); 0 in an impact
    double velocity = 0.0;  ///< indenter velocity dd/dt [m/s] (impact only, else 0)
    double fraction = 0.0;  ///< part of the run done, 0..1: the steps of the time grid of a loading history, the
                            ///< time over its expected end of contact in an impact (impact_progress)
    bool settled = true;    ///< no further step follows at this time (false inside a jump of the load; the initial
                            ///< state counts as settled)
    bool row = false;       ///< a written row of the result: the initial state, every numerics.output_every-th
                            ///< step and the last state
    bool last = false;      ///< the run's last state (its end, or an observer's stop)
    double layer_contact_radius = 0.0;  ///< a [m] on a [layer] (its drivers have no foundation); 0 on the
                                        ///< half-space: read contact_radius()
    const foundation::Foundation* foundation = nullptr;  ///< the MDR foundation after the step (null only on a
                                                         ///< [layer]): contact radius, elements in contact, line loads
    /// The contact radius a [m]: the foundation's (Foundation::contact_radius, a scan of its elements; 0 at zero
    /// force), or on a [layer] layer_contact_radius.
    double contact_radius() const;
};

/// Watches a run. For every state, in time order (the initial one first), the driver asks each observer whether to
/// stop, then hands the state to each observer's `observe`. The observers see the state after the standard ones
/// (which fill IndentationResult) have recorded it; they must not throw except to abandon the run.
class StepObserver {
public:
    virtual ~StepObserver() = default;
    /// The state at one time.
    virtual void observe(const StepState& state) = 0;
    /// Whether the run is to end with `state` (asked before `observe`; by default never). When an observer says
    /// yes, `state` becomes the last one (`last` and `row` set) and IndentationResult::stopped is true; the outcomes,
    /// which need the whole run (an impact's, the tangential and the harmonic one), are then left out.
    virtual bool stop(const StepState& state) {
        (void)state;
        return false;
    }
    /// Whether it must see the states of one run only (by default yes). A [layer]'s run of Ting's class finds only
    /// when it happens that the contact grows again, and the cells then run the case from the start
    /// (run_layer_indentation): it keeps its states and shows them to such an observer once it has ended in Ting's
    /// class (a stop then ends the result at its state as at once). An observer that only asks to stop (a sweep's)
    /// says no: it is asked at once, so that it can stop a long run at any step, and may be shown the states of
    /// Ting's run and then those of the cells' from the start.
    virtual bool needs_one_run() const { return true; }
};

/// Observers a caller attaches to a run (not owned; each must outlive the run; a null pointer is an
/// std::invalid_argument). The driver calls them after its standard ones, in this order.
using StepObservers = std::vector<StepObserver*>;

}  // namespace mdr::drivers
