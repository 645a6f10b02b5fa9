#include "cycle_measure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mdr/foundation/foundation.hpp"

namespace mdr::drivers {
namespace {

// The part [first, second] (fractions 0..1) of the last step with some element in contact, from the contact at its
// start and end: a loss or a regain is located inside the step where the foundation located the last exit (the
// force crossing zero) or the first entry (the gap closing), by linear interpolation of the crossing quantity
// (second order; numerics-notes, events inside a step).
std::pair<double, double> touching_part_of_step(bool touching_before, bool touching_after,
                                                const foundation::Foundation& foundation) {
    if (touching_before) return {0.0, touching_after ? 1.0 : foundation.latest_exit()};
    if (!touching_after) return {0.0, 0.0};
    double first_entry = 1.0;
    for (const foundation::Entry& entry : foundation.entries()) first_entry = std::min(first_entry, entry.fraction);
    return {first_entry, 1.0};
}

}  // namespace

CycleMeasure::CycleMeasure(const HarmonicLoad& harmonic, double simulated_end)
    : start_(harmonic.start),
      omega_(2.0 * std::numbers::pi * harmonic.frequency),
      cycle_(harmonic.last_full_cycle(simulated_end)) {}

void CycleMeasure::observe(const StepState& state) {
    const foundation::Foundation& foundation = *state.foundation;
    const bool touching = foundation.contact_count() > 0;
    const auto part = last_ ? touching_part_of_step(last_->touching, touching, foundation)
                            : std::pair<double, double>{0.0, 0.0};
    record(state.time, state.depth, state.force, touching, part);
}

void CycleMeasure::record(double time, double depth, double force, bool touching,
                          std::pair<double, double> touching_part) {
    const Sample sample{time, depth, force, touching};
    // The cycle's bounds are nodes of the time grid (HarmonicLoad::breakpoints); the steps inside it are uniform.
    if (cycle_ && last_ && last_->time >= cycle_->first && time <= cycle_->second && time >= last_->time) {
        const double step = time - last_->time;
        const auto phasor = [&](double t) { return std::polar(1.0, -omega_ * (t - start_)); };
        // Trapezoidal rule: exact for a trigonometric polynomial below the step count on a uniform cycle.
        depth_sum_ += 0.5 * step * (last_->depth * phasor(last_->time) + depth * phasor(time));
        // The force is zero out of contact. It falls to zero continuously at a loss, but may jump at a regain (a
        // dashpot meeting the surface at a different rate): there it is taken as the step's end value from the
        // entry on, so that the jump's place inside the step is kept (second order; a trapezoid over the whole
        // step would be first order).
        const auto [first, second] = touching_part;
        const double t_first = last_->time + first * step, t_second = last_->time + second * step;
        const double force_first = first > 0.0 ? force : last_->force;
        const double force_second = second < 1.0 ? 0.0 : force;
        const double depth_change = (second - first) * (depth - last_->depth);
        force_sum_ += 0.5 * (t_second - t_first) * (force_first * phasor(t_first) + force_second * phasor(t_second));
        work_ += 0.5 * (force_first + force_second) * depth_change;
        lost_time_ += step - (t_second - t_first);
    }
    last_ = sample;
}

std::optional<HarmonicOutcome> CycleMeasure::outcome() const {
    if (!cycle_) return std::nullopt;
    const double period = cycle_->second - cycle_->first;
    const std::complex<double> depth = 2.0 / period * depth_sum_;
    const std::complex<double> force = 2.0 / period * force_sum_;
    HarmonicOutcome outcome;
    outcome.depth_amplitude = std::abs(depth);
    outcome.force_amplitude = std::abs(force);
    outcome.dissipated_energy = work_;
    outcome.contact_loss_fraction = lost_time_ / period;
    if (outcome.depth_amplitude > 0.0) {
        const std::complex<double> stiffness = force / depth;
        outcome.phase = std::arg(stiffness);
        outcome.storage_stiffness = stiffness.real();
        outcome.loss_stiffness = stiffness.imag();
        if (stiffness.real() != 0.0) outcome.loss_tangent = stiffness.imag() / stiffness.real();
    }
    return outcome;
}

}  // namespace mdr::drivers
