#pragma once
// A displacement-, force- or spring-controlled run on a layer of constant Poisson ratio whose contact may grow again
// after it shrank (a reload, a harmonic depth): the coupled time-stepping of LayerCells (docs/theory.md, "Layers",
// eq. L16 to L19).

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// Runs a displacement-, force- or spring-controlled case with a `[layer]` on LayerCells (under force and spring
/// control the depth of each step solved from F(d) + k d = the right side, LayerCells::step_loaded; in a force pause
/// with k = 0 and the force held, docs/theory.md eq. L22):
/// `numerics.elements` cells (default default_layer_cells) on [0, `largest_radius`] (the widest contact prepared for,
/// [m]), on the half-space driver's time grid (its harmonic part added and its last full cycle measured as on the
/// half-space, HarmonicOutcome). A parallel dashpot sees the indenter's rates as on the half-space (LayerCells).
/// Throws mdr::InvalidInput naming key `layer` when the contact outgrows the range, `material.eta` for a jump of the
/// force against a dashpot that pulls the contact's edge off or lands on the surface (LayerCells::step_loaded).
IndentationResult run_layer_regrowing(const ContactCase& contact_case, double largest_radius,
                                      const ProgressObserver& progress, const StepObservers& observers = {});

}  // namespace mdr::drivers
