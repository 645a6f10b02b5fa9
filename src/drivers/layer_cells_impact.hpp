#pragma once
// An impact on a layer on the cells (docs/theory.md, "Layers", eq. L16 to L19 and L27): its stepping class in the
// one loop (run_loop.hpp), m d'' = -F by the half-space impact's trapezoidal rule (eq. 37), the force of each trial
// depth from LayerCells, which carry the surface outside the contact as it recedes after the turn (what a snapshot
// there needs).

#include <cstddef>
#include <optional>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "impact_clock.hpp"
#include "layer_cells.hpp"
#include "observer_list.hpp"

namespace mdr::drivers {

/// Steps the impact `impact` (its mass and approach speed, LayerLoading::impact) on `cells` until the contact is lost
/// (its stop rule), each step's depth solved from F(d) + (4m/dt^2)(d - d0 - v0 dt) = -F0 (LayerCells::step_inertial),
/// the steps cut to land on the snapshot times as the half-space impact's; the outcome by the half-space's rule
/// (impact_outcome) with the loss located where the edge function at the axis crosses zero inside the step
/// (eq. L19).
class LayerCellsImpactStepping {
public:
    /// `contact_case`, `impact`, `cells` and `numerics` (the run's) must outlive the stepping.
    LayerCellsImpactStepping(const ContactCase& contact_case, const ImpactControl& impact, LayerCells& cells,
                             const ResolvedNumerics& numerics);
    LayerCellsImpactStepping(const LayerCellsImpactStepping&) = delete;
    LayerCellsImpactStepping& operator=(const LayerCellsImpactStepping&) = delete;

    /// None of its own.
    void add_observers(ObserverList& /*observers*/, IndentationResult& /*result*/) {}
    /// The first contact at t = 0, at the approach speed.
    StepState first_state() const { return state(0); }
    /// Step `n` (1, 2, ...); the run ends in the step in which the contact is lost. Throws mdr::InvalidInput naming
    /// `load.end` (no rebound in time), `layer` (the contact outgrows the range) or `numerics.max_element_steps`;
    /// std::runtime_error when the restitution lies outside [0, 1].
    StepState step(std::size_t n);
    /// The impact's outcome.
    void add_outcomes(IndentationResult& result) const { result.impact = outcome_; }

private:
    StepState state(std::size_t n) const;

    const ContactCase& contact_case_;
    const ResolvedNumerics& numerics_;
    LayerCells& cells_;
    double mass_;
    double approach_;
    ImpactClock clock_;
    double depth_ = 0.0;
    double velocity_;
    double force_ = 0.0;
    double contact_radius_ = 0.0;
    std::optional<ImpactOutcome> outcome_;
};

/// Runs the impact of `contact_case` (with a `[layer]`; `impact`, what its control brings) on LayerCellsImpactStepping:
/// layer_cell_count cells of [0, `largest_radius`] (the widest contact prepared for, [m]); snapshots from the cells (CellSnapshots). Throws as LayerCellsImpactStepping::step.
IndentationResult run_layer_cells_impact(const ContactCase& contact_case, const ImpactControl& impact,
                                         double largest_radius, const ProgressObserver& progress,
                                         const StepObservers& observers = {});

}  // namespace mdr::drivers
