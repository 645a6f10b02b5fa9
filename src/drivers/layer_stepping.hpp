#pragma once
// The viscoelastic layer's contact stepped node by node (docs/theory.md, "Layers", eq. L11 to L14): a growing
// contact (Lee-Radok), a receding one (Ting), the free centre after the contact is lost. A step is tried at any depth
// without changing the history (the force-controlled driver solves for the depth), then committed.

#include <optional>
#include <span>
#include <vector>

#include "layer_receding.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::drivers {

/// Where a layer's contact stands.
enum class LayerPhase {
    approach,    ///< not touched yet: nothing has happened
    growing,     ///< Lee-Radok (eq. L11)
    receding,    ///< Ting (eq. L12, L13)
    lifted_off,  ///< contact lost: the centre of the surface recovers freely (eq. L14)
};

/// The rate a parallel dashpot sees (docs/theory.md, section 3 and "Layers"): the secant rate of a prescribed depth (of
/// F_el while growing), or, where the depth is solved, a trapezoidal rate 2 ds/dt - rate0. Under force or spring
/// control s = F_el while the contact grows (eq. L11; smooth where the depth is not: d ~ t^(2/3) under a force step
/// on a sphere) and s = d while it recedes (eq. L12); in an impact s = d throughout (the indenter's velocity of the
/// equation of motion's trapezoidal rule). From the indenter's rate `start` at the first contact (F_el's rate there:
/// E* times the touching stiffness times it, zero for a profile touching at a point; unknown for a flat punch
/// without `start`: the secant rate for that step).
struct DashpotRate {
    bool trapezoidal = false;     ///< the depth is solved
    std::optional<double> start;  ///< dd/dt [m/s] at the first contact, where known
    bool indenter_motion = false;  ///< the depth follows a smooth motion (an impact): its rate while growing too
};

/// The state after a step (committed) or a step tried.
struct LayerStep {
    LayerPhase phase = LayerPhase::approach;
    double time = 0.0;           ///< t [s]
    double centre = 0.0;         ///< w0 [m]: the depth while in contact, the free surface after
    double force = 0.0;          ///< F [N]
    double elastic_force = 0.0;  ///< F_el at the contact's depth (growing) [N per Pa of shear modulus]
    double force_slope = 0.0;    ///< dF/dd [N/m] of a growing step tried at this depth (eq. L11); 0 otherwise
    double position = 0.0;       ///< loading position of t1 (LoadingRecord); while growing, the last node's
    bool grows_again = false;    ///< receding: t1 would move forward (outside Ting's solution)
    /// dd/dt [m/s] at this node that a parallel dashpot saw, where the depth is solved (trapezoidal rate); unknown
    /// before the first contact of a spring's indenter, after a jump without contact and after the loss.
    std::optional<double> rate;
    /// dF_el/dt [N per Pa of shear modulus, per s] at this node, where the depth is solved and the contact grows
    /// (or has not touched yet): the trapezoidal rate the dashpot's term eta dF_el/dt of eq. L11 takes.
    std::optional<double> elastic_force_rate;
    contact::LayerContactState contact;  ///< the elastic layer's equilibrium at a(t); none once lifted off
    PronyBranches centre_branches;       ///< of w0
    PronyBranches force_branches;        ///< of F_el (loading)
};

/// A displacement- or force-controlled history on a layer, in steps.
class LayerStepper {
public:
    /// Starts at `time`, untouched; `unit_modulus` is E* / G of the layer (4, G the effective modulus of eq. 56),
    /// `largest_depth` [m] the scale of the solves' tolerances, `dashpot` the rate a parallel dashpot sees.
    LayerStepper(const rheology::Rheology& material, const contact::LayerContact& layer, double unit_modulus,
                 double time, double largest_depth, const DashpotRate& dashpot = {});
    /// The committed state.
    const LayerStep& current() const { return current_; }
    /// A step to `time` with the indenter at `depth`, the contact growing (Lee-Radok, eq. L11; meaningful for a
    /// depth >= the current one).
    LayerStep grow(double time, double depth) const;
    /// The growing step to `time` (eq. L11) at which F + k d = `right_side` [N] with k = `stiffness` [N/m] (force
    /// control: k = 0; spring control; an impact's trapezoidal rule), solved over the contact radius to
    /// `force_tolerance` [N]: one elastic solve a trial (at_radius), none for the depth. A contact of zero radius
    /// where the force at no contact already exceeds the right side (then the contact cannot grow). Not for a flat
    /// punch (its radius is fixed). Throws mdr::InvalidInput (key `layer`) beyond the layer's largest radius.
    LayerStep grow_to(double time, double stiffness, double right_side, double force_tolerance) const;
    /// A step to `time` with the indenter at `depth`, the contact receding (Ting, eq. L12, L13): lifted off when
    /// int_0^t G dd <= 0. Needs a growing phase before.
    LayerStep recede(double time, double depth) const;
    /// A step to `time` after the contact was lost: the free centre (eq. L14).
    LayerStep recover(double time) const;
    /// A step to `time` before any contact.
    LayerStep wait(double time) const;
    /// A jump of the force to `force` [N] at the current time against the parallel dashpot of a solved depth: the
    /// depth stays, the rate jumps (growing: dF = eta dF_el/dd d(rate), eq. L11; receding: the rate at which
    /// L12-L13 give that force, t1 moving back). Without contact, or without a known rate, the force is taken as
    /// the dashpot's and the rate becomes unknown. `grows_again` where the force would move t1 forward.
    LayerStep jump(double force) const;
    /// Makes `step` the current state (a growing one is recorded for Ting's solution).
    void commit(const LayerStep& step);
    /// The times [s] of the loading record since the last untouched state (eq. L12's t1 runs over it): its start, then
    /// each growing step committed.
    std::span<const double> loading_times() const { return loading_.times(); }
    /// The elastic layer's equilibrium at each time of loading_times (none at the start).
    std::span<const contact::LayerContactState> loading_contacts() const { return loading_contacts_; }

private:
    // The growing step with the elastic equilibrium `contact` at `depth` (< 0: the contact's own depth).
    LayerStep grow_with(double time, const contact::LayerContactState& contact, double depth) const;
    // The receding step at `depth` whose dashpot sees `rate` [m/s] (eq. L12).
    LayerStep recede_at_rate(double time, double depth, double rate) const;
    // The rate at the end of a step of `step` [s] changing the depth by `change` (trapezoidal, or the secant one).
    double end_rate(double step, double change) const;
    // dd/dt of a growing (or untouched) `state` from its dF_el/dt = E* S dd/dt (eq. L5); unknown where S = 0.
    std::optional<double> depth_rate(const LayerStep& state) const;

    const rheology::Rheology* material_;
    const contact::LayerContact* layer_;
    double unit_modulus_;
    double largest_depth_;
    LoadingRecord loading_;
    // The elastic equilibrium at each node of loading_ (none at its start): where the solves at a depth of the
    // loading (Ting's d(t1)) start, interpolated between the nodes around it.
    std::vector<contact::LayerContactState> loading_contacts_;
    LayerStep current_;
    double previous_radius_ = 0.0;  // the contact radius of the state before the current one
    bool trapezoidal_;              // the dashpot sees the trapezoidal rate of a solved depth
    bool indenter_motion_;          // of the depth while growing too (DashpotRate::indenter_motion)
    double touch_stiffness_;        // dF_el/dd / E* as the indenter touches (LayerContact::touch_stiffness)
    // The last equilibrium solved, tried or committed: where the next solve starts (the force-controlled driver
    // tries depths ever closer to its root).
    mutable contact::LayerContactState hint_;
};

}  // namespace mdr::drivers
