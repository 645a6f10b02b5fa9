#pragma once
/// \file
/// The root finder the drivers and the layer contact share: a continuous, non-decreasing (piecewise-smooth) function
/// of one variable, such as the foundation's force over the depth, the tangential layer's force over the tangential
/// increment or a layer's depth over its contact radius.

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mdr::numerics {

/// The x with f(x) = 0, from `start` (f(start) = f_start): the bracket f(lower) <= 0 < f(upper) is grown from
/// `start` in doubling steps of `step`, then narrowed by Illinois regula falsi (exact on a linear piece) until
/// |f| <= value_tolerance or the bracket is narrower than width_tolerance. With `plateau` (f = 0 on a whole
/// interval, such as zero force below the surface) it bisects for the largest x with f(x) <= 0 instead. Throws
/// std::runtime_error when the bracket grows without bound (f never changes sign: the target is out of reach).
template <typename Function>
double monotone_root(const Function& f, double start, double f_start, double step, double value_tolerance,
                     double width_tolerance, bool plateau) {
    if (!plateau && std::abs(f_start) <= value_tolerance) return start;
    double lower = start, upper = start, f_lower = f_start, f_upper = f_start;
    // Only one of the two loops runs.
    const auto out_of_reach = [] {
        throw std::runtime_error("no solution: the prescribed value cannot be reached (the solve's bracket grew "
                                 "without bound)");
    };
    while (f_lower > 0.0) {
        upper = lower;
        f_upper = f_lower;
        lower -= step;
        step *= 2.0;
        if (!std::isfinite(lower)) out_of_reach();
        f_lower = f(lower);
    }
    while (f_upper <= 0.0) {
        lower = upper;
        f_lower = f_upper;
        upper += step;
        step *= 2.0;
        if (!std::isfinite(upper)) out_of_reach();
        f_upper = f(upper);
    }
    int side = 0;
    for (int iteration = 0; iteration < 200 && upper - lower > width_tolerance; ++iteration) {
        double middle = 0.5 * (lower + upper);
        if (!plateau && f_upper > f_lower) {
            middle = std::clamp((lower * f_upper - upper * f_lower) / (f_upper - f_lower), lower, upper);
        }
        const double f_middle = f(middle);
        if (!plateau && std::abs(f_middle) <= value_tolerance) return middle;
        if (f_middle <= 0.0) {
            lower = middle;
            f_lower = f_middle;
            if (side == -1) f_upper *= 0.5;
            side = -1;
        } else {
            upper = middle;
            f_upper = f_middle;
            if (side == 1) f_lower *= 0.5;
            side = 1;
        }
    }
    return plateau ? lower : lower - f_lower * (upper - lower) / (f_upper - f_lower);
}

}  // namespace mdr::numerics
