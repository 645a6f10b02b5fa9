#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "oblique_stepping.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"
#include "stepping.hpp"

namespace mdr::drivers {

IndentationResult run_impact(const ContactCase& contact_case, const ProgressObserver& progress,
                             const StepObservers& extra_observers) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    const auto& indenter = *contact_case.indenter;
    const ImpactControl& impact = std::get<ImpactControl>(contact_case.control);
    const double mass = impact.mass;
    const double approach = impact.velocity;
    foundation::Foundation foundation(contact_case.material, indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    CoefficientCache cache(contact_case.material);
    std::optional<ObliqueStepper> oblique;
    if (impact.oblique) {
        oblique.emplace(*impact.oblique, oblique_sphere(contact_case), mass, contact_case.material, foundation);
    }

    double time = 0.0, depth = 0.0, velocity = approach, force = 0.0;
    std::array<double, 2> inner_exits{-1.0, -1.0};  // when the two innermost elements last left contact

    // The standard observers fill the result; the caller's follow them.
    ObserverList observers(numerics.output_every);
    RowRecorder rows(result, {.velocity = true, .base = false});
    observers.add(rows);
    std::optional<TangentialColumns<ObliqueStepper>> oblique_columns;
    if (oblique) observers.add(oblique_columns.emplace(*oblique, result));
    SnapshotRecorder::ShearStress shear_stress;
    if (oblique) shear_stress = [&](Snapshot& snapshot) { oblique->add_shear_stress(snapshot); };
    SnapshotRecorder snapshots(contact_case.snapshots, indenter, result, std::move(shear_stress));
    observers.add(snapshots);
    std::optional<ProgressReport> progress_report;
    if (progress) observers.add(progress_report.emplace(progress));
    observers.add(extra_observers);
    // The state after `step` steps, the last one when the contact has ended.
    const auto notify = [&](std::size_t step, bool ended) {
        StepState state{.step = step, .time = time, .depth = depth, .force = force, .velocity = velocity,
                        .fraction = std::min(time / numerics.time_limit, 1.0), .last = ended,
                        .foundation = &foundation};
        return observers.notify(state);
    };
    if (notify(0, false)) {
        result.stopped = true;
        return result;
    }
    for (std::size_t n = 1;; ++n) {
        if (time >= numerics.time_limit) {
            throw InvalidInput("load.end", format_value(numerics.time_limit),
                               "the contact has not ended by then (velocity v = " + format_value(velocity) +
                                   "): the indenter does not rebound in time; give a later load.end");
        }
        // Land exactly on snapshot times (the recorder takes each at the first state at or after it).
        const auto snapshot_time = snapshots.next_time();
        const double step = snapshot_time ? std::min(numerics.time_step, *snapshot_time - time) : numerics.time_step;
        foundation.begin_step(cache.get(step), velocity);
        // Trapezoidal rule for m d'' = -F (eq. 37): d1 = d0 + (v0 + v1) dt/2, v1 = v0 - (F0 + F1) dt/(2m), i.e.
        // F(d1) + (4m/dt^2)(d1 - d0 - v0 dt) = -F0, monotone in d1.
        const double spring = 4.0 * mass / (step * step);
        const double anchor = depth + velocity * step;
        const double guess = anchor - force * step * step / (2.0 * mass);
        // The depth increment of the step, never below a billionth of the approach increment: scales with the
        // impact itself (not with the half-width), so that a slow impact is solved as precisely as a fast one.
        const double scale = std::max(std::abs(velocity), 1e-9 * approach) * step;
        const double new_depth = solve_depth(foundation, depth, guess, scale, -force, spring, anchor);
        foundation.advance(depth, new_depth);
        for (std::size_t i = 0; i < inner_exits.size(); ++i) {
            if (foundation.inner_exit(i) >= 0.0) inner_exits[i] = time + foundation.inner_exit(i) * step;
        }
        const double new_force = foundation.total_force();
        double new_velocity = 2.0 * (new_depth - depth) / step - velocity;
        ++result.steps;
        require_steps_within_bound(contact_case, numerics, result.steps, time);

        if (new_force == 0.0 && force > 0.0) {
            // Every element has left (eq. 39): the last one left where its force crossed zero inside the step
            // (located by the foundation); the impulse of that part of the step is taken as a linear decay.
            const double fraction = foundation.latest_exit();
            new_velocity = velocity - force * fraction * step / (2.0 * mass);
            ImpactOutcome outcome;
            // Where the contact shrinks to the axis, the exit times of the two innermost elements are linear in
            // g near it, so extrapolated there (Foundation::axis_weight) they give the end to O(dx^2), where the
            // innermost element's own exit is only O(dx) for a cone.
            outcome.contact_time = time + fraction * step;
            const bool axis_last = foundation.inner_exit(0) == fraction;  // not an annulus leaving last
            if (axis_last && inner_exits[1] >= 0.0 && inner_exits[1] < inner_exits[0]) {
                outcome.contact_time += foundation.axis_weight() * (inner_exits[1] - inner_exits[0]);
            }
            outcome.rebound_velocity = -new_velocity;
            outcome.restitution = -new_velocity / approach;
            outcome.dissipated_energy = 0.5 * mass * (approach * approach - new_velocity * new_velocity);
            if (oblique) {
                oblique->finish(cache.get(step), step, fraction);
                outcome.oblique = oblique->outcome(outcome, approach);
                outcome.dissipated_energy += oblique->kinetic_energy_lost();
            }
            // A passive body returns at most the energy it was given (e <= 1), and the indenter leaves (e >= 0);
            // beyond round-off anything else is a failure of the numerics, never a result.
            if (!(outcome.restitution >= 0.0 && outcome.restitution <= 1.0 + 1e-6)) {
                throw std::runtime_error(fmt::format(
                    "the impact is not resolved at these numerics: restitution e = {} lies outside [0, 1]; give a "
                    "smaller numerics.time_step (now {:.4g} s) or more numerics.elements",
                    outcome.restitution, step));
            }
            result.impact = outcome;
            time += step;
            depth = new_depth;
            force = new_force;
            velocity = new_velocity;
            notify(n, true);
            return result;
        }
        if (oblique) oblique->step(cache.get(step), step);
        time += step;
        depth = new_depth;
        force = new_force;
        velocity = new_velocity;
        if (notify(n, false)) {
            result.stopped = true;  // the outcome needs the whole impact
            return result;
        }
    }
}

IndentationResult run_case(const ContactCase& contact_case, const ProgressObserver& progress,
                           const StepObservers& observers) {
    auto result = contact_case.layer    ? run_layer_indentation(contact_case, progress, observers)
                  : contact_case.impact() ? run_impact(contact_case, progress, observers)
                                          : run_indentation(contact_case, progress, observers);
    require_finite_result(result);
    return result;
}

}  // namespace mdr::drivers
