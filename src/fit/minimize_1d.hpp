#pragma once
// Minimisation of a function of one variable on an interval (Brent's method: golden sections with parabolic steps).

#include <cmath>

namespace mdr::fit {

/// A minimum found by minimize_1d.
struct Minimum1d {
    double x;
    double value;
};

/// A local minimum of f on [lower, upper] to within `tolerance` in x (Brent 1973, "Algorithms for minimization
/// without derivatives", ch. 5): golden-section steps, replaced by the vertex of the parabola through the three
/// best points when that vertex lies inside the bracket and the step shrinks fast enough. At most `max_calls`
/// evaluations of f.
template <typename Function>
Minimum1d minimize_1d(const Function& f, double lower, double upper, double tolerance, int max_calls = 100) {
    const double golden = 0.5 * (3.0 - std::sqrt(5.0));
    double x = lower + golden * (upper - lower);  // the best point so far
    double w = x, v = x;                          // the second and third best
    double fx = f(x), fw = fx, fv = fx;
    double step = 0.0, previous_step = 0.0;
    for (int call = 1; call < max_calls; ++call) {
        const double middle = 0.5 * (lower + upper);
        const double tol = tolerance + 1e-12 * std::abs(x);
        if (std::abs(x - middle) <= 2.0 * tol - 0.5 * (upper - lower)) break;
        bool parabolic = false;
        if (std::abs(previous_step) > tol) {
            // The vertex of the parabola through (v, fv), (w, fw), (x, fx), as a step p / q from x.
            double r = (x - w) * (fx - fv);
            double q = (x - v) * (fx - fw);
            double p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if (q > 0.0) p = -p;
            q = std::abs(q);
            if (std::abs(p) < std::abs(0.5 * q * previous_step) && p > q * (lower - x) && p < q * (upper - x)) {
                previous_step = step;
                step = p / q;
                const double u = x + step;
                if (u - lower < 2.0 * tol || upper - u < 2.0 * tol) step = x < middle ? tol : -tol;
                parabolic = true;
            }
        }
        if (!parabolic) {
            previous_step = (x < middle ? upper : lower) - x;
            step = golden * previous_step;
        }
        const double u = std::abs(step) >= tol ? x + step : x + (step > 0.0 ? tol : -tol);
        const double fu = f(u);
        if (fu <= fx) {
            (u < x ? upper : lower) = x;
            v = w, fv = fw;
            w = x, fw = fx;
            x = u, fx = fu;
        } else {
            (u < x ? lower : upper) = u;
            if (fu <= fw || w == x) {
                v = w, fv = fw;
                w = u, fw = fu;
            } else if (fu <= fv || v == x || v == w) {
                v = u, fv = fu;
            }
        }
    }
    return {x, fx};
}

}  // namespace mdr::fit
