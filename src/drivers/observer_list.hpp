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

/// Keeps every state of a run for observers that may see them only once the run is known to give the result (a
/// [layer]'s run of Ting's class, which the cells replace from the start where the contact grows again): a copy of
/// each state, O(steps) memory.
class StateLog final : public StepObserver {
public:
    /// Makes room for `states` states at once (numerics.max_memory counts them: require_kept_states_within_bound).
    void reserve(std::size_t states) { states_.reserve(states); }
    void observe(const StepState& state) override { states_.push_back(state); }
    /// Hands the kept states in order to `observers` (ObserverList::notify: their stops asked, a stop making its state
    /// the last one and a row) up to the run's last state; returns the state the run ends with (the last kept, or the
    /// one an observer stopped at).
    StepState replay(ObserverList& observers) const;

private:
    std::vector<StepState> states_;
};

}  // namespace mdr::drivers
