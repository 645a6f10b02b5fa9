#pragma once
// The observers of one run, in calling order: the driver's standard ones, then the caller's.

#include <cstddef>
#include <vector>

#include "mdr/drivers/step_observer.hpp"

namespace mdr::drivers {

/// Hands each state of a run to its observers (include/mdr/drivers/step_observer.hpp).
class ObserverList {
public:
    /// Rows every `output_every` steps (numerics.output_every, >= 1).
    explicit ObserverList(std::size_t output_every) : output_every_(output_every) {}
    /// Appends an observer (not owned; it must outlive the list).
    void add(StepObserver& observer) { observers_.push_back(&observer); }
    /// Appends the caller's observers.
    void add(const StepObservers& observers);
    /// Makes `state` the last one when an observer asks to stop, marks its row and hands it to every observer.
    /// Returns whether the run ends with it (the driver's own end, `state.last` set by it, or a stop).
    bool notify(StepState& state);
    /// Whether an observer stopped the run.
    bool stopped() const { return stopped_; }

private:
    std::vector<StepObserver*> observers_;
    std::size_t output_every_;
    bool stopped_ = false;
};

}  // namespace mdr::drivers
