#pragma once
// The force of a rigid sphere pressed at constant speed into an incompressible half-space whose relaxation modulus is
// a power of time: the closed form the power-law and springpot tests check the drivers and the fits against.

#include <cmath>

namespace mdr::testing {

/// F(t) = 8 sqrt(R) v^(3/2) K Gamma(1 - beta) Gamma(3/2) / Gamma(5/2 - beta) t^(3/2 - beta) for the depth d = v t from
/// t = 0 and G(t) = K t^(-beta), 0 <= beta < 1: Lee & Radok (1960), F(t) = (16/3) sqrt(R) int_0^t G(t - s) d/ds
/// d(s)^(3/2) ds (Hertz's sphere, E* = 4 G), the integral a Beta function. A power law G0 (t/t0)^(-beta) has K = G0
/// t0^beta; a springpot of quasi-property c and order alpha has beta = alpha and K = c / Gamma(1 - alpha).
inline double power_law_sphere_ramp_force(double K, double beta, double R, double speed, double t) {
    return 8.0 * std::sqrt(R) * std::pow(speed, 1.5) * K * std::tgamma(1.0 - beta) * std::tgamma(1.5) /
           std::tgamma(2.5 - beta) * std::pow(t, 1.5 - beta);
}

}  // namespace mdr::testing
