#include "impact_stepping.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/drivers/oblique_sphere.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "impact_end.hpp"

namespace mdr::drivers {

ImpactStepping::ImpactStepping(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                               foundation::Foundation& foundation, const ImpactControl& impact)
    : contact_case_(contact_case),
      numerics_(numerics),
      foundation_(foundation),
      mass_(impact.mass),
      approach_(impact.velocity),
      cache_(contact_case.material),
      cuts_(contact_case.snapshots),
      velocity_(impact.velocity) {
    std::sort(cuts_.begin(), cuts_.end());
    if (impact.oblique) {
        oblique_.emplace(*impact.oblique, oblique_sphere(contact_case), mass_, contact_case.material, foundation);
    }
}

void ImpactStepping::add_observers(ObserverList& observers, IndentationResult& result) {
    if (oblique_) observers.add(oblique_columns_.emplace(*oblique_, result));
}

SnapshotRecorder::ShearStress ImpactStepping::shear_stress() {
    if (!oblique_) return {};
    return [this](Snapshot& snapshot) { oblique_->add_shear_stress(snapshot); };
}

StepState ImpactStepping::state(std::size_t step, bool ended) const {
    return {.step = step, .time = time_, .depth = depth_, .force = force_, .velocity = velocity_,
            .fraction = std::min(time_ / numerics_.time_limit, 1.0), .last = ended, .foundation = &foundation_};
}

StepState ImpactStepping::step(std::size_t n) {
    if (time_ >= numerics_.time_limit) {
        throw InvalidInput("load.end", format_value(numerics_.time_limit),
                           "the contact has not ended by then (velocity v = " + format_value(velocity_) +
                               "): the indenter does not rebound in time; give a later load.end");
    }
    // Land exactly on snapshot times (the recorder takes each at the first state at or after it).
    while (next_cut_ < cuts_.size() && cuts_[next_cut_] <= time_) ++next_cut_;
    const double step = next_cut_ < cuts_.size() ? std::min(numerics_.time_step, cuts_[next_cut_] - time_)
                                                 : numerics_.time_step;
    foundation_.begin_step(cache_.get(step), velocity_);
    // Trapezoidal rule for m d'' = -F (eq. 37): d1 = d0 + (v0 + v1) dt/2, v1 = v0 - (F0 + F1) dt/(2m), i.e.
    // F(d1) + (4m/dt^2)(d1 - d0 - v0 dt) = -F0, monotone in d1.
    const double spring = 4.0 * mass_ / (step * step);
    const double anchor = depth_ + velocity_ * step;
    const double guess = anchor - force_ * step * step / (2.0 * mass_);
    // The depth increment of the step, never below a billionth of the approach increment: scales with the
    // impact itself (not with the half-width), so that a slow impact is solved as precisely as a fast one.
    const double scale = std::max(std::abs(velocity_), 1e-9 * approach_) * step;
    const double new_depth = solve_depth(foundation_, depth_, guess, scale, -force_, spring, anchor);
    foundation_.advance(depth_, new_depth);
    for (std::size_t i = 0; i < inner_exits_.size(); ++i) {
        if (foundation_.inner_exit(i) >= 0.0) inner_exits_[i] = time_ + foundation_.inner_exit(i) * step;
    }
    const double new_force = foundation_.total_force();
    require_steps_within_bound(contact_case_, numerics_, n, time_);
    // The stop rule: every element has left (eq. 39).
    const bool ended = new_force == 0.0 && force_ > 0.0;
    const double new_velocity = ended ? end_contact(step) : 2.0 * (new_depth - depth_) / step - velocity_;
    if (oblique_ && !ended) oblique_->step(cache_.get(step), step);
    time_ += step;
    depth_ = new_depth;
    force_ = new_force;
    velocity_ = new_velocity;
    return state(n, ended);
}

double ImpactStepping::end_contact(double time_step) {
    // The last element left where its force crossed zero inside the step (located by the foundation).
    const double fraction = foundation_.latest_exit();
    ImpactOutcome outcome = impact_outcome({.mass = mass_, .approach = approach_, .time = time_, .time_step = time_step,
                                            .velocity = velocity_, .force = force_, .fraction = fraction});
    // Where the contact shrinks to the axis, the exit times of the two innermost elements are linear in g near it,
    // so extrapolated there (Foundation::axis_weight) they give the end to O(dx^2), where the innermost element's
    // own exit is only O(dx) for a cone.
    const bool axis_last = foundation_.inner_exit(0) == fraction;  // not an annulus leaving last
    if (axis_last && inner_exits_[1] >= 0.0 && inner_exits_[1] < inner_exits_[0]) {
        outcome.contact_time += foundation_.axis_weight() * (inner_exits_[1] - inner_exits_[0]);
    }
    if (oblique_) {
        oblique_->finish(cache_.get(time_step), time_step, fraction);
        outcome.oblique = oblique_->outcome(outcome, approach_);
        outcome.dissipated_energy += oblique_->kinetic_energy_lost();
    }
    outcome_ = outcome;
    return -outcome.rebound_velocity;
}

}  // namespace mdr::drivers
