#include "layer_cells_impact.hpp"

#include <algorithm>

#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "impact_clock.hpp"
#include "impact_end.hpp"
#include "layer_cells.hpp"
#include "layer_snapshot.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

IndentationResult run_layer_cells_impact(const ContactCase& contact_case, double largest_radius,
                                         const ProgressObserver& progress, const StepObservers& observers) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const std::size_t cells = contact_case.numerics.elements.value_or(default_layer_cells);
    result.numerics.elements = cells;
    result.numerics.half_width = largest_radius;  // reported: the cells' range
    const ResolvedNumerics& numerics = result.numerics;
    LayerCells layer(contact_case.material, *contact_case.layer, layer_poisson_ratio(contact_case),
                     *contact_case.indenter, largest_radius, cells);
    const double mass = contact_case.impact()->mass, approach = contact_case.impact()->velocity;
    ImpactClock clock(contact_case.snapshots, numerics.time_step);
    double depth = 0.0, velocity = approach, force = 0.0, contact_radius = 0.0;
    CellRunObservers run_observers(contact_case, layer, result, observers);
    ObserverList& observed = run_observers.list();
    // Hands the state after step n to the observers; returns whether the run ends.
    const auto notify = [&](std::size_t n) {
        StepState state{.step = n,
                        .time = clock.time(),
                        .depth = depth,
                        .force = force,
                        .velocity = velocity,
                        .fraction = std::min(clock.time() / numerics.time_limit, 1.0),
                        .last = result.impact.has_value(),
                        .layer_contact_radius = contact_radius};
        return observed.notify(state);
    };
    if (notify(0)) {
        result.stopped = true;
        return result;
    }
    for (std::size_t n = 1;; ++n) {
        require_before_end(clock.time(), numerics.time_limit, velocity);
        const double step = clock.step();  // landing exactly on the snapshot times, as the half-space impact
        // Trapezoidal rule for m d'' = -F (eq. 37), as ImpactStepping: F(d1) + (4m/dt^2)(d1 - d0 - v0 dt) = -F0.
        const double spring = inertial_stiffness(mass, step);
        const LayerCellState state = layer.step_inertial(step, spring * (depth + velocity * step) - force, spring,
                                                         velocity);
        ++result.steps;
        require_steps_within_bound(contact_case, numerics, result.steps, clock.time());
        double new_velocity = trapezoidal_velocity(depth, state.depth, velocity, step);
        if (state.force == 0.0 && force > 0.0) {
            // The contact shrinks to the axis and is lost where the edge function there (eq. L19) crosses zero,
            // located linearly over the step (LayerCellState::touching_part; the step's end if the axis still
            // touches without a cell in contact).
            const double fraction = state.touching ? 1.0 : state.touching_part.second;
            result.impact = impact_outcome({.mass = mass, .approach = approach, .time = clock.time(),
                                            .time_step = step, .velocity = velocity, .force = force,
                                            .fraction = fraction});
            new_velocity = -result.impact->rebound_velocity;
        }
        clock.advance();
        depth = state.depth;
        force = state.force;
        velocity = new_velocity;
        contact_radius = state.contact_radius;
        const bool ends = notify(n);
        if (progress) progress(std::min(clock.time() / numerics.time_limit, 1.0));
        if (ends) {
            result.stopped = observed.stopped();
            return result;
        }
    }
}

}  // namespace mdr::drivers
