#pragma once
/// \file
/// Coefficients of the exact exponential update of the foundation's internal variables over one time step.

#include <cmath>
#include <cstddef>
#include <vector>

#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {

/// For a branch G_k exp(-t/tau_k), the memory variable h_k(t) = int exp(-(t-s)/tau_k) w'(s) ds obeys
/// h_k' = w' - h_k/tau_k. For w linear over a step dt the update is exact (numerics notes, eq. 16 and 18):
///   h_k <- E_k h_k + B_k dw,  E_k = exp(-dt/tau_k),  B_k = (tau_k/dt)(1 - E_k).
/// The element "stress" (force per k_z dx, eq. 16) at the end of the step is
///   sigma = G_inf w_new + eta dw/dt + sum_k G_k h_k,new = relaxed + stiffness * dw
/// with relaxed = G_inf w_old + sum_k G_k E_k h_k,old and stiffness = G_inf + eta/dt + sum_k G_k B_k.
struct StepCoefficients {
    double time_step = 0.0;           ///< dt [s]; 0 for an instantaneous jump (only without a dashpot)
    std::vector<double> decay;        ///< E_k, one per branch
    std::vector<double> gain;         ///< B_k, one per branch
    double stiffness = 0.0;           ///< G_inf + eta/dt + sum_k G_k B_k [Pa], the modulus seen by dw
};

/// B = (1 - exp(-ratio)) / ratio for ratio = dt/tau >= 0 (1 at ratio = 0). expm1 keeps every digit for
/// ratio -> 0, where 1 - exp(-ratio) would cancel.
inline double branch_gain(double ratio) { return ratio > 0.0 ? -std::expm1(-ratio) / ratio : 1.0; }

/// The coefficients for a step of length `time_step` >= 0. B_k uses expm1, so it stays exact for dt << tau_k.
/// A zero step (a jump) needs a material without a parallel dashpot (eta = 0).
StepCoefficients step_coefficients(const rheology::Rheology& material, double time_step);

/// Same as step_coefficients, written into `out` without allocating when `out` already has the right size.
void fill_step_coefficients(const rheology::Rheology& material, double time_step, StepCoefficients& out);

/// Copies `from` into `to`, element by element when their branch counts agree (a foundation's step of a contact
/// law: no library call per vector), else by assignment (which may allocate).
inline void copy_step_coefficients(const StepCoefficients& from, StepCoefficients& to) {
    if (&from == &to) return;
    to.time_step = from.time_step;
    to.stiffness = from.stiffness;
    const std::size_t branches = from.decay.size();
    if (to.decay.size() != branches || to.gain.size() != branches) {
        to.decay = from.decay;
        to.gain = from.gain;
        return;
    }
    for (std::size_t k = 0; k < branches; ++k) {
        to.decay[k] = from.decay[k];
        to.gain[k] = from.gain[k];
    }
}

}  // namespace mdr::foundation
