#include "layer_impact.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/monotone_root.hpp"
#include "impact_end.hpp"

namespace mdr::drivers {

LayerImpactStepping::LayerImpactStepping(const ContactCase& contact_case, const ImpactControl& impact,
                                         const contact::LayerContact& layer, double unit_modulus,
                                         double largest_depth, const ResolvedNumerics& numerics)
    : contact_case_(contact_case),
      numerics_(numerics),
      mass_(impact.mass),
      approach_(impact.velocity),
      // A parallel dashpot sees the indenter's trapezoidal rate, the velocity below (docs/theory.md, section 3).
      stepper_(contact_case.material, layer, unit_modulus, 0.0, largest_depth,
               {.trapezoidal = contact_case.material.viscosity() > 0.0, .start = impact.velocity,
                .indenter_motion = true}),
      velocity_(impact.velocity) {}

StepState LayerImpactStepping::state(std::size_t n, const LayerStep& step) const {
    return {.step = n,
            .time = time_,
            .depth = depth_,
            .force = force_,
            .velocity = velocity_,
            .fraction = impact_progress(time_, outcome_.has_value(), numerics_),
            .last = outcome_.has_value(),
            .layer_contact_radius = step.contact.contact_radius};
}

StepState LayerImpactStepping::step(std::size_t n) {
    require_before_end(time_, numerics_.time_limit, velocity_);
    const double step = numerics_.time_step;
    const double next_time = time_ + step;
    // Trapezoidal rule for m d'' = -F (eq. 37), as ImpactStepping: F(d1) + (4m/dt^2)(d1 - d0 - v0 dt) = -F0,
    // increasing in d1 in either phase (the force increases with the depth, theory.md "Layers").
    const double spring = inertial_stiffness(mass_, step);
    const double anchor = depth_ + velocity_ * step;
    const auto solve = [&](auto&& trial) {
        const auto residual = [&](double d) { return trial(d).force + spring * (d - anchor) + force_; };
        const double guess = anchor - force_ * step * step / (2.0 * mass_);
        // The step's depth to 1e-13 of its increment, or the force to 5e-8 of itself (the contact solve's own
        // precision, theory.md "Layers"), whichever is coarser.
        const double scale = std::max(std::abs(velocity_), 1e-9 * approach_) * step;
        return numerics::monotone_root(residual, guess, residual(guess), scale,
                                       std::max(1e-13 * spring * scale, 5e-8 * force_), 1e-15 * scale, false);
    };
    const LayerStep& now = stepper_.current();
    const auto recede = [&] {
        return stepper_.recede(next_time, solve([&](double d) { return stepper_.recede(next_time, d); }));
    };
    // Over the depth in both phases, not over the radius (LayerStepper::grow_to): the going in and the coming out
    // then solve the contact alike (depth to 1e-8), and their work errors cancel. An elastic layer's 1 - e was
    // 1.4e-10 at 0.5 us, second order; with the going in exact by grow_to, 1.5e-9 (the coming out's alone).
    LayerStep next = now.phase == LayerPhase::receding
                         ? recede()
                         : stepper_.grow(next_time, solve([&](double d) { return stepper_.grow(next_time, d); }));
    if (now.phase == LayerPhase::growing && next.centre < now.centre) next = recede();
    if (next.grows_again) {
        throw InvalidInput("load.velocity", format_value(approach_),
                           "the contact on the [layer] would grow again at t = " + format_value(next_time) +
                               " s after it shrank: not built on a [layer] yet (issue 28)");
    }
    require_steps_within_bound(contact_case_, numerics_, n, time_);
    double new_velocity = trapezoidal_velocity(depth_, next.centre, velocity_, step);
    if (next.phase == LayerPhase::lifted_off) {
        // The contact is lost inside the step where int_0^t G dd = 0 (eq. L12 with t1 at the start), the depth
        // linear over the step as in the stepper: the fraction found by bisection of that phase boundary; the
        // outcome by the half-space's rule (impact_outcome).
        const double depth_change = next.centre - depth_;
        double inside = 0.0, outside = 1.0;
        for (int iteration = 0; iteration < 60 && outside - inside > 1e-13; ++iteration) {
            const double middle = 0.5 * (inside + outside);
            const bool lost =
                stepper_.recede(time_ + middle * step, depth_ + middle * depth_change).phase == LayerPhase::lifted_off;
            (lost ? outside : inside) = middle;
        }
        const double fraction = 0.5 * (inside + outside);
        outcome_ = impact_outcome({.mass = mass_, .approach = approach_, .time = time_, .time_step = step,
                                   .velocity = velocity_, .force = force_, .fraction = fraction});
        new_velocity = -outcome_->rebound_velocity;
    }
    stepper_.commit(next);
    time_ = next_time;
    depth_ = next.centre;
    force_ = next.force;
    velocity_ = new_velocity;
    return state(n, next);
}

}  // namespace mdr::drivers
