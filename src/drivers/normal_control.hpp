#pragma once
// The history-driven controls in the drivers. What each does in HistoryStepping (history_stepping.hpp), its step in
// the one loop of run_indentation (indentation.cpp), is a step class: its grid cuts and grid, its starting depth, the
// depth at the end of a step, the force of a jump, the depth and load shown, and its own observers. One step class
// per history-driven control type of LoadControl (load_control.hpp), made from its data, and beside it the type's
// ControlTraits (control_traits.hpp); an impact is a stepping class of its own (impact_stepping.hpp).

#include <algorithm>
#include <optional>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/foundation/foundation.hpp"
#include "control_traits.hpp"
#include "history_stepping.hpp"
#include "layer_loading.hpp"
#include "observer_list.hpp"
#include "paused_base.hpp"
#include "recorders.hpp"
#include "stepping.hpp"

namespace mdr::drivers {

/// Common defaults: no z column, no grid cuts or extra observers, no grading towards zeros, the grid as made, the
/// indenter starting at the surface and never moving free of the body, the depth shown as stepped and the prescribed
/// value as the load, nothing to do at a settled node.
class HistoryControl {
public:
    /// The steps are graded towards each time the history falls to zero (only a force's: the contact ends there).
    static constexpr bool graded_towards_zeros = false;
    bool base_column() const { return false; }  ///< z is a column of the result
    void add_cuts(std::vector<double>& /*cuts*/, double /*end_time*/) const {}
    void shape_grid(std::vector<GridNode>& /*nodes*/) const {}
    double start_depth(const GridNode& /*first*/) const { return 0.0; }
    /// The depth at the step's end if nothing touched the indenter, where it moves free of the body (a spring's
    /// base carries it); none where the depth is prescribed or a force needs a contact.
    std::optional<double> free_depth(double /*target*/) const { return std::nullopt; }
    void add_observers(ObserverList& /*observers*/, IndentationResult& /*result*/) {}
    void begin_step(double /*from*/, double /*to*/) {}
    double shown_depth(double depth, double /*target*/, const foundation::Foundation& /*foundation*/) const {
        return depth;
    }
    double shown_load(double target, double /*depth*/) const { return target; }
    void settled(double /*time*/, double /*force*/, double /*depth*/, double /*history_value*/) {}
};

/// The history prescribes the depth (eq. 16): each step goes to it.
class DisplacementStepping : public HistoryControl {
public:
    explicit DisplacementStepping(const DisplacementControl& /*control*/) {}
    static constexpr bool solves_depth = false;  ///< the depth is given; no trapezoidal rate of its own
    double target(double history_value) const { return history_value; }
    double jump_force(double /*target*/, double /*depth*/, const foundation::Foundation& foundation) const {
        return foundation.total_force();
    }
    double step_depth(const foundation::Foundation& /*foundation*/, double /*depth*/, const DepthGuess& /*start*/,
                      double target) const {
        return target;
    }
};

template <>
struct ControlTraits<DisplacementControl> : HistoryControlTraits<DisplacementControl, DisplacementStepping> {
    static std::vector<ControlKind> rows();
    static const char* row_name(const DisplacementControl& /*control*/) { return "displacement"; }
    /// The layer's drivers prescribe the depth.
    static LayerLoading on_layer(const ContactCase& /*contact_case*/, const DisplacementControl& /*control*/) {
        return {.prescribes_depth = true};
    }
    /// No jump in depth against a dashpot; a harmonic's rules.
    static void validate(const ContactCase& contact_case, const DisplacementControl& control);
    /// 1.1 times the Lee-Radok radius g^-1 at the largest depth (an upper bound under unloading too: the free
    /// surface never rises above the undeformed level).
    static double largest_contact_radius(const ContactCase& contact_case, const DisplacementControl& control,
                                         double peak, const ForceRadiusBound& force_bound);
};

/// The history prescribes the force F >= 0 (eq. 19): each step solves F(d) = target on the foundation.
class ForceStepping : public HistoryControl {
public:
    explicit ForceStepping(const ForceControl& /*control*/) {}
    static constexpr bool solves_depth = true;
    static constexpr bool graded_towards_zeros = true;
    /// The sine's round-off at a zero of the validated (>= 0) prescribed force is no pull.
    double target(double history_value) const { return std::max(history_value, 0.0); }
    /// A jump against a dashpot: the dashpot takes the prescribed force at once.
    double jump_force(double target, double /*depth*/, const foundation::Foundation& /*foundation*/) const {
        return target;
    }
    double step_depth(const foundation::Foundation& foundation, double depth, const DepthGuess& start,
                      double target) const {
        return solve_depth(foundation, depth, start.guess, start.scale, target, 0.0, 0.0);
    }
    /// Riding on the recovering surface without force: the depth shown is where the surface touches, located
    /// between the centres (the foundation keeps stepping from its own depth).
    double shown_depth(double depth, double target, const foundation::Foundation& foundation) const {
        return target == 0.0 ? std::min(depth, foundation.touching_depth()) : depth;
    }
};

template <>
struct ControlTraits<ForceControl> : HistoryControlTraits<ForceControl, ForceStepping> {
    static std::vector<ControlKind> rows();
    static const char* row_name(const ForceControl& /*control*/) { return "force"; }
    /// The layer's drivers solve for the prescribed force.
    static LayerLoading on_layer(const ContactCase& /*contact_case*/, const ForceControl& /*control*/) {
        return {};
    }
    /// No negative force in the history; a harmonic's rules, and it must not make the force pull.
    static void validate(const ContactCase& contact_case, const ForceControl& control);
    /// The force-control bound at the largest force.
    static double largest_contact_radius(const ContactCase& contact_case, const ForceControl& control, double peak,
                                         const ForceRadiusBound& force_bound);
};

/// The history prescribes the base z of a spring k: each step solves F(d) + k d = k z; a force pause (PausedBase)
/// holds the force instead, F(d) = the force held; a durometer's indenter stops at its full extension.
class SpringStepping : public HistoryControl {
public:
    static constexpr bool solves_depth = true;
    explicit SpringStepping(const SpringControl& control)
        : control_(control),
          paused_(control.force_pauses.empty()
                      ? std::nullopt
                      : std::make_optional<PausedBase>(control.force_pauses, control.spring_constant)) {}
    /// z is a column of its own, except in a Shore test (its reading is).
    bool base_column() const { return !control_.shore; }
    /// Each Shore reading and each pause's ends on a node of its own.
    void add_cuts(std::vector<double>& cuts, double end_time) const {
        if (control_.shore) {
            for (const double time : shore_reading_times) {
                if (time <= end_time) cuts.push_back(time);
            }
        }
        for (const ForcePause& pause : control_.force_pauses) cuts.insert(cuts.end(), {pause.start, pause.end});
    }
    /// The base starts where it is (z <= 0, validated): no jump from z = 0. A Shore test keeps its step at t = 0,
    /// the foot's landing.
    void shape_grid(std::vector<GridNode>& nodes) const {
        if (!control_.shore && nodes.size() > 1 && nodes[1].time == nodes[0].time) nodes.erase(nodes.begin());
    }
    /// The massless indenter rests on the unloaded spring, d = z, until it touches the surface.
    double start_depth(const GridNode& first) const { return first.value; }
    void add_observers(ObserverList& observers, IndentationResult& result) {
        if (control_.shore) observers.add(shore_readings_.emplace(control_.shore->instrument, result));
    }
    /// Out of contact the indenter hangs at the base, d = z, up to the durometer's stop; a force pause holds a
    /// contact.
    std::optional<double> free_depth(double target) const {
        if (holding_) return std::nullopt;
        return control_.shore ? std::min(target, control_.shore->instrument.full_extension()) : target;
    }
    void begin_step(double from, double to) { holding_ = paused_ && paused_->holding(from, to); }
    /// The base: the history shifted by the pauses passed (PausedBase).
    double target(double history_value) const { return paused_ ? paused_->base(history_value) : history_value; }
    /// A jump against a dashpot (only a Shore test has one, at the foot's landing): the spring's force.
    double jump_force(double target, double depth, const foundation::Foundation& /*foundation*/) const {
        return control_.spring_constant * (target - depth);
    }
    double step_depth(const foundation::Foundation& foundation, double depth, const DepthGuess& start,
                      double target) const {
        const double k = control_.spring_constant;
        const double depth_end = holding_ ? solve_depth(foundation, depth, start.guess, start.scale,
                                                        paused_->held_force(), 0.0, 0.0)
                                          : solve_depth(foundation, depth, start.guess, start.scale, k * target, k,
                                                        0.0);
        // A durometer's indenter stops at its full extension (reading 0): the stop takes the rest.
        return control_.shore ? std::min(depth_end, control_.shore->instrument.full_extension()) : depth_end;
    }
    /// In a pause the feedback's base: z = d + F / k.
    double shown_load(double target, double depth) const {
        return holding_ ? paused_->base_in_pause(depth) : target;
    }
    void settled(double time, double force, double depth, double history_value) {
        if (paused_) paused_->passed(time, force, depth, history_value);
    }

private:
    const SpringControl& control_;
    std::optional<PausedBase> paused_;
    bool holding_ = false;
    std::optional<ShoreRecorder> shore_readings_;
};

template <>
struct ControlTraits<SpringControl> : HistoryControlTraits<SpringControl, SpringStepping> {
    /// spring, then shore (a spring control with a durometer).
    static std::vector<ControlKind> rows();
    static const char* row_name(const SpringControl& control) { return control.shore ? "shore" : "spring"; }
    /// The layer's drivers solve for the spring's base, its pauses and a durometer's test as on the half-space.
    static LayerLoading on_layer(const ContactCase& /*contact_case*/, const SpringControl& control) {
        return {.spring_constant = control.spring_constant,
                .force_pauses = &control.force_pauses,
                .shore = control.shore ? &*control.shore : nullptr};
    }
    /// A Shore test: its durometer in the case's units (make_shore_test: the spring, refusing a constant of the
    /// control's own, `load.spring_constant`), the standard's indenter and base history; a plain spring: nothing.
    static BroughtParts bring(const SpringControl& control, double length_unit, double force_unit);
    /// A Shore test: the durometer's standard indenter, which the case does not give.
    static ControlBrings brings(const SpringControl& control) { return {.indenter = control.shore.has_value()}; }
    /// A Shore test: its durometer (spring force at reading 100, its rate, one point's depth) and duration; a plain
    /// spring: its history with the spring constant, harmonic and force pauses.
    static std::string describe(const ContactCase& contact_case, const SpringControl& control,
                                const rheology::UnitNames& unit_names);
    /// A harmonic's rules; a spring constant > 0; a base history starting at or above the surface (z <= 0) without
    /// jumps, or a Shore test's rules (a duration > 0, the durometer's spring, no harmonic, no tangential load).
    static void validate(const ContactCase& contact_case, const SpringControl& control);
    /// Force pauses (none in a Shore test) in time order and apart, each starting after the history's first time,
    /// ending after its start and by the end, and not overlapping a harmonic.
    static void validate_within_run(const ContactCase& contact_case, const SpringControl& control);
    /// The smaller of the displacement-control bound at the largest base (d <= z) and the force-control one at the
    /// force k max z (F <= k z); with force pauses the largest base bounded by paused_base_peak.
    static double largest_contact_radius(const ContactCase& contact_case, const SpringControl& control, double peak,
                                         const ForceRadiusBound& force_bound);
};

}  // namespace mdr::drivers
