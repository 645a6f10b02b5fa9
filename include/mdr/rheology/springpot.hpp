#pragma once
/// \file
/// Fractional models built from a springpot (Scott Blair element, stress c d^alpha strain / dt^alpha, 0 < alpha < 1):
/// the springpot alone, with a spring in parallel (fractional Kelvin-Voigt), with a spring in series (fractional
/// Maxwell), and the fractional standard solid (a spring in parallel with a fractional Maxwell branch). One form
/// covers them: G(t) = G_inf + G_b(t), the branch a springpot in series with a spring G (G = infinity: none).

#include <complex>
#include <limits>

#include "mdr/rheology/approximation.hpp"

namespace mdr::rheology {

/// G_inf + (springpot c, alpha in series with a spring G).
struct FractionalModel {
    double equilibrium_modulus = 0.0;                                ///< G_inf [Pa], >= 0 (a spring in parallel)
    double series_modulus = std::numeric_limits<double>::infinity(); ///< G [Pa] of the spring in series; inf: none
    double quasi_property = 0.0;                                     ///< c [Pa s^alpha], > 0
    double alpha = 0.0;                                              ///< order, 0 < alpha < 1

    /// Throws mdr::InvalidInput with keys `G_inf`, `G`, `c`, `alpha` (as the models name them).
    void validate() const;
    /// G(t) [Pa], t > 0: G_inf + c t^(-alpha) / Gamma(1 - alpha) without a series spring, else
    /// G_inf + G E_alpha(-(t/tau)^alpha) with tau^alpha = c / G (E_alpha the Mittag-Leffler function).
    double relaxation(double t) const;
    /// G^(omega) = G_inf + G c (i omega)^alpha / (G + c (i omega)^alpha) (springs and springpot in the frequency
    /// domain; eq. 7).
    std::complex<double> complex_modulus(double omega) const;
    /// The exact functions, for certify.
    ModelFunctions functions() const;
};

/// E_alpha(-x) for x >= 0 and 0 < alpha < 1, from its spectral representation
///   E_alpha(-x) = sin(alpha pi) / (alpha pi) int_0^inf exp(-x^(1/alpha) s^(1/alpha)) / (s^2 + 2 s cos(alpha pi) + 1) ds
/// (completely monotone: a non-negative spectrum), by the trapezoidal rule in ln s with a spacing set by the strip
/// of analyticity alpha pi / 2; ~1e-12 relative. For alpha > 2/3 the integrand's poles at ln s = +-i pi (1 - alpha)
/// lie inside that strip: the sum on a half-step grid with the two poles' terms added (a cost that does not grow as
/// alpha -> 1). Where the strip is narrower than 1/32 (alpha below ~0.02) and where x^(1/alpha) leaves the doubles,
/// Gauss-Legendre in ln(s^(1/alpha) x^(1/alpha)) with the tail in closed form (springpot.cpp).
double mittag_leffler_decay(double alpha, double x);

/// The Prony series of a fractional model over `window`, certified to `tolerance` (relative, G(t) and G^(omega)):
/// the springpot's series (the power law G0 = c / Gamma(1 - alpha), beta = alpha, t0 = 1 s; see approximate),
/// put in series with the spring G by eq. (8) (creep functions add) and in parallel with G_inf; certified against
/// relaxation() and complex_modulus() over the window and at its frequencies, the springpot's tolerance tightened
/// until it holds.
Approximation approximate(const FractionalModel& model, const TimeWindow& window,
                          double tolerance = default_material_tolerance);

}  // namespace mdr::rheology
