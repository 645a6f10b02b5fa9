#pragma once
// The base of a spring-controlled run through its constant-force pauses (ForcePause): which steps hold the force,
// the force held, and the shift of the base history after each pause.

#include <cstddef>
#include <vector>

#include "mdr/drivers/force_pause.hpp"
#include "mdr/drivers/load_history.hpp"

namespace mdr::drivers {

class PausedBase {
public:
    /// `pauses` validated (in time order, apart), `spring_constant` k > 0.
    PausedBase(std::vector<ForcePause> pauses, double spring_constant);

    /// True when the step (from, to] lies inside a pause that has started: the force is held over it.
    bool holding(double from, double to) const;
    /// The force held [N] by the current pause.
    double held_force() const { return held_force_; }
    /// The base z [m] outside the pauses: the history's value plus the shift of the pauses passed.
    double base(double history_value) const { return history_value + shift_; }
    /// The base z [m] during a pause: the spring is stretched by the force held, z = d + F / k.
    double base_in_pause(double depth) const { return depth + held_force_ / spring_constant_; }
    /// Called with the state at the last node at `time`: at a pause's start takes the force to hold (throws
    /// mdr::InvalidInput naming `load.force_pauses[i]` when it is not > 0, no contact); at its end sets the shift
    /// so that the base history resumes from the z reached (`history_value` the history's z at `time`).
    void passed(double time, double force, double depth, double history_value);

private:
    std::vector<ForcePause> pauses_;
    double spring_constant_;
    std::size_t next_ = 0;      // the first pause not yet ended
    bool active_ = false;       // inside pauses_[next_]
    double held_force_ = 0.0;
    double shift_ = 0.0;
};

/// An upper bound of the base z [m] over a run whose history peaks at `history_peak` (the harmonic part
/// included): each pause can raise the later base by the depth it creeps, at most `creep_bound` [m], plus the
/// history's own fall over the pause (its values there are not used).
double paused_base_peak(const LoadHistory& history, const std::vector<ForcePause>& pauses, double history_peak,
                        double creep_bound);

}  // namespace mdr::drivers
