#pragma once
/// \file
/// Axisymmetric power-law indenters f(r) = c rⁿ for the reference solutions, with their MDR profile
/// g(x) = κ_n c |x|ⁿ (handbook eq. 9 and section 3 of equations.md). Sphere (n = 2) and cone (n = 1) included.

namespace mdr::reference {

/// Rigid indenter with gap f(r) = coefficient · r^exponent [m]; r in m, coefficient in m^(1−exponent).
struct PowerLawIndenter {
    double coefficient = 0.0;  ///< c of f(r) = c rⁿ
    double exponent = 0.0;     ///< n > 0

    /// Gap f(r) [m] between the undeformed surfaces at radius r [m].
    double gap(double r) const;
    /// κ_n = sqrt(π) Γ(n/2 + 1) / Γ(n/2 + 1/2) (κ_1 = π/2, κ_2 = 2).
    double kappa() const;
    /// MDR profile g(x) = κ_n c |x|ⁿ [m] (eq. 9).
    double mdr_profile(double x) const;
    /// Depth at which the contact radius is a for monotone loading, d = g(a) [m] (eq. 15).
    double depth_at_radius(double a) const;
    /// Contact radius for monotone loading to depth d ≥ 0, a = g⁻¹(d) [m] (eq. 15).
    double radius_at_depth(double d) const;
    /// Throws std::invalid_argument unless coefficient > 0 and exponent > 0.
    void validate() const;
};

/// Sphere of radius R [m] in the parabolic approximation f = r²/(2R), g = x²/R (eq. 30).
PowerLawIndenter sphere_indenter(double radius);
/// Cone f = r tanθ, θ [rad] the angle between flank and surface, g = (π/2) tanθ |x| (eqs. 24, 25).
PowerLawIndenter cone_indenter(double slope_angle);

}  // namespace mdr::reference
