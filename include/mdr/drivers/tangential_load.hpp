#pragma once
/// \file
/// The tangential loading superimposed on a normal contact (handbook section 6): friction coefficient and the
/// prescribed tangential displacement u(t) or force F_x(t) of the indenter, piecewise-linear or harmonic.

#include "mdr/drivers/load.hpp"

namespace mdr::drivers {

/// What the tangential history prescribes.
enum class TangentialControl {
    displacement,  ///< tangential displacement u(t) [m] of the indenter
    force,         ///< total tangential force F_x(t) [N]; u is solved for each step
};

/// `[tangential]`: local Amontons-Coulomb friction (eq. 48-50) and the prescribed u(t) or F_x(t).
struct TangentialLoad {
    double friction = 0.0;                                        ///< mu >= 0
    TangentialControl control = TangentialControl::displacement;  ///< what `load` prescribes
    /// (t, u) or (t, F_x): a history without jumps or a harmonic, exactly one of the two (drivers::validate).
    Load load{};
};

}  // namespace mdr::drivers
