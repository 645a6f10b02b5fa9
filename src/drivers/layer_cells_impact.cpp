#include "layer_cells_impact.hpp"

#include <algorithm>

#include "mdr/drivers/work_estimate.hpp"
#include "impact_end.hpp"
#include "layer_cells_run.hpp"

namespace mdr::drivers {

LayerCellsImpactStepping::LayerCellsImpactStepping(const ContactCase& contact_case, const ImpactControl& impact,
                                                   LayerCells& cells, const ResolvedNumerics& numerics)
    : contact_case_(contact_case),
      numerics_(numerics),
      cells_(cells),
      mass_(impact.mass),
      approach_(impact.velocity),
      clock_(contact_case.snapshots, numerics.time_step),
      velocity_(impact.velocity) {}

StepState LayerCellsImpactStepping::state(std::size_t n) const {
    return {.step = n,
            .time = clock_.time(),
            .depth = depth_,
            .force = force_,
            .velocity = velocity_,
            .fraction = impact_progress(clock_.time(), outcome_.has_value(), numerics_),
            .last = outcome_.has_value(),
            .layer_contact_radius = contact_radius_};
}

StepState LayerCellsImpactStepping::step(std::size_t n) {
    require_before_end(clock_.time(), numerics_.time_limit, velocity_);
    const double step = clock_.step();  // landing exactly on the snapshot times, as the half-space impact
    // Trapezoidal rule for m d'' = -F (eq. 37), as ImpactStepping: F(d1) + (4m/dt^2)(d1 - d0 - v0 dt) = -F0.
    const double spring = inertial_stiffness(mass_, step);
    const LayerCellState state =
        cells_.step_inertial(step, spring * (depth_ + velocity_ * step) - force_, spring, velocity_);
    require_steps_within_bound(contact_case_, numerics_, n, clock_.time());
    double new_velocity = trapezoidal_velocity(depth_, state.depth, velocity_, step);
    if (state.force == 0.0 && force_ > 0.0) {
        // The contact shrinks to the axis and is lost where the edge function there (eq. L19) crosses zero,
        // located linearly over the step (LayerCellState::touching_part; the step's end if the axis still
        // touches without a cell in contact).
        const double fraction = state.touching ? 1.0 : state.touching_part.second;
        outcome_ = impact_outcome({.mass = mass_, .approach = approach_, .time = clock_.time(), .time_step = step,
                                   .velocity = velocity_, .force = force_, .fraction = fraction});
        new_velocity = -outcome_->rebound_velocity;
    }
    clock_.advance();
    depth_ = state.depth;
    force_ = state.force;
    velocity_ = new_velocity;
    contact_radius_ = state.contact_radius;
    return this->state(n);
}

IndentationResult run_layer_cells_impact(const ContactCase& contact_case, const ImpactControl& impact,
                                         double largest_radius, const ProgressObserver& progress,
                                         const StepObservers& observers) {
    return run_on_layer_cells<LayerCellsImpactStepping>(contact_case, impact, largest_radius, progress, observers);
}

}  // namespace mdr::drivers
