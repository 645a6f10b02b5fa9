#include "cycle_measure.hpp"

#include <cmath>
#include <numbers>

#include "mdr/foundation/foundation.hpp"

namespace mdr::drivers {

CycleMeasure::CycleMeasure(const HarmonicLoad& harmonic, double simulated_end)
    : start_(harmonic.start),
      omega_(2.0 * std::numbers::pi * harmonic.frequency),
      cycle_(harmonic.last_full_cycle(simulated_end)) {}

void CycleMeasure::observe(const StepState& state) {
    const double time = state.time;
    const double depth = state.depth;
    const double force = state.force;
    const Sample sample{time, depth, force};
    // The cycle's bounds are nodes of the time grid (HarmonicLoad::breakpoints); the steps inside it are uniform.
    if (cycle_ && last_ && last_->time >= cycle_->first && time <= cycle_->second && time >= last_->time) {
        const double step = time - last_->time;
        const auto phasor = [&](double t) { return std::polar(1.0, -omega_ * (t - start_)); };
        // Trapezoidal rule: exact for a trigonometric polynomial below the step count on a uniform cycle.
        depth_sum_ += 0.5 * step * (last_->depth * phasor(last_->time) + depth * phasor(time));
        force_sum_ += 0.5 * step * (last_->force * phasor(last_->time) + force * phasor(time));
        work_ += 0.5 * (last_->force + force) * (depth - last_->depth);
        if (state.foundation->contact_count() == 0) lost_time_ += step;
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
