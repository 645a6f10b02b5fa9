#include "observer_list.hpp"

#include <stdexcept>

namespace mdr::drivers {

void ObserverList::add(const StepObservers& observers) {
    for (StepObserver* observer : observers) {
        if (observer == nullptr) throw std::invalid_argument("run_case: an observer is a null pointer");
        observers_.push_back(observer);
    }
}

bool ObserverList::notify(StepState& state) {
    if (!state.last) {
        for (StepObserver* observer : observers_) {
            if (observer->stop(state)) {
                state.last = true;
                stopped_ = true;
                break;
            }
        }
    }
    state.row = state.step % output_every_ == 0 || state.last;
    for (StepObserver* observer : observers_) observer->observe(state);
    return state.last;
}

StepState StateLog::replay(ObserverList& observers) const {
    StepState state;
    for (const StepState& kept : states_) {
        state = kept;
        if (observers.notify(state)) break;
    }
    return state;
}

}  // namespace mdr::drivers
