#pragma once
/// \file
/// Impact of a rigid sphere on an incompressible viscoelastic half-space (handbook eq. 37-39) from the 3D theory,
/// without the MDR foundation: Lee–Radok while the contact radius grows, Ting (1966) while it shrinks. The equation
/// of motion m d'' = −F(t) becomes an integro-differential equation, integrated with memory variables of the Prony
/// series. Independent of the library's impact driver.

#include "reference/prony_material.hpp"

namespace mdr::reference {

/// Accuracy of sphere_impact_ting. The step is h = min(T_H / steps_per_contact_time,
/// τ_min / steps_per_relaxation_time), T_H the Hertz contact time at the instantaneous modulus G(0⁺) (the shortest
/// contact time of the material) and τ_min the shortest relaxation time. Observed convergence order 2 to 3 (the
/// d^{3/2} start and (T − t)^{3/2} end of the force cap RK4's 4); the defaults give e to ~1e-9 (see
/// tests/unit/reference/impact_ode_test.cpp).
struct ImpactOdeOptions {
    double steps_per_contact_time = 4000.0;   ///< RK4 steps per T_H [-]
    double steps_per_relaxation_time = 4.0;   ///< RK4 steps at least per τ_min [-] (resolves the memory)
};

/// Outcome of an impact (eq. 39).
struct ImpactOdeResult {
    double restitution;        ///< e = −v(T)/v0 [-]
    double contact_time;       ///< T, the time at which the contact is lost [s]
    double max_depth;          ///< d(t_m) [m], the deepest penetration
    double time_of_max_depth;  ///< t_m [s], where d' = 0 and the contact radius starts to shrink
};

/// Rigid sphere (mass m [kg], radius R [m]) hitting the half-space at speed v0 [m/s] > 0 at t = 0, quasi-static,
/// m d'' = −F (eq. 37), with K = 16 sqrt(R)/3, s = d^{3/2}:
/// - loading, d' > 0 (Lee–Radok): F = K ∫_0^t G(t − τ) s'(τ) dτ = K [G∞ s + η s' + Σ G_k h_k],
///   h_k(t) = ∫_0^t exp(−(t−τ)/τ_k) s'(τ) dτ; until t_m where d' = 0;
/// - unloading, t > t_m (Ting): the contact radius is the loading radius at t1(t) < t_m, the root of
///   ∫_{t1}^t G(t − τ) d'(τ) dτ = G∞ (d(t) − d(t1)) + η d'(t) + Σ G_k (q_k(t) − exp(−(t−t1)/τ_k) q_k(t1)) = 0,
///   q_k(t) = ∫_0^t exp(−(t−τ)/τ_k) d'(τ) dτ, and F = K ∫_0^{t1} G(t − τ) s'(τ) dτ
///   = K [G∞ s(t1) + Σ G_k exp(−(t−t1)/τ_k) h_k(t1)];
/// - the contact ends at T when no t1 > 0 remains: G∞ d(T) + η d'(T) + Σ G_k q_k(T) = 0; e = −d'(T)/v0 (eq. 39).
/// Classical RK4 on a uniform step (the loading phase in the variables d, P = d' + K η s/m and
/// g_k = ∫ exp(−(t−τ)/τ_k) s dτ, h_k = s − g_k/τ_k, whose right-hand sides have no sqrt(t) singularity at impact),
/// the loading history tabulated at the steps and interpolated by cubic Hermite for t1 (Brent, 1e-14 t_m); t_m and
/// T located inside their step by Brent on the step fraction. Throws std::invalid_argument for m, R, v0 not > 0 or
/// an invalid material, std::runtime_error if the contact has not ended after 1000 T_H.
ImpactOdeResult sphere_impact_ting(const PronyMaterial& material, double mass, double radius, double velocity,
                                   const ImpactOdeOptions& options = {});

/// Hertz (elastic, shear modulus G [Pa], E* = 4G) contact time [s] of the same impact:
/// T = 2 (d_max/v0) ∫_0^1 (1 − x^{5/2})^{−1/2} dx = (4/5) B(2/5, 1/2) d_max/v0,
/// d_max = (15 m v0² / (16 E* sqrt(R)))^{2/5} (energy balance with F = (4/3) E* sqrt(R) d^{3/2}); equals
/// 2.8682656 (m² / (R E*² v0))^{1/5}.
double hertz_impact_time(double shear_modulus, double mass, double radius, double velocity);

}  // namespace mdr::reference
