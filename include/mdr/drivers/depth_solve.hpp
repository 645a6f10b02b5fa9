#pragma once
/// \file
/// The depth solve of a force-, spring- or impact-driven step (eq. 19), on any model of the foundation's force: the
/// drivers' Foundation (stepping.hpp) and the fit's band model (src/fit/band_model.hpp) take the same steps.

#include <algorithm>
#include <cmath>

#include "mdr/numerics/monotone_root.hpp"

namespace mdr::drivers {

/// The depth d at the end of a step with F(d) + spring (d - anchor) = target, where `force`(d) is the foundation's
/// force for a depth going linearly from the step's start to d and `slope` is dF/dd while no element enters or leaves
/// contact. F is continuous and non-decreasing, so after up to four Newton corrections with `slope` (exact while the
/// contact set does not change, so it usually ends after one) the root is bracketed from there in steps of `scale` and
/// found by Illinois regula falsi (numerics::monotone_root) to 1e-13 of the target. A correction that would leave the
/// bracket of the depths already tried is not taken (the slope does not hold there: a contact made or lost inside
/// the step, such as a spring's indenter touching a dashpot); the bracket then grows from the depth tried with the
/// smallest residual. With no spring and target 0 the force has a plateau: the largest depth without force is
/// returned.
template <typename Force>
double solve_force_balance(const Force& force, double slope, double guess, double scale, double target, double spring,
                           double anchor) {
    const auto residual = [&](double depth) { return force(depth) + spring * (depth - anchor) - target; };
    const bool plateau = spring == 0.0 && target == 0.0;
    const double force_tolerance = 1e-13 * std::max(std::abs(target), spring * scale);
    double start = guess;
    double f_start = residual(start);
    const double newton_slope = slope + spring;
    // The residual is non-decreasing: each depth tried bounds the root from below (residual <= 0) or above.
    double below = -HUGE_VAL, above = HUGE_VAL;
    double best = start, f_best = f_start;
    for (int newton = 0; newton < 4 && !plateau && newton_slope > 0.0; ++newton) {
        if (std::abs(f_start) <= force_tolerance) return start;
        (f_start <= 0.0 ? below : above) = start;
        const double next = start - f_start / newton_slope;
        if (!(next > below && next < above)) {
            start = best;
            f_start = f_best;
            break;
        }
        start = next;
        f_start = residual(start);
        if (std::abs(f_start) < std::abs(f_best)) {
            best = start;
            f_best = f_start;
        }
    }
    return numerics::monotone_root(residual, start, f_start, scale, force_tolerance,
                                   1e-15 * std::max(std::abs(start), scale), plateau);
}

}  // namespace mdr::drivers
