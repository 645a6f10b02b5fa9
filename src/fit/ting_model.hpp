#pragma once
/// \file
/// The force of the MDR foundation in its continuum limit (no elements, no discretisation in x) for a depth history
/// in Ting's class: the fast forward model of depth-driven fits (internal to mdr_fit).
///
/// Element x enters contact at t_x, when the depth first reaches g(x) (eq. 14, 15). While it stays in contact,
/// w1D = d(t) - g(x) (eq. 13): every element in contact has the rate d'(t), and its force per length is
/// 4 Psi(t_x, t) with Psi(t_x, t) = int_{t_x}^t G(t - s) d'(s) ds (eq. 16). While the contact radius grows (and
/// holds), the force is F(t) = 8 int_0^t G(t - s) a(s) d'(s) ds (eq. 21, Lee-Radok). Once it shrinks, the edge is the
/// element t_1 whose force has fallen to zero, Psi(t_1, t) = 0 (eq. 20), and F(t) = 8 int_0^{t_1} G(t - s) a(s) d'(s)
/// ds (Ting). For a Prony series each branch of G is a running sum over the steps, so a history of n points costs
/// O(n x branches) instead of O(n x elements), and the force is exact up to the quadrature of one step (relative
/// error ~1e-10).
///
/// Ting's class: Psi(t_1, t) is non-increasing in t_1 along the loading (dPsi/dt_1 = -G(t - t_1) d'(t_1) <= 0), so
/// an element that left contact has Psi <= 0 as long as the edge never moves outwards again, and then it cannot
/// come back into contact (its gap w_free - w1D = -int J(t - s) dPsi(s) stays positive, eq. 6). A history in which
/// the edge would move outwards again (reloading after an unloading, a hold after a partial unloading, a depth
/// that dips while it loads) is outside the class: the elements' own states decide it, and the model says so.

#include <optional>
#include <vector>

#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::fit {

/// True when the continuum model covers this material and indenter: no parallel dashpot, and a profile whose g is a
/// power law (Profile::power_law_exponent: closed-form g, contact radius smooth in the depth).
bool ting_model_applies(const rheology::Rheology& material, const profile::Profile& indenter);

/// What the continuum model gives for one depth history.
struct TingResponse {
    std::vector<double> force;  ///< F [N] at each time
    /// dF/dG_b at each time, per branch of the material: the equilibrium modulus first, then the Prony terms in the
    /// material's order ([branch][time]). The force is linear in the moduli for a fixed contact history; where the
    /// edge of a shrinking contact moves with them (Ting's condition) its motion is included.
    std::vector<std::vector<double>> modulus_derivatives;
};

/// The force [N] at each time of a depth history through the points (time[i], depth[i]) (linear between them,
/// times increasing, depth below the contact point: <= 0 out of contact), incompressible body of `material` (the
/// combined material of the case, eq. 8 and 56). A first depth > 0 is reached by a jump at the first time (as the
/// element model does). The depth is `depth[i] - depth_shift` (the measured depth below a contact point, taken in
/// place: the history is not copied). nullopt when the history is outside Ting's class or when !ting_model_applies.
/// Without `modulus_derivatives` the response has the force alone. Memory: the response, and while the contact grows
/// 2 doubles a step and branch, kept only when it shrinks later.
///
/// `preloaded`: a first depth d_0 > 0 is a relaxed preload instead of a jump (docs/theory.md §4d: every branch
/// relaxed under d_0 at time[0]); the force is then the change since time[0], F(t) - G_inf F_el(d_0) =
/// int_{t_0}^t G(t - s) dF_el(d(s)), and nullopt once the depth falls (the contact would shrink: band_model.hpp
/// covers that history).
std::optional<TingResponse> ting_forces(const rheology::Rheology& material, const profile::Profile& indenter,
                                        const std::vector<double>& time, const std::vector<double>& depth,
                                        double depth_shift = 0.0, bool modulus_derivatives = true,
                                        bool preloaded = false);

}  // namespace mdr::fit
