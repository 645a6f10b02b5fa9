#pragma once
// Snapshots on a layer (`output.snapshots` with a `[layer]`; docs/theory.md, "Layers", eq. L25 to L27): the
// pressure p(r) from the MDR line load q(x) by eq. 23, the surface displacement w(r) from its transform w1(x) by
// eq. 10, both as on the half-space; q and w1 from the cells (eq. L16 to L19) or, while the contact grows in a run of
// Ting's class, from the elastic layer's q and w1 at the loading nodes (eq. L11).

#include <cstddef>
#include <vector>

#include "layer_cells.hpp"
#include "layer_stepping.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/rheology/rheology.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

/// The snapshot of `cells` after a step at `time` [s] with the contact radius `contact_radius` [m] (eq. L19): p(r)
/// from the cells' line load, taken to the edge by its linear extrapolation there, w(r) from their w1, over the cells'
/// range (a flat punch's: its radius). Steps every cell from then on (LayerCells::surface).
Snapshot cells_snapshot(LayerCells& cells, double contact_radius, double time);

/// Snapshots of a growing contact in a run of Ting's class (eq. L26): records the loading nodes as
/// LayerStepper::commit does, and takes the snapshot of an untouched or growing step from them.
class GrowingSnapshots {
public:
    /// `unit_modulus`: E* / G of the layer (4, G the effective modulus of eq. 56), as LayerStepper's.
    GrowingSnapshots(const rheology::Rheology& material, const contact::LayerContact& layer, double unit_modulus);
    /// Records a committed step: an untouched one restarts the record, a growing one is appended.
    void commit(const LayerStep& step);
    /// The snapshot of the last committed `step`, untouched or growing: q(x, t) = int_0^t G(t - t') dq_el(x, t')
    /// with the parallel dashpot's part in the unit depth's shape, w1 the elastic layer's at the depth (eq. L26),
    /// p and w by eq. L25, over [0, the layer's largest contact radius].
    Snapshot take(const LayerStep& step) const;

private:
    struct Node {
        double time = 0.0;
        contact::LayerContactState contact;
    };
    const rheology::Rheology* material_;
    const contact::LayerContact* layer_;
    double unit_modulus_;
    double start_ = 0.0;      // the record's start: the last untouched node
    std::vector<Node> nodes_;  // the loading nodes since
};

}  // namespace mdr::drivers
