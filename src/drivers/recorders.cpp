#include "recorders.hpp"

#include <algorithm>
#include <utility>

#include "mdr/foundation/foundation.hpp"
#include "every_control.hpp"
#include "stepping.hpp"

namespace mdr::drivers {

void RowRecorder::observe(const StepState& state) {
    if (!state.row) return;
    result_.time.push_back(state.time);
    result_.depth.push_back(state.depth);
    result_.force.push_back(state.force);
    result_.radius.push_back(state.contact_radius());
    if (columns_.velocity) result_.velocity.push_back(state.velocity);
    if (columns_.base) result_.base.push_back(state.load);
}

RowRecorder::Columns row_columns(const LoadControl& control) {
    return visit_control(control, [](auto traits, const auto& data) { return traits.columns(data); });
}

SnapshotSchedule::SnapshotSchedule(std::vector<double> times) : times_(std::move(times)) {
    std::sort(times_.begin(), times_.end());
}

std::size_t SnapshotSchedule::due(double time) {
    const std::size_t first = next_;
    while (next_ < times_.size() && times_[next_] <= time) ++next_;
    return next_ - first;
}

SnapshotRecorder::SnapshotRecorder(std::vector<double> times, const profile::Profile& indenter,
                                   IndentationResult& result, ShearStress shear_stress)
    : schedule_(std::move(times)), indenter_(indenter), result_(result), shear_stress_(std::move(shear_stress)) {}

void SnapshotRecorder::observe(const StepState& state) {
    if (!state.settled) return;
    for (std::size_t due = schedule_.due(state.time); due > 0; --due) {
        result_.snapshots.push_back(take_snapshot(*state.foundation, indenter_, state.time));
        if (shear_stress_) shear_stress_(result_.snapshots.back());
    }
}

void ShoreRecorder::observe(const StepState& state) {
    if (state.row) result_.shore.push_back(instrument_.reading(state.depth));
    if (state.settled &&
        std::find(shore_reading_times.begin(), shore_reading_times.end(), state.time) != shore_reading_times.end()) {
        result_.shore_readings.push_back({state.time, instrument_.reading(state.depth)});
    }
}

void ProgressReport::observe(const StepState& state) {
    if (state.fraction < next_) return;
    while (next_ <= state.fraction) next_ += 0.01;
    progress_(std::min(state.fraction, 1.0));
}

}  // namespace mdr::drivers
