#pragma once
// A displacement-, force- or spring-controlled run on a layer of constant Poisson ratio whose contact may grow again
// after it shrank (a reload, a harmonic depth): the coupled time-stepping of LayerCells (docs/theory.md, "Layers",
// eq. L16 to L19), its stepping class in the one loop (run_loop.hpp).

#include <cstddef>
#include <optional>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/load_history.hpp"
#include "cycle_measure.hpp"
#include "layer_cells.hpp"
#include "layer_loading.hpp"
#include "observer_list.hpp"
#include "paused_base.hpp"

namespace mdr::drivers {

/// Steps a history-driven control (`loading`) on LayerCells node by node along its grid (indentation_grid, its
/// harmonic part added): a prescribed depth goes to it, a force or a spring's base solves F(d) + k d = the right side
/// (LayerCells::step_loaded; in a force pause with k = 0 and the force held, docs/theory.md eq. L22, and the base
/// history resumes shifted from the z reached, PausedBase, as on the half-space); a harmonic load's last full cycle
/// measured as on the half-space (CycleMeasure, its own observer), its outcome.
class LayerCellsStepping {
public:
    /// `contact_case`, `loading` and `cells` must outlive the stepping; `numerics` are the run's.
    LayerCellsStepping(const ContactCase& contact_case, const LayerLoading& loading, LayerCells& cells,
                       const ResolvedNumerics& numerics);
    LayerCellsStepping(const LayerCellsStepping&) = delete;
    LayerCellsStepping& operator=(const LayerCellsStepping&) = delete;

    /// A harmonic load's cycle measure (as HistoryStepping's).
    void add_observers(ObserverList& observers, IndentationResult& result);
    /// The state at the grid's first node.
    StepState first_state() { return step(0); }
    /// The step to node `n` (1, 2, ...); the last node ends the run.
    StepState step(std::size_t n);
    /// The harmonic outcome of the last full cycle.
    void add_outcomes(IndentationResult& result) const;

private:
    // The cycle measure of the states observed, with the cells' contact over each step (LayerCellState::touching,
    // touching_part: the cells have no foundation for CycleMeasure::observe to read).
    class CellCycle final : public StepObserver {
    public:
        CellCycle(const HarmonicLoad& harmonic, double simulated_end, const LayerCellState& cells)
            : measure_(harmonic, simulated_end), cells_(cells) {}
        void observe(const StepState& state) override {
            measure_.record(state.time, state.depth, state.force, cells_.touching, cells_.touching_part);
        }
        std::optional<HarmonicOutcome> outcome() const { return measure_.outcome(); }

    private:
        CycleMeasure measure_;
        const LayerCellState& cells_;
    };

    const ContactCase& contact_case_;
    const LayerLoading& loading_;
    LayerCells& cells_;
    LayerCellState last_;  // the cells after the last step
    std::vector<GridNode> grid_;
    // A prescribed depth under a harmonic with a parallel dashpot: its rate inside a step.
    bool sine_rate_;
    std::optional<PausedBase> paused_;
    std::optional<CellCycle> cycle_;
};

/// Runs a displacement-, force- or spring-controlled case with a `[layer]` (`loading`, what its control brings) on
/// LayerCellsStepping: layer_cell_count cells on [0, `largest_radius`] (the widest contact prepared for, [m]), on
/// the half-space driver's time grid; snapshots from the cells (CellSnapshots). A parallel dashpot sees the
/// indenter's rates as on the half-space (LayerCells). Throws mdr::InvalidInput naming key
/// `layer` when the contact outgrows the range, `material.eta` for a jump of the force against a dashpot that pulls
/// the contact's edge off or lands on the surface (LayerCells::step_loaded).
IndentationResult run_layer_regrowing(const ContactCase& contact_case, const LayerLoading& loading,
                                      double largest_radius, const ProgressObserver& progress,
                                      const StepObservers& observers = {});

}  // namespace mdr::drivers
