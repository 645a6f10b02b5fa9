#pragma once
/// \file
/// Test helper: adaptive 5-point Gauss-Legendre quadrature, an independent reference for the rheology tests.

#include <cmath>

namespace mdr::rheology::test {

/// 5-point Gauss-Legendre rule on [a, b] (exact for polynomials of degree 9).
template <class Function>
auto gauss_legendre_5(const Function& f, double a, double b) {
    static const double x1 = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    static const double x2 = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    static const double w0 = 128.0 / 225.0;
    static const double w1 = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0;
    static const double w2 = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
    const double centre = 0.5 * (a + b);
    const double half = 0.5 * (b - a);
    return half * (w0 * f(centre) + w1 * (f(centre - half * x1) + f(centre + half * x1)) +
                   w2 * (f(centre - half * x2) + f(centre + half * x2)));
}

/// Integral of f over [a, b] by recursive halving until, on every panel, the two-half and the one-panel results
/// agree to `tolerance` (absolute). The two-half result is then far more accurate than that difference (the rule
/// is of order 10), so the total error stays well below `tolerance` times the number of panels.
template <class Function>
auto integrate(const Function& f, double a, double b, double tolerance, int depth = 0) {
    const auto whole = gauss_legendre_5(f, a, b);
    const double middle = 0.5 * (a + b);
    const auto halves = gauss_legendre_5(f, a, middle) + gauss_legendre_5(f, middle, b);
    if (std::abs(halves - whole) <= tolerance || depth >= 50) return halves;
    return integrate(f, a, middle, tolerance, depth + 1) + integrate(f, middle, b, tolerance, depth + 1);
}

}  // namespace mdr::rheology::test
