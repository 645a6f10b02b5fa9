#pragma once
/// \file
/// The harmonic part of a load, shared by the normal load (added to its piecewise-linear history) and the
/// tangential load: a sine between a start and an end time, and the last full cycle the results are measured on.

#include <optional>
#include <utility>
#include <vector>

namespace mdr::drivers {

/// A harmonic load: value = amplitude sin(2 pi frequency (t - start)) for start <= t <= end, 0 before start, held
/// at its end value after end.
struct HarmonicLoad {
    double amplitude;  ///< depth [m], force [N], base displacement [m], u0 [m] or F0 [N]
    double frequency;  ///< f [Hz] > 0
    double start;      ///< [s]
    double end;        ///< [s] > start

    /// The harmonic value at time t [s].
    double value(double t) const;
    /// The harmonic's rate d value / dt [unit/s] just after time t (from the right): 2 pi f amplitude
    /// cos(2 pi f (t - start)) for start <= t < end, else 0.
    double rate(double t) const;
    /// The period 1 / frequency [s].
    double period() const { return 1.0 / frequency; }
    /// Times [s] the time grid must step on: start, end and the bounds of the last full cycle.
    std::vector<double> breakpoints() const;
    /// The last full cycle [first, second] [s] ending no later than `simulated_end`; none when not one full cycle
    /// fits.
    std::optional<std::pair<double, double>> last_full_cycle(double simulated_end) const;
};

/// Steps per harmonic period when `[numerics] time_step` is not given (normal and tangential harmonics). With
/// the load linear between steps, the response's first harmonic is off by O((2 pi / 200)^2 / 12) ~ 8e-5 of its
/// viscous part at most (measured for a standard solid: below 1e-5 of |k| under displacement control, 6e-5 under
/// force control; tests/verification/test_harmonic_normal.cpp).
inline constexpr double default_steps_per_period = 200.0;

}  // namespace mdr::drivers
