#pragma once
/// \file
/// A compressible viscoelastic half-space as the equivalent incompressible one (handbook section 7, eq. 56), and its
/// Poisson ratio where that is constant in time.

#include <optional>

#include "mdr/rheology/rheology.hpp"

namespace mdr::rheology {

/// The effective shear material of a half-space with shear rheology `shear` and bulk rheology `bulk` (eq. 56): the
/// shear material in series with one of operational modulus K(s) + G(s)/3, so that J_eff = J + J_B. The MDR maps
/// the normal contact of the compressible body exactly onto the incompressible one with this material.
Rheology compressible_effective(const Rheology& shear, const Rheology& bulk);

/// Relative deviation from K(t) = c G(t) that constant_poisson_ratio still takes for round-off (of a series converted
/// from a continuous model, say).
inline constexpr double proportional_tolerance = 1e-10;

/// The Poisson ratio nu = (3K - 2G) / (2 (3K + G)) of a body whose bulk relaxation is proportional to its shear
/// relaxation, K(t) = c G(t) at every t (the same relaxation times, the moduli, equilibrium moduli and viscosities in
/// the ratio c = K/G, each to proportional_tolerance): nu is then constant in time, -1 < nu < 0.5. nullopt when
/// K(t)/G(t) changes in time (sums of exponentials with distinct times are independent, so a ratio constant over any
/// time window is constant everywhere).
std::optional<double> constant_poisson_ratio(const Rheology& shear, const Rheology& bulk);

}  // namespace mdr::rheology
