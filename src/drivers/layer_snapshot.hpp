#pragma once
// Snapshots on a layer (`output.snapshots` with a `[layer]`; docs/theory.md, "Layers", eq. L25 to L27): the
// pressure p(r) from the MDR line load q(x) by eq. 23, the surface displacement w(r) from its transform w1(x) by
// eq. 10, both as on the half-space; q and w1 from the cells (eq. L16 to L19) or, while the contact grows in a run of
// Ting's class, from the elastic layer's q and w1 at the loading nodes (eq. L11). They are the snapshot sources of a
// [layer] (recorders.hpp: the half-space's SnapshotRecorder takes them at the case's times).

#include <cstddef>
#include <vector>

#include "layer_cells.hpp"
#include "layer_stepping.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/rheology/rheology.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

/// Snapshots on the cells (eq. L19): after a step, p(r) from the cells' line load, taken to the edge by its linear
/// extrapolation there, w(r) from their w1, over the cells' range (a flat punch's: its radius). Taking one steps every
/// cell from then on (LayerCells::surface).
class CellSnapshots final : public SnapshotSource {
public:
    /// `cells` must outlive the source.
    explicit CellSnapshots(LayerCells& cells) : cells_(cells) {}
    /// The snapshot after the step to `state`, with its contact radius (StepState::contact_radius).
    Snapshot take(const StepState& state) override;

private:
    LayerCells& cells_;
};

/// A snapshot due while the contact recedes or after it was lost: the surface outside a receding contact creeps under
/// the nonlocal load K q of the contact (eq. L27; L18's free cells), which Ting's solution (eq. L12) does not carry.
/// Thrown by GrowingSnapshots::take, caught by run_layer_indentation, which runs the case again on LayerCells.
struct SnapshotOnCells {};

/// Snapshots of a growing contact in a run of Ting's class (eq. L26), from the loading record of the stepper
/// (LayerStepper::loading_times, loading_contacts).
class GrowingSnapshots final : public SnapshotSource {
public:
    /// `unit_modulus`: E* / G of the layer (4, G the effective modulus of eq. 56), as `stepper`'s, which must outlive
    /// the source.
    GrowingSnapshots(const rheology::Rheology& material, const contact::LayerContact& layer, double unit_modulus,
                     const LayerStepper& stepper);
    /// The snapshot of the stepper's committed step, untouched or growing: q(x, t) = int_0^t G(t - t') dq_el(x, t')
    /// with the parallel dashpot's part in the unit depth's shape, w1 the elastic layer's at the depth (eq. L26),
    /// p and w by eq. L25, over [0, the layer's largest contact radius]. Throws SnapshotOnCells where the contact
    /// recedes or was lost.
    Snapshot take(const StepState& state) override;

private:
    const rheology::Rheology* material_;
    const contact::LayerContact* layer_;
    double unit_modulus_;
    const LayerStepper* stepper_;
};

}  // namespace mdr::drivers
