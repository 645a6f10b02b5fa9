#pragma once
/// \file
/// The material of the reference solutions: a Prony series with an optional parallel dashpot, written
/// independently of the library's rheology module. Handbook Table 1: G(t) = G∞ + η δ(t) + Σ_k G_k exp(−t/τ_k).

#include <utility>
#include <vector>

namespace mdr::reference {

/// Shear relaxation function G(t) = G_inf + eta·δ(t) + Σ_k G_k exp(−t/τ_k) of an incompressible material.
/// Moduli in Pa, eta in Pa·s, relaxation times in s. Covers the elastic body (no terms, eta = 0), Kelvin–Voigt
/// (eta > 0), Maxwell (G_inf = 0, one term) and the standard solid (one term) of Table 1.
struct PronyMaterial {
    double G_inf = 0.0;                             ///< long-time modulus G∞ [Pa]
    double eta = 0.0;                               ///< parallel dashpot η [Pa·s] (the δ(t) part of G)
    std::vector<std::pair<double, double>> terms;   ///< (G_k [Pa], τ_k [s]) of the Maxwell branches

    /// Regular part of G(t) [Pa], t ≥ 0: G∞ + Σ G_k exp(−t/τ_k) (the dashpot's δ(t) excluded).
    double relaxation(double t) const;
    /// Φ(s) = ∫_0^s of the regular part of G [Pa·s]: G∞ s + Σ G_k τ_k (1 − exp(−s/τ_k)), computed with expm1.
    double relaxation_integral(double s) const;
    /// Throws std::invalid_argument unless all moduli ≥ 0, τ_k > 0, eta ≥ 0 and G(0⁺) > 0.
    void validate() const;
};

/// Creep function J(t) [1/Pa] of the standard solid, Table 1:
/// J(t) = (1/G∞) [1 − G1/(G∞+G1) · exp(−G∞ t / ((G∞+G1) τ1))].
double standard_solid_creep(double G_inf, double G1, double tau1, double t);

}  // namespace mdr::reference
