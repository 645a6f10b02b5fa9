#include "impact_clock.hpp"

#include <algorithm>
#include <utility>

namespace mdr::drivers {

namespace {

// A snapshot time within this fraction of a step after the current time is that time (the summed steps' round-off).
constexpr double landing_slack = 1e-9;

}  // namespace

ImpactClock::ImpactClock(std::vector<double> snapshots, double time_step)
    : cuts_(std::move(snapshots)), time_step_(time_step) {
    std::sort(cuts_.begin(), cuts_.end());
    land();
}

double ImpactClock::step() const {
    return next_cut_ < cuts_.size() ? std::min(time_step_, cuts_[next_cut_] - time_) : time_step_;
}

void ImpactClock::advance() {
    time_ += step();
    land();
}

void ImpactClock::land() {
    const double reach = time_ + landing_slack * time_step_;
    while (next_cut_ < cuts_.size() && cuts_[next_cut_] <= reach) time_ = std::max(time_, cuts_[next_cut_++]);
}

}  // namespace mdr::drivers
