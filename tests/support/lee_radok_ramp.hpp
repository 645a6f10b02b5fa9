#pragma once
// The Lee-Radok force of a standard solid under a depth ramped to its end at t = 1 and held, by direct
// quadrature: the reference the layer's viscoelastic tests check the drivers against.

#include <functional>
#include <vector>

namespace mdr::testing {

/// F(t) = G_inf F_el(t) + G1 [F_el(t) - (1/tau) int_0^t exp(-(t - s)/tau) F_el(s) ds] (Lee & Radok 1960, integrated
/// by parts with F_el(0) = 0) for G(t) = G_inf + G1 exp(-t/tau) and the elastic force F_el(s) at unit modulus of a
/// depth ramped over 0 <= s <= 1 and held after: composite 8-point Gauss-Legendre on 100 panels over the ramp, the
/// hold in closed form.
double ramp_and_hold_force(double t, double g_inf, double g1, double tau, const std::function<double(double)>& elastic);

/// The same force at each of ascending `times` >= 0, the integral carried from each time to the next, I(t_i) =
/// exp(-(t_i - t_{i-1})/tau) I(t_{i-1}) + int_{t_{i-1}}^{t_i} exp(-(t_i - s)/tau) F_el(s) ds (exact for the
/// exponential kernel), each step by 8-point Gauss-Legendre, split at the ramp's end: for many times at once, F_el
/// called 9 times a step rather than 801 times a time. `elastic` must be smooth on each step of the ramp.
std::vector<double> ramp_and_hold_forces(const std::vector<double>& times, double g_inf, double g1, double tau,
                                         const std::function<double(double)>& elastic);

}  // namespace mdr::testing
