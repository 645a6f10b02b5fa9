#pragma once
/// \file
/// A prescribed load: a piecewise-linear part and a harmonic part, either optional. The normal load (`[load]`:
/// a history, plus `harmonic`) and the tangential load (`[tangential]`: a history or a harmonic) are both one.

#include <optional>
#include <utility>
#include <vector>

#include "mdr/drivers/harmonic_load.hpp"
#include "mdr/drivers/load_history.hpp"

namespace mdr::drivers {

/// The value prescribed over time: the piecewise-linear history plus the harmonic, each optional (a normal load
/// has a history, drivers::validate; a tangential load has exactly one of the two).
struct Load {
    std::optional<LoadHistory> history{};   ///< piecewise-linear (t, value) points
    std::optional<HarmonicLoad> harmonic{}; ///< added to the history, or alone

    /// The prescribed value at time t [s]: the sum of the parts given.
    double value(double t) const;
    /// A bound of the largest prescribed value: the history's largest point plus the harmonic's |amplitude| (the
    /// history is required: a harmonic alone has no level to oscillate about).
    double largest_value() const;
    /// The prescribed rate at the start of a step from (t0, v0) to (t1, v1), t1 > t0, of values of this load: the
    /// history's slope over the step, (v1 - h(t1) - v0 + h(t0)) / (t1 - t0) with h the harmonic (0 without one),
    /// plus the harmonic's rate at t0. A dashpot's trapezoidal rate starts from it, second order where the secant
    /// rate of a sine would be first order at the nodes.
    double start_rate(double t0, double v0, double t1, double v1) const;
    /// Last time [s] at which a part changes: the later of the history's last point and the harmonic's end.
    double end_time() const;
    /// Times [s] the time grid must step on: the history's points, and the harmonic's start, end and the bounds of
    /// its last full cycle.
    std::vector<double> breakpoints() const;
    /// The harmonic's last full cycle [first, second] [s] ending no later than `simulated_end`; none without a
    /// harmonic or when not one full cycle fits.
    std::optional<std::pair<double, double>> last_full_cycle(double simulated_end) const;
};

}  // namespace mdr::drivers
