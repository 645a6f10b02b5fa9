#include "layer_impact.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/numerics/monotone_root.hpp"
#include "impact_end.hpp"
#include "layer_stepping.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

IndentationResult run_layer_impact(const ContactCase& contact_case, const contact::LayerContact& layer,
                                   double unit_modulus, double largest_depth, const ResolvedNumerics& numerics,
                                   const ProgressObserver& progress, const StepObservers& observers) {
    IndentationResult result;
    result.numerics = numerics;
    const double mass = contact_case.impact()->mass;
    const double approach = contact_case.impact()->velocity;
    const double step = numerics.time_step;
    // A parallel dashpot sees the indenter's trapezoidal rate, the velocity below (docs/theory.md, section 3).
    LayerStepper stepper(
        contact_case.material, layer, unit_modulus, 0.0, largest_depth,
        {.trapezoidal = contact_case.material.viscosity() > 0.0, .start = approach, .indenter_motion = true});
    double time = 0.0, depth = 0.0, velocity = approach, force = 0.0;
    // The rows by the half-space's recorder, then the caller's observers; a stop ends the run with its state (and no
    // outcome).
    ObserverList observed(std::max<std::size_t>(contact_case.numerics.output_every, 1));
    RowRecorder rows(result, row_columns(contact_case.control));
    observed.add(rows);
    observed.add(observers);
    // Hands the state after step n to the observers; returns whether the run ends with it.
    const auto notify = [&](std::size_t n, const LayerStep& state) {
        StepState observed_state{.step = n,
                                 .time = time,
                                 .depth = depth,
                                 .force = force,
                                 .velocity = velocity,
                                 .fraction = std::min(time / numerics.time_limit, 1.0),
                                 .last = result.impact.has_value(),
                                 .layer_contact_radius = state.contact.contact_radius};
        return observed.notify(observed_state);
    };
    if (notify(0, stepper.current())) {
        result.stopped = true;
        return result;
    }
    for (std::size_t n = 1;; ++n) {
        require_before_end(time, numerics.time_limit, velocity);
        const double next_time = time + step;
        // Trapezoidal rule for m d'' = -F (eq. 37), as ImpactStepping: F(d1) + (4m/dt^2)(d1 - d0 - v0 dt) = -F0,
        // increasing in d1 in either phase (the force increases with the depth, theory.md "Layers").
        const double spring = inertial_stiffness(mass, step);
        const double anchor = depth + velocity * step;
        const auto solve = [&](auto&& trial) {
            const auto residual = [&](double d) { return trial(d).force + spring * (d - anchor) + force; };
            const double guess = anchor - force * step * step / (2.0 * mass);
            // The step's depth to 1e-13 of its increment, or the force to 5e-8 of itself (the contact solve's own
            // precision, theory.md "Layers"), whichever is coarser.
            const double scale = std::max(std::abs(velocity), 1e-9 * approach) * step;
            return numerics::monotone_root(residual, guess, residual(guess), scale,
                                           std::max(1e-13 * spring * scale, 5e-8 * force), 1e-15 * scale, false);
        };
        const LayerStep& now = stepper.current();
        const auto recede = [&] {
            return stepper.recede(next_time, solve([&](double d) { return stepper.recede(next_time, d); }));
        };
        // Over the depth in both phases, not over the radius (LayerStepper::grow_to): the going in and the coming out
        // then solve the contact alike (depth to 1e-8), and their work errors cancel. An elastic layer's 1 - e was
        // 1.4e-10 at 0.5 us, second order; with the going in exact by grow_to, 1.5e-9 (the coming out's alone).
        LayerStep next = now.phase == LayerPhase::receding
                             ? recede()
                             : stepper.grow(next_time, solve([&](double d) { return stepper.grow(next_time, d); }));
        if (now.phase == LayerPhase::growing && next.centre < now.centre) next = recede();
        if (next.grows_again) {
            throw InvalidInput("load.velocity", format_value(approach),
                               "the contact on the [layer] would grow again at t = " + format_value(next_time) +
                                   " s after it shrank: not built on a [layer] yet (issue 28)");
        }
        ++result.steps;
        require_steps_within_bound(contact_case, numerics, result.steps, time);
        double new_velocity = trapezoidal_velocity(depth, next.centre, velocity, step);
        if (next.phase == LayerPhase::lifted_off) {
            // The contact is lost inside the step where int_0^t G dd = 0 (eq. L12 with t1 at the start), the depth
            // linear over the step as in the stepper: the fraction found by bisection of that phase boundary; the
            // outcome by the half-space's rule (impact_outcome).
            const double depth_change = next.centre - depth;
            double inside = 0.0, outside = 1.0;
            for (int iteration = 0; iteration < 60 && outside - inside > 1e-13; ++iteration) {
                const double middle = 0.5 * (inside + outside);
                const bool lost =
                    stepper.recede(time + middle * step, depth + middle * depth_change).phase == LayerPhase::lifted_off;
                (lost ? outside : inside) = middle;
            }
            const double fraction = 0.5 * (inside + outside);
            result.impact = impact_outcome({.mass = mass, .approach = approach, .time = time, .time_step = step,
                                            .velocity = velocity, .force = force, .fraction = fraction});
            new_velocity = -result.impact->rebound_velocity;
        }
        stepper.commit(next);
        time = next_time;
        depth = next.centre;
        force = next.force;
        velocity = new_velocity;
        const bool ends = notify(n, next);
        if (progress) progress(std::min(time / numerics.time_limit, 1.0));
        if (ends) {
            result.stopped = observed.stopped();
            return result;
        }
    }
}

}  // namespace mdr::drivers
