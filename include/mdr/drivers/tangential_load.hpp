#pragma once
/// \file
/// The tangential loading superimposed on a normal contact (handbook section 6): friction coefficient and the
/// prescribed tangential displacement u(t) or force F_x(t) of the indenter, piecewise-linear or harmonic.

#include <optional>
#include <vector>

#include "mdr/drivers/harmonic_load.hpp"
#include "mdr/drivers/load_history.hpp"

namespace mdr::drivers {

/// What the tangential history prescribes.
enum class TangentialControl {
    displacement,  ///< tangential displacement u(t) [m] of the indenter
    force,         ///< total tangential force F_x(t) [N]; u is solved for each step
};

/// `[tangential]`: local Amontons-Coulomb friction (eq. 48-50) and one of a history or a harmonic.
struct TangentialLoad {
    double friction = 0.0;                           ///< mu >= 0
    TangentialControl control = TangentialControl::displacement;
    std::optional<LoadHistory> history;              ///< piecewise-linear (t, u) or (t, F_x), without jumps
    std::optional<HarmonicLoad> harmonic;            ///< or a harmonic; exactly one of the two is set

    /// The prescribed value (u [m] or F_x [N]) at time t [s].
    double value(double t) const;
    /// Last time [s] at which the prescribed value changes.
    double end_time() const;
    /// Times [s] the time grid must step on: the history points, or the harmonic's start, end and the bounds of
    /// its last full cycle.
    std::vector<double> breakpoints() const;
    /// The last full harmonic cycle [first, second] [s] ending no later than `simulated_end`; none for a history
    /// or when not one full cycle fits.
    std::optional<std::pair<double, double>> last_full_cycle(double simulated_end) const;
};

}  // namespace mdr::drivers
