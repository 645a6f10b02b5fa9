#pragma once
// A displacement-, force- or spring-controlled run of Ting's class on a layer (one maximum of the contact radius;
// docs/theory.md, "Layers", eq. L11 to L14, L22): its stepping class in the one loop (run_loop.hpp), on the
// half-space's time grid, the force of a depth from LayerStepper (Lee-Radok while the contact grows, Ting once it
// recedes).

#include <cstddef>
#include <optional>
#include <vector>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/load_history.hpp"
#include "layer_loading.hpp"
#include "layer_stepping.hpp"
#include "observer_list.hpp"
#include "paused_base.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

/// A contact that grows again after it shrank (reloading, or the recovering surface reaching the indenter again):
/// Ting's solution (eq. L12) no longer holds. Thrown by LayerTingStepping::step, caught by run_layer_indentation,
/// which runs the case again on LayerCells.
struct ContactRegrows {};

/// Steps a history-driven control (`loading`: the depth, the force, or a spring's base with its force pauses and a
/// durometer) node by node along its grid (indentation_grid: graded after the fast changes under force or spring
/// control, each force pause's ends and each Shore reading on a node of its own): a prescribed depth goes to it, a
/// force or a spring's base solves F(d) + k d = the right side (eq. L22; in a force pause F(d) = the force held,
/// PausedBase, as on the half-space).
class LayerTingStepping {
public:
    /// `contact_case`, `loading` and `layer` (the elastic layer at unit modulus `unit_modulus`, E* / G) must outlive
    /// the stepping; `solved_depth_scale` [m] is the depth's scale of a solved depth (the profile's at the largest
    /// radius), `numerics` the run's.
    LayerTingStepping(const ContactCase& contact_case, const LayerLoading& loading, const contact::LayerContact& layer,
                      double unit_modulus, double solved_depth_scale, const ResolvedNumerics& numerics);
    LayerTingStepping(const LayerTingStepping&) = delete;
    LayerTingStepping& operator=(const LayerTingStepping&) = delete;

    /// A Shore test's readings (ShoreRecorder, as on the half-space).
    void add_observers(ObserverList& observers, IndentationResult& result);
    /// The state at the grid's first node.
    StepState first_state() { return step(0); }
    /// The step to node `n` (1, 2, ...); the last node ends the run. Throws ContactRegrows where the contact would
    /// grow again after it shrank.
    StepState step(std::size_t n);
    /// None: the outcomes of a history (the harmonic one) are the cells'.
    void add_outcomes(IndentationResult& /*result*/) const {}
    /// The nodes of the grid, the states of the run.
    std::size_t nodes() const { return grid_.size(); }
    /// The stepper, whose loading record a growing contact's snapshots read (GrowingSnapshots).
    const LayerStepper& stepper() const { return stepper_; }

private:
    const ContactCase& contact_case_;
    const LayerLoading& loading_;
    std::vector<GridNode> grid_;
    // The depth's scale: the largest prescribed (under spring control the base's: d <= z while F >= 0), or the
    // solved one under force control.
    double largest_depth_;
    // The force of a trial depth is exact to ~1.5e-8 (the contact solve's depth to 1e-8): the depth solves' force
    // tolerance is no finer than 5e-8 of the largest force (under spring control at most k max z).
    double force_tolerance_;
    DashpotRate dashpot_rate_;
    LayerStepper stepper_;
    bool by_radius_;  // a growing contact solved over its radius (not a flat punch's: over the depth)
    std::optional<PausedBase> paused_;
    std::optional<ShoreRecorder> shore_recorder_;
    double previous_centre_ = 0.0;
};

}  // namespace mdr::drivers
