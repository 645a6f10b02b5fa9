#pragma once
// An impact on a layer on the cells (docs/theory.md, "Layers", eq. L16 to L19 and L27): m d'' = -F by the half-space
// impact's trapezoidal rule (eq. 37), the force of each trial depth from LayerCells, which carry the surface outside
// the contact as it recedes after the turn (what a snapshot there needs).

#include <cstddef>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// Runs the impact of `contact_case` (with a `[layer]`) on `numerics.elements` cells (default default_layer_cells) of
/// [0, `largest_radius`] (the widest contact prepared for, [m]) until the contact is lost, each step's depth solved
/// from F(d) + (4m/dt^2)(d - d0 - v0 dt) = -F0 (LayerCells::step_inertial), the steps cut to land on the snapshot times
/// as the half-space impact's; snapshots from the cells (cells_snapshot), the outcome by the half-space's rule
/// (impact_outcome) with the loss located where the edge function at the axis crosses zero inside the step (eq. L19).
/// The caller's `observers` see every state; a stop ends the run with its state (and no outcome). Throws
/// mdr::InvalidInput naming `load.end` (no rebound in time), `layer` (the contact outgrows the range) or
/// `numerics.max_element_steps`; std::runtime_error when the restitution lies outside [0, 1].
IndentationResult run_layer_cells_impact(const ContactCase& contact_case, double largest_radius,
                                         const ProgressObserver& progress, const StepObservers& observers = {});

}  // namespace mdr::drivers
