#pragma once
// The time of an impact, whose steps have no grid: steps of the time step that land exactly on the snapshot times
// (one rule for the half-space, ImpactStepping, and the layer's cells, run_layer_cells_impact).

#include <cstddef>
#include <vector>

namespace mdr::drivers {

/// Steps of `time_step` [s] from t = 0, each cut to end on the next snapshot time, none longer; a step that ends
/// within 1e-9 of a step before a snapshot time ends on it (the time set to it): the summed steps' round-off would
/// otherwise leave a step of ~1e-19 s, whose trapezoidal rate 2 dd/dt - v0 turns the depth's round-off into any
/// velocity.
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
    std::vector<double> cuts_;  // ascending
    std::size_t next_cut_ = 0;  // the first snapshot time after the current time
    double time_step_;
    double time_ = 0.0;
};

}  // namespace mdr::drivers
