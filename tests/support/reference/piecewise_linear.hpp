#pragma once
/// \file
/// A piecewise-linear function of time, the load histories d(t) of the reference solutions.

#include <vector>

namespace mdr::reference {

/// Piecewise-linear history through the points (times[i], values[i]); times strictly increasing, at least
/// two points. Constant (the end value) outside [times.front(), times.back()].
struct PiecewiseLinear {
    std::vector<double> times;   ///< breakpoints [s]
    std::vector<double> values;  ///< values at the breakpoints (depth in m for d(t))

    /// Value at time t.
    double value(double t) const;
    /// Slope on the piece that contains t, the earlier piece at a breakpoint (left derivative); 0 outside.
    double slope(double t) const;
    /// Throws std::invalid_argument unless the sizes match, there are ≥ 2 points and times increase strictly.
    void validate() const;
};

}  // namespace mdr::reference
