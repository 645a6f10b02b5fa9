#pragma once
// The time of an impact, whose steps have no grid: steps of the time step that land exactly on the snapshot times
// (one rule for the half-space, ImpactStepping, and the layer's cells, run_layer_cells_impact).

#include <cstddef>
#include <vector>

namespace mdr::drivers {

/// Steps of `time_step` [s] from t = 0, each cut to end on the next snapshot time, none longer; the time (the
/// start's too) is set to the latest snapshot time within 1e-9 of a step after it: the summed steps' round-off, or
/// two snapshot times within round-off of each other, or one within round-off of 0, would otherwise leave a step of
/// ~1e-19 s, whose trapezoidal rate 2 dd/dt - v0 turns the depth's round-off into any velocity (or whose 4m/dt^2
/// overflows).
class ImpactClock {
public:
    /// `snapshots` [s] in any order; `time_step` > 0 [s].
    ImpactClock(std::vector<double> snapshots, double time_step);
    /// The current time [s].
    double time() const { return time_; }
    /// The length [s] of the next step from the current time.
    double step() const;
    /// Ends the step of length step(): the time moves on by it, to the snapshot time itself where it ends on one.
    void advance();

private:
    /// Sets the time to the latest snapshot time within the slack after it and moves past those reached.
    void land();

    std::vector<double> cuts_;  // ascending
    std::size_t next_cut_ = 0;  // the first snapshot time after the current time
    double time_step_;
    double time_ = 0.0;
};

}  // namespace mdr::drivers
