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

Snapshot FoundationSnapshots::take(const StepState& state) {
    Snapshot snapshot = take_snapshot(*state.foundation, indenter_, state.time);
    if (shear_stress_) shear_stress_(snapshot);
    return snapshot;
}

SnapshotRecorder::SnapshotRecorder(std::vector<double> times, SnapshotSource& source, IndentationResult& result)
    : times_(std::move(times)), source_(source), result_(result) {
    std::sort(times_.begin(), times_.end());
}

void SnapshotRecorder::observe(const StepState& state) {
    if (!state.settled) return;
    for (; next_ < times_.size() && times_[next_] <= state.time; ++next_) {
        result_.snapshots.push_back(source_.take(state));
    }
}

void drop_snapshots_after(std::vector<Snapshot>& snapshots, const StepState& end) {
    std::erase_if(snapshots, [&](const Snapshot& snapshot) {
        return snapshot.time > end.time || (snapshot.time == end.time && !end.settled);
    });
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
