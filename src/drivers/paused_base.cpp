#include "paused_base.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "mdr/error.hpp"

namespace mdr::drivers {

PausedBase::PausedBase(std::vector<ForcePause> pauses, double spring_constant)
    : pauses_(std::move(pauses)), spring_constant_(spring_constant) {}

bool PausedBase::holding(double from, double to) const {
    return active_ && from >= pauses_[next_].start && to <= pauses_[next_].end;
}

void PausedBase::passed(double time, double force, double depth, double history_value) {
    if (next_ == pauses_.size()) return;
    const ForcePause& pause = pauses_[next_];
    if (!active_ && time == pause.start) {
        if (!(force > 0.0)) {
            throw InvalidInput(fmt::format("load.force_pauses[{}]", next_),
                               fmt::format("[{}, {}]", format_value(pause.start), format_value(pause.end)),
                               fmt::format("the force at its start is {} (no contact): a force pause holds the force "
                                           "of a contact; start it after the tip has touched",
                                           format_value(force)));
        }
        held_force_ = force;
        active_ = true;
    } else if (active_ && time == pause.end) {
        shift_ = base_in_pause(depth) - history_value;  // the base history resumes from the z reached
        active_ = false;
        ++next_;
    }
}

double paused_base_peak(const LoadHistory& history, const std::vector<ForcePause>& pauses, double history_peak,
                        double creep_bound) {
    double peak = history_peak;
    for (const ForcePause& pause : pauses) {
        peak += creep_bound + std::max(0.0, history.value(pause.start) - history.value(pause.end));
    }
    return peak;
}

}  // namespace mdr::drivers
