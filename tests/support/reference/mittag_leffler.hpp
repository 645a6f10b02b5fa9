#pragma once
/// \file
/// The Mittag-Leffler relaxation E_alpha(-x), 0 < alpha < 1, independent of the library's spectral quadrature: its
/// power series for small x, and elsewhere the fixed Talbot inversion (Abate and Valko 2004) of its Laplace transform
///   L[E_alpha(-t^alpha)](s) = s^(alpha - 1) / (s^alpha + 1),   x = t^alpha.

namespace mdr::reference {

/// E_alpha(-x) = sum_k (-x)^k / Gamma(alpha k + 1), summed while the terms matter (x <= 0.5).
double mittag_leffler_series(double alpha, double x);

/// E_alpha(-x) by fixed Talbot inversion with 32 nodes (~1e-10 relative in double precision).
double mittag_leffler_talbot(double alpha, double x);

/// E_alpha(-x): the series for x <= 0.5, Talbot beyond.
double mittag_leffler(double alpha, double x);

}  // namespace mdr::reference
