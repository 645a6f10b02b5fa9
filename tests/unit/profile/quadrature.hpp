#pragma once
/// \file
/// Adaptive Simpson quadrature for the profile tests: an independent way to evaluate eq. (9) and (10).

#include <algorithm>
#include <cmath>

namespace mdr::test {

namespace detail {

template <class F>
double simpson_step(const F& f, double a, double b, double fa, double fm, double fb, double whole, double tolerance,
                    double floor, int depth) {
    const double m = 0.5 * (a + b);
    const double lm = 0.5 * (a + m);
    const double rm = 0.5 * (m + b);
    const double flm = f(lm);
    const double frm = f(rm);
    const double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    const double right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    const double delta = left + right - whole;
    if (depth <= 0 || std::abs(delta) <= 15.0 * tolerance) return left + right + delta / 15.0;
    // Halving the tolerance stops at `floor`, so rounding noise cannot drive the recursion to full depth.
    const double half = std::max(0.5 * tolerance, floor);
    return simpson_step(f, a, m, fa, flm, fm, left, half, floor, depth - 1) +
           simpson_step(f, m, b, fm, frm, fb, right, half, floor, depth - 1);
}

}  // namespace detail

/// int_a^b f(x) dx by adaptive Simpson with Richardson extrapolation, to a `relative_tolerance` of the
/// integral (each sub-interval's share floored at 1e-3 of it, which bounds the work where f is noisy).
template <class F>
double adaptive_simpson(const F& f, double a, double b, double relative_tolerance) {
    const double fa = f(a);
    const double fm = f(0.5 * (a + b));
    const double fb = f(b);
    const double whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    const double tolerance = relative_tolerance * std::abs(whole);
    return detail::simpson_step(f, a, b, fa, fm, fb, whole, tolerance, 1e-3 * tolerance, 50);
}

}  // namespace mdr::test
