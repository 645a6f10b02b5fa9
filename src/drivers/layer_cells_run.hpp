#pragma once
// A run on a layer's LayerCells (docs/theory.md, "Layers", eq. L16 to L19) in the one loop (run_loop.hpp): the cells
// made for the case and its widest contact, a stepping class over them, snapshots from them.

#include <cstddef>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "layer_cells.hpp"
#include "layer_snapshot.hpp"
#include "run_loop.hpp"

namespace mdr::drivers {

/// Runs `contact_case` (with a `[layer]`) on a `Stepping` (LayerCellsStepping, LayerCellsImpactStepping) made from the
/// case, what its control brings (`brought`: its LayerLoading or ImpactControl), the cells and the run's numerics:
/// layer_cell_count cells on [0, `largest_radius`] (the widest contact prepared for,
/// [m], reported as the numerics' half-width); snapshots from the cells (CellSnapshots).
template <class Stepping, class Brought>
IndentationResult run_on_layer_cells(const ContactCase& contact_case, const Brought& brought, double largest_radius,
                                     const ProgressObserver& progress, const StepObservers& observers) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const std::size_t cells = layer_cell_count(contact_case);
    result.numerics.elements = cells;
    result.numerics.half_width = largest_radius;  // reported: the cells' range
    LayerCells layer(contact_case.material, *contact_case.layer, layer_poisson_ratio(contact_case),
                     *contact_case.indenter, largest_radius, cells);
    Stepping stepping(contact_case, brought, layer, result.numerics);
    CellSnapshots snapshot_source(layer);
    run_stepping(stepping, contact_case, snapshot_source, progress, observers, result);
    return result;
}

}  // namespace mdr::drivers
