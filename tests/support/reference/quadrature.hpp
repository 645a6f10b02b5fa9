#pragma once
/// \file
/// Numerical tools of the reference solutions: adaptive Gauss–Kronrod quadrature and a bracketed root finder.
/// Independent of the library; used only by the oracles in this folder.

#include <functional>

namespace mdr::reference {

/// ∫_a^b f(x) dx by globally adaptive Gauss–Kronrod (7/15 points), bisecting the interval with the largest
/// error estimate until the summed estimate is below max(abs_tol, rel_tol·|∫|f||). Throws std::runtime_error
/// if 4000 subintervals do not reach the tolerance. Accurate to ~1e-14 relative for smooth integrands.
double integrate(const std::function<double(double)>& f, double a, double b, double rel_tol = 1e-13,
                 double abs_tol = 0.0);

/// Root of f in [lo, hi] where f(lo) and f(hi) differ in sign (or one is zero), by Brent's method (inverse
/// quadratic interpolation safeguarded by bisection) to |hi − lo| ≤ x_tol. Throws std::invalid_argument when
/// the root is not bracketed.
double find_root(const std::function<double(double)>& f, double lo, double hi, double x_tol);

}  // namespace mdr::reference
