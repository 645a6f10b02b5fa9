#pragma once
/// \file
/// Ting's solution (Ting 1966; Graham 1965) for a triangular depth history, the reference for viscoelastic
/// unloading with a shrinking contact radius. Independent of the library's MDR code.

#include "reference/indenter.hpp"
#include "reference/prony_material.hpp"

namespace mdr::reference {

/// Power-law indenter (sphere, cone) driven by d(t) = v t for t ≤ t_m and d(t) = v (2 t_m − t) after, into a
/// Prony material. Element x (|x| < a) has been in contact since t_c(x) = g(x)/v and carries the force density
/// 4 Ψ(t, t_c), Ψ(t, t_c) = ∫_{t_c}^t G(t − τ) ḋ(τ) dτ (in closed form through Φ(s) = ∫_0^s G; the dashpot adds
/// η ḋ(t)). While a(t) decreases (t > t_m), a(t) = g⁻¹(v t1(t)) with Ψ(t, t1) = 0 (Ting's condition);
/// F(t) = 8 ∫_0^{a(t)} Ψ(t, t_c(x)) dx. Contact is lost at t_loss where Ψ(t, 0) = 0; F = 0 and a = 0 after it.
class TingSolution {
public:
    /// Validates the inputs (speed v [m/s] > 0, peak time t_m [s] > 0) and finds t_loss (Brent, 1e-13 t_m).
    TingSolution(PowerLawIndenter indenter, PronyMaterial material, double speed, double peak_time);

    /// Depth d(t) [m] of the triangular history.
    double depth(double t) const;
    /// Loading time t1(t) [s] of the element at the contact edge: t for t ≤ t_m; the root of Ψ(t, t1) = 0 in
    /// [0, t_m] (Brent to 1e-13 t_m) for t_m < t < t_loss; 0 from t_loss on.
    double edge_loading_time(double t) const;
    /// Contact radius a(t) = g⁻¹(v t1(t)) [m].
    double contact_radius(double t) const;
    /// Total normal force F(t) [N], the x integral by adaptive Gauss–Kronrod to 1e-13 relative.
    double force(double t) const;
    /// Time of contact loss t_loss [s], in [t_m, 2 t_m]; exactly 2 t_m for an elastic material.
    double contact_loss_time() const { return contact_loss_time_; }
    /// Ψ(t, t_c) = ∫_{t_c}^t G(t − τ) ḋ(τ) dτ [Pa·m] for 0 ≤ t_c ≤ min(t, t_m): the force per unit length of the
    /// element that entered contact at t_c, divided by 4.
    double element_memory(double t, double t_c) const;

private:
    PowerLawIndenter indenter_;
    PronyMaterial material_;
    double speed_;
    double peak_time_;
    double contact_loss_time_;
};

}  // namespace mdr::reference
