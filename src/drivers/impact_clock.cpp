#include "impact_clock.hpp"

#include <algorithm>

namespace mdr::drivers {

namespace {

// A snapshot time within this fraction of a step beyond a full step is landed on by that step.
constexpr double landing_slack = 1e-9;

}  // namespace

ImpactClock::ImpactClock(std::vector<double> snapshots, double time_step)
    : cuts_(std::move(snapshots)), time_step_(time_step) {
    std::sort(cuts_.begin(), cuts_.end());
    while (next_cut_ < cuts_.size() && cuts_[next_cut_] <= time_) ++next_cut_;
}

double ImpactClock::step() const {
    if (next_cut_ < cuts_.size() && cuts_[next_cut_] - time_ <= (1.0 + landing_slack) * time_step_) {
        return cuts_[next_cut_] - time_;
    }
    return time_step_;
}

void ImpactClock::advance() {
    const bool lands = next_cut_ < cuts_.size() && cuts_[next_cut_] - time_ <= (1.0 + landing_slack) * time_step_;
    time_ = lands ? cuts_[next_cut_] : time_ + time_step_;
    while (next_cut_ < cuts_.size() && cuts_[next_cut_] <= time_) ++next_cut_;
}

}  // namespace mdr::drivers
