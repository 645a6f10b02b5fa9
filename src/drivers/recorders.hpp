#pragma once
// The drivers' standard observers: what fills IndentationResult (rows, snapshots, Shore readings, tangential
// columns) and the progress reports.

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/shore.hpp"
#include "mdr/drivers/step_observer.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {

/// The rows t, d, F, a (and v of an impact, z of spring control when asked) at every written row, on the half-space
/// and on a [layer] (StepState::contact_radius).
class RowRecorder final : public StepObserver {
public:
    /// The optional columns of IndentationResult that this run fills.
    struct Columns {
        bool velocity = false;  ///< v: an impact
        bool base = false;      ///< z: spring control (not a Shore test)
    };
    RowRecorder(IndentationResult& result, Columns columns) : result_(result), columns_(columns) {}
    void observe(const StepState& state) override;

private:
    IndentationResult& result_;
    Columns columns_;
};

/// The optional row columns that `control` writes (its ControlTraits' columns), on the half-space and on a [layer].
RowRecorder::Columns row_columns(const LoadControl& control);

/// What a run's snapshots are taken of: the physics of its pressure p(r), surface displacement w(r) (and shear
/// stress) at a state, which differs between the half-space's foundation (FoundationSnapshots) and a [layer]'s Ting
/// solution or cells (layer_snapshot.hpp); the times, the result and its columns are SnapshotRecorder's.
class SnapshotSource {
public:
    virtual ~SnapshotSource() = default;
    /// The snapshot at `state`, a settled state at or after a snapshot time, taken at the state's time.
    virtual Snapshot take(const StepState& state) = 0;
};

/// The half-space's snapshots: pressure (eq. 23) and surface displacement of its MDR foundation (take_snapshot), and
/// the shear stress when `shear_stress` is given.
class FoundationSnapshots final : public SnapshotSource {
public:
    /// Fills a snapshot's shear stress from a tangential layer.
    using ShearStress = std::function<void(Snapshot&)>;
    FoundationSnapshots(const profile::Profile& indenter, ShearStress shear_stress)
        : indenter_(indenter), shear_stress_(std::move(shear_stress)) {}
    Snapshot take(const StepState& state) override;

private:
    const profile::Profile& indenter_;
    ShearStress shear_stress_;
};

/// Snapshots at the case's times, each taken from `source` at the first settled state at or after it (the drivers
/// put a state on each of these times), on the half-space and on a [layer].
class SnapshotRecorder final : public StepObserver {
public:
    /// `source` must outlive the recorder.
    SnapshotRecorder(std::vector<double> times, SnapshotSource& source, IndentationResult& result);
    void observe(const StepState& state) override;

private:
    std::vector<double> times_;  // ascending
    std::size_t next_ = 0;       // the first time not taken yet
    SnapshotSource& source_;
    IndentationResult& result_;
};

/// Leaves out the snapshots taken after state `end` (a stop in a replay, StateLog): each is taken at the first settled
/// state at or after its time, which is `end` itself only when `end` is settled.
void drop_snapshots_after(std::vector<Snapshot>& snapshots, const StepState& end);

/// A Shore test: the reading column H at every row, and the readings at shore_reading_times (settled states on
/// those times; the driver puts nodes there).
class ShoreRecorder final : public StepObserver {
public:
    ShoreRecorder(const Durometer& instrument, IndentationResult& result) : instrument_(instrument), result_(result) {}
    void observe(const StepState& state) override;

private:
    const Durometer& instrument_;
    IndentationResult& result_;
};

/// The columns of a tangential stepper (TangentialStepper, ObliqueStepper: its `record`) at every row.
template <class Stepper>
class TangentialColumns final : public StepObserver {
public:
    TangentialColumns(const Stepper& stepper, IndentationResult& result) : stepper_(stepper), result_(result) {}
    void observe(const StepState& state) override {
        if (state.row) stepper_.record(result_);
    }

private:
    const Stepper& stepper_;
    IndentationResult& result_;
};

/// Calls `progress` with the fraction done each time the run has done another hundredth of it.
class ProgressReport final : public StepObserver {
public:
    /// `progress` must be callable and outlive the report.
    explicit ProgressReport(const ProgressObserver& progress) : progress_(progress) {}
    void observe(const StepState& state) override;

private:
    const ProgressObserver& progress_;
    double next_ = 0.01;
};

}  // namespace mdr::drivers
