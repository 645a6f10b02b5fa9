#pragma once
/// \file
/// Indentation of a viscoelastic layer on a rigid substrate (`[layer]`): displacement, force or spring control,
/// impact, an incompressible layer or a compressible one of constant Poisson ratio, a contact that grows and then
/// recedes (docs/theory.md, "Layers").

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// Cells on the contact's widest range when neither `[numerics] layer_cells` nor `elements` is given: the force
/// within ~1e-5 of the peak with the contact over a third of the range (third order in the cell without memory, eq.
/// L19a; with memory the time step's part remains; tests/verification/test_layer_regrowing.cpp,
/// tests/python/test_layer_unloading.py).
inline constexpr std::size_t default_layer_cells = 400;

/// The same with a parallel dashpot (`material.eta`): its line load jumps at a growing edge, so the cells are first
/// order in the cell where the contact's edge turns and where a cone's point contact starts from rest (the radius
/// 1.5e-3 and a cone's depth 1.0e-3 of their peaks at 400 cells, 4.6e-4 and ~5e-4 at 800; docs/theory.md 4c, eq.
/// L19b, L19c): twice the cells keep every output within 1e-3 of its peak.
inline constexpr std::size_t default_layer_cells_with_dashpot = 800;

/// The most cells `[numerics] layer_cells` may ask: I - K and its factor are dense (O(m^2) doubles, its factoring
/// O(m^3)), 4096 cells at most about 1 GB (540 MB measured) and 2.3e10 multiply-adds (3 s), a fifth of the default
/// numerics.max_element_steps before the first step (estimate_work, work_estimate.hpp).
inline constexpr std::size_t max_layer_cells = 4096;

/// The Gauss nodes of a layer's run of Ting's class (contact::LayerContact): at least `numerics.elements` (else
/// contact::default_layer_nodes), up to contact::most_nodes_over_default times the default rule's at each contact
/// radius, beyond which the solution no longer changes (LayerNodes::capped).
contact::LayerNodes layer_nodes(const ContactCase& contact_case);

/// The cells of a layer's coupled time-stepping (eq. L16 to L19): `numerics.layer_cells`, else `numerics.elements`
/// (so that a case without the key runs as before it existed), else default_layer_cells, or
/// default_layer_cells_with_dashpot for a material with a parallel dashpot.
std::size_t layer_cell_count(const ContactCase& contact_case);

/// The Poisson ratio of the layer's body, on which its kernel depends (docs/theory.md eq. L1): 0.5 for one
/// incompressible body; for one compressible body whose bulk relaxation is proportional to its shear relaxation
/// (K(t)/G(t) constant: an elastic G with an elastic K, or the same relaxation times with the moduli in one ratio),
/// rheology::constant_poisson_ratio. Throws mdr::InvalidInput naming `material.K` (an elastic bulk modulus) or
/// `material.bulk` when K(t)/G(t) changes in time (the layer's kernel would change in time, and the layer no longer
/// separates in time and space, eq. L11-L14), and `indenter.material` for a deformable indenter.
double layer_poisson_ratio(const ContactCase& contact_case);

/// Throws mdr::InvalidInput (key `layer` or the offending key, its value and the rule) for a case with a `[layer]`
/// that needs what is not built on a layer yet: an oblique impact, tangential loading, a compressible body whose
/// Poisson ratio changes in time, a deformable indenter (layer_poisson_ratio) or a Shore test against a parallel
/// dashpot (`material.eta`). Does nothing for a case without a layer.
void validate_layer(const ContactCase& contact_case);

/// Runs a displacement-, force- or spring-controlled case on its layer: the elastic layer's force F_el(d) at unit
/// effective shear modulus (contact::LayerContact, E* = 4, the kernel of layer_poisson_ratio) on the time grid of the
/// half-space driver. While the contact grows, F(t) = int_0^t G(t - t') dF_el(t') and a(t) = a_el(d(t)) (Lee & Radok
/// 1960; eq. L11); once it recedes, Ting's solution (Ting 1966; eq. L12, L13): a(t) = a_el(d(t1)) with int_{t1}^t G(t -
/// t') dd = 0 and F(t) = int_0^t1 G(t - t') dF_el(t'), exact as the layer's kernel (of a constant nu) does not change
/// in time; each Prony branch is updated exactly for F_el and d linear over a step (LayerStepper). Once the contact is
/// lost (t1 = the start) the force is zero and the free surface at the centre recovers (eq. L14); under force control
/// the indenter rides on it, under spring control it hangs at the base z. Force control solves the depth of each step
/// by numerics::monotone_root (the force increases with it in either phase), spring control likewise F(d) + k d = k z
/// (F = k (z - d)), and in a force pause F(d) = the force held (eq. L22; the base z = d + F / k, shifted after it as on
/// the half-space, PausedBase); a parallel dashpot then sees the trapezoidal rate of the solved depth, and takes a
/// force jump at a fixed depth (LayerStepper::jump). An impact runs LayerImpactStepping (src/drivers/layer_impact.hpp),
/// or with snapshots (or NumericsOptions::cells_from_start) LayerCellsImpactStepping on cells from the start
/// (src/drivers/layer_cells_impact.hpp: the surface outside its receding contact is theirs alone). Every way runs its
/// stepping class in the half-space's one loop (src/drivers/run_loop.hpp), with its observers and progress report.
/// `numerics.elements` is the least number of Gauss nodes over the contact (layer_nodes: up to twice the default
/// rule's, default contact::default_layer_nodes). A
/// Shore test (`control = "shore"`) is that spring control with the durometer's spring, its base step at the landing
/// and the half-space's reading columns (ShoreRecorder); the layer solves the durometer's tip (layer_indenter); a
/// contact that reaches the rod is refused (layer_shore_refusal), which comes before the stop. A case whose contact
/// would grow again after it shrank (a reload, a held depth that the recovering surface reaches, creep under a held
/// force or a force pause after an unload, a force after the contact was lost, a spring's base reaching the recovering
/// surface, a harmonic load: outside Ting's solution) runs the coupled time-stepping on cells instead, from the start
/// (Ting 1968's general case; eq. L16 to L19, src/drivers/layer_cells.hpp): a history once the run of Ting's class
/// finds the regrowth (the progress then held at the fraction reached), a harmonic (or any history with
/// NumericsOptions::cells_from_start) at once; its number of cells is layer_cell_count (`numerics.layer_cells`, else
/// `numerics.elements`, else default_layer_cells). Snapshots (`output.snapshots`, eq. L25 to L27): of a growing contact
/// in the run of Ting's class (GrowingSnapshots, src/drivers/layer_snapshot.hpp), and on the cells; one due while the
/// contact recedes or after it was lost runs the case on the cells from the start (the surface outside a receding
/// contact is theirs alone). The rows and a Shore test's readings are recorded by the half-space's recorders
/// (RowRecorder, ShoreRecorder). The caller's `observers` see every state of the run that gives the result after them,
/// as on the half-space (step_observer.hpp; StepState::layer_contact_radius filled, foundation null); a stop ends the
/// run there (IndentationResult::stopped, no harmonic outcome). With an observer that needs one run
/// (StepObserver::needs_one_run), a run of Ting's class keeps its states and shows them once it has ended in that class
/// (dropped where the cells take over; counted against numerics.max_memory before they are kept, refused naming it
/// where they exceed it), so that they never see the states of a run abandoned for the cells; a stop then ends the
/// result at its state as a stop asked at once. Throws as validate_layer; and naming `material.eta` for a force jump in
/// contact against a parallel dashpot on the cells.
IndentationResult run_layer_indentation(const ContactCase& contact_case, const ProgressObserver& progress = {},
                                        const StepObservers& observers = {});

}  // namespace mdr::drivers
