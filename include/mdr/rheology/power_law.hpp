#pragma once
/// \file
/// The power-law material of cell and soft-tissue mechanics, G(t) = G0 (t/t0)^(-beta), and its Prony series.

#include <complex>

#include "mdr/rheology/approximation.hpp"

namespace mdr::rheology {

/// G(t) = G0 (t/t0)^(-beta), 0 < beta < 1 (a springpot of quasi-property G0 t0^beta).
struct PowerLaw {
    double G0 = 0.0;    ///< modulus at t = t0 [Pa], > 0
    double beta = 0.0;  ///< exponent, 0 < beta < 1
    double t0 = 1.0;    ///< reference time [s], > 0

    /// Throws mdr::InvalidInput with keys `G0`, `beta`, `t0`.
    void validate() const;
    /// G(t) [Pa], t > 0.
    double relaxation(double t) const;
    /// G^(omega) = G0 t0^beta Gamma(1 - beta) (i omega)^beta [Pa] (eq. 7 with G*(s) = G0 t0^beta Gamma(1-beta) s^(beta-1)).
    std::complex<double> complex_modulus(double omega) const;
    /// The exact functions, for certify.
    ModelFunctions functions() const;
};

/// The Prony series of a power law over `window`, certified to `tolerance` (relative, in G(t) and G^(omega)):
/// the trapezoidal rule in log tau of G(t) = G0 t0^beta / Gamma(beta) int tau^(-beta) exp(-t/tau) d ln tau, its
/// node spacing chosen from the aliasing error ~ 2 |Gamma(beta + 2 pi i / h)| / Gamma(beta), the sum continued past
/// the window's ends by one Maxwell term each that keeps the sum's moments (so that the area of G below the
/// window, which a convolution sees, is kept), then certified; refined until certified. The nodes span the window
/// widened to the lags 1/omega of its frequencies, where G^(omega) is certified too. Throws mdr::InvalidInput
/// for invalid parameters, window or tolerance (not in [1e-10, 0.1]).
Approximation approximate(const PowerLaw& model, const TimeWindow& window,
                          double tolerance = default_material_tolerance);

}  // namespace mdr::rheology
