#pragma once
// The stepping class of a history-driven control (displacement, force, spring) in the one loop (indentation.cpp):
// its grid (the history's points with the cuts of the snapshots, the tangential load, the harmonic and the control,
// graded after fast changes), its step (jumps against a dashpot, the trapezoidal rate, the control's depth, the
// tangential layer's step) and its outcomes (tangential, harmonic). What differs between the three controls is a
// step class of normal_control.hpp; HistoryControlTraits is what their ControlTraits share.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/rheology/material_models.hpp"
#include "control_traits.hpp"
#include "cycle_measure.hpp"
#include "default_numerics.hpp"
#include "observer_list.hpp"
#include "recorders.hpp"
#include "stepping.hpp"
#include "tangential_stepping.hpp"

namespace mdr::drivers {

/// Where the depth solve of a step starts: the extrapolated guess and the scale of its bracket.
struct DepthGuess {
    double guess = 0.0;  ///< d0 + (d0 - d_previous)
    double scale = 0.0;  ///< |d0 - d_previous|, at least a small fraction of the depth scale
};

/// The time grid of a history-driven control: the history's points, the cuts of the snapshots, the tangential load,
/// the harmonic and the control, graded after fast changes, with the harmonic added to the history's values.
template <class Control>
std::vector<GridNode> history_grid(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                                   const Control& control) {
    std::vector<double> cuts = contact_case.snapshots;
    if (contact_case.tangential) {
        const auto breakpoints = contact_case.tangential->load.breakpoints();
        cuts.insert(cuts.end(), breakpoints.begin(), breakpoints.end());
    }
    if (const auto& harmonic = contact_case.load.harmonic) {
        const auto breakpoints = harmonic->breakpoints();
        cuts.insert(cuts.end(), breakpoints.begin(), breakpoints.end());
        if (const auto last = harmonic->last_full_cycle(contact_case.end_time)) {
            cuts.insert(cuts.end(), {last->first, last->second});  // the measured cycle on uniform steps
        }
    }
    control.add_cuts(cuts, contact_case.end_time);
    if (numerics.zero_grading_exponent > 0.0) {
        const auto towards_zeros =
            cuts_towards_zeros(*contact_case.load.history, contact_case.end_time, numerics.time_step,
                               numerics.min_segment_steps, zero_graded_fraction, numerics.zero_grading_exponent);
        cuts.insert(cuts.end(), towards_zeros.begin(), towards_zeros.end());
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    auto nodes = make_time_grid(*contact_case.load.history, contact_case.end_time, numerics.time_step,
                                numerics.min_segment_steps, cuts);
    control.shape_grid(nodes);
    if (numerics.grading_ratio > 0.0) {
        const auto changes = fast_change_times(*contact_case.load.history, contact_case.end_time, numerics.time_step,
                                               min_steps_per_segment);
        nodes = grade_after_changes(nodes, changes, numerics.grading_ratio, numerics.first_graded_step);
    }
    if (const auto& harmonic = contact_case.load.harmonic) {
        for (auto& node : nodes) node.value += harmonic->value(node.time);
    }
    return nodes;
}

/// Steps a history-driven control (`Control`: a step class of normal_control.hpp) node by node along history_grid,
/// with the tangential loading and the harmonic cycle measure of the case; the run ends at the grid's last node.
template <class Control>
class HistoryStepping {
public:
    /// `contact_case`, `numerics`, `foundation` and `data` (the case's control, from which the step class is made)
    /// must outlive the stepping.
    template <class ControlData>
    HistoryStepping(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                    foundation::Foundation& foundation, const ControlData& data)
        : contact_case_(contact_case),
          foundation_(foundation),
          control_(data),
          cache_(contact_case.material),
          nodes_(history_grid(contact_case, numerics, control_)),
          last_node_(nodes_.size() - 1),
          has_dashpot_(contact_case.material.viscosity() > 0.0),
          trapezoidal_(has_dashpot_ && Control::solves_depth),
          sine_rate_(has_dashpot_ && !Control::solves_depth && contact_case.load.harmonic),
          rate_(trapezoidal_ ? std::optional<double>(0.0) : std::nullopt),
          depth_(control_.start_depth(nodes_.front())),
          previous_depth_(depth_) {
        const double equivalent = contact_case.indenter->equivalent(numerics.half_width);
        depth_scale_ = std::isfinite(equivalent) ? std::max(equivalent, 1e-300) : numerics.half_width;
        if (contact_case.tangential) {
            tangential_.emplace(*contact_case.tangential, contact_case.material, foundation, contact_case.end_time);
        }
        if (const auto& harmonic = contact_case.load.harmonic) cycle_.emplace(*harmonic, contact_case.end_time);
    }

    /// The control's observers, the tangential columns and the harmonic cycle measure.
    void add_observers(ObserverList& observers, IndentationResult& result) {
        control_.add_observers(observers, result);
        if (tangential_) observers.add(tangential_columns_.emplace(*tangential_, result));
        if (cycle_) observers.add(*cycle_);
    }
    /// The tangential layer's shear stress in snapshots, with tangential loading.
    FoundationSnapshots::ShearStress shear_stress() {
        if (!tangential_) return {};
        return [this](Snapshot& snapshot) { tangential_->add_shear_stress(snapshot); };
    }
    /// The state at the grid's first node.
    StepState first_state() const {
        return {.time = nodes_.front().time, .depth = depth_, .load = nodes_.front().value, .last = last_node_ == 0,
                .foundation = &foundation_};
    }

    /// The step to node `n` (1, 2, ...): the control's depth (a jump against a dashpot keeps it), then the
    /// tangential layer's step (its jump, TangentialStepper::jump, at a jump against a dashpot); the last node ends
    /// the run.
    StepState step(std::size_t n) {
        const double time_step = nodes_[n].time - nodes_[n - 1].time;
        control_.begin_step(nodes_[n - 1].time, nodes_[n].time);
        const double target = control_.target(nodes_[n].value);
        double load = target;
        double force = 0.0;
        double shown_depth = depth_;  // a jump keeps it
        if (time_step == 0.0 && has_dashpot_) {
            // A jump against a dashpot: the dashpots take the force at once and the depth does not move; under a
            // force the contact may recede at once (Foundation::jump, eq. J1), and the rate is unknown without one.
            force = control_.jump_force(target, depth_, foundation_);
            if (rate_) {
                const auto rate_change = foundation_.jump(force);
                rate_ = rate_change ? std::optional<double>(*rate_ + *rate_change) : std::nullopt;
            }
            // The tangential layer takes the same jump with the normal state after it (eq. T1, T2).
            if (tangential_) tangential_->jump(nodes_[n].time);
        } else {
            if (sine_rate_) {
                // A prescribed depth under a harmonic with a dashpot: the depth is not linear inside a step, and
                // the secant rate would be first order at the nodes. The dashpot takes the trapezoidal rate from the
                // prescribed rate at the step's start, the history's slope plus the sine's rate (second order).
                rate_ = contact_case_.load.start_rate(nodes_[n - 1].time, nodes_[n - 1].value, nodes_[n].time,
                                                      nodes_[n].value);
            }
            // The step from the touch on (all of it unless the indenter moves free and touches inside it).
            const double touch_time = trapezoidal_ ? free_until_touch(time_step, target) : 0.0;
            const double contact_step = time_step - touch_time;
            const double before = touch_time > 0.0 ? depth_ : previous_depth_;
            foundation_.begin_step(cache_.get(contact_step), rate_, rate_at_entry);
            const DepthGuess start{.guess = depth_ + (depth_ - before),
                                   .scale = std::max(std::abs(depth_ - before), 1e-6 * depth_scale_)};
            const double new_depth = control_.step_depth(foundation_, depth_, start, target);
            foundation_.advance(depth_, new_depth);
            if (trapezoidal_) rate_ = next_rate();
            if (tangential_) tangential_->step(cache_.get(time_step), nodes_[n - 1].time, nodes_[n].time);
            previous_depth_ = depth_;
            depth_ = new_depth;
            force = foundation_.total_force();
            shown_depth = control_.shown_depth(depth_, target, foundation_);
            load = control_.shown_load(target, depth_);
        }
        const bool settled = n == last_node_ || nodes_[n + 1].time != nodes_[n].time;
        if (settled) control_.settled(nodes_[n].time, force, depth_, nodes_[n].value);
        return {.step = n, .time = nodes_[n].time, .depth = shown_depth, .force = force, .load = load,
                .fraction = static_cast<double>(n) / static_cast<double>(last_node_), .settled = settled,
                .last = n == last_node_, .foundation = &foundation_};
    }

    /// The tangential and harmonic outcomes of the whole run.
    void add_outcomes(IndentationResult& result) const {
        if (tangential_) result.tangential = tangential_->outcome();
        if (cycle_) result.harmonic = cycle_->outcome();
    }

private:
    // A massless indenter under a force: its rate breaks where an element enters (Foundation::begin_step).
    static constexpr foundation::RateAtEntry rate_at_entry =
        Control::solves_depth ? foundation::RateAtEntry::breaks : foundation::RateAtEntry::continuous;
    // With a parallel dashpot, a step that starts with nothing in contact while the indenter moves free (a spring's
    // base carries it, Step::free_depth) is split where the free indenter touches the body (Foundation::
    // touch_fraction): the foundation steps free up to the touch, and depth_ moves there. The rest of the step is
    // solved from the touch with the dashpots at rest: the indenter's rate breaks at the touch (F = k (z - d) is
    // continuous, so the dashpots in contact stop it), and the approach's rate in a dashpot would be a force out of
    // balance with the spring. Nothing is in contact at the touch: every element in contact after it entered after
    // it and takes its own trapezoidal rate from its own start (Foundation::begin_step). Returns the time stepped
    // free (0: no split).
    double free_until_touch(double time_step, double target) {
        if (foundation_.contact_count() != 0) return 0.0;
        const auto free_end = control_.free_depth(target);
        if (!free_end) return 0.0;
        foundation_.begin_step(cache_.get(time_step), rate_, rate_at_entry);
        const double fraction = foundation_.touch_fraction(depth_, *free_end);
        if (!(fraction > 0.0 && fraction < 1.0)) return 0.0;
        const double touch_time = fraction * time_step;
        const double touch_depth = depth_ + fraction * (*free_end - depth_);
        foundation_.begin_step(cache_.get(touch_time), rate_, rate_at_entry);
        foundation_.advance(depth_, touch_depth);
        depth_ = touch_depth;
        rate_ = 0.0;
        return touch_time;
    }
    // The rate at the end of a force-controlled step: what the dashpots in contact saw, so that the next step starts
    // in equilibrium (Foundation::contact_rate: the trapezoidal 2 dd/dt - rate0, or the secant dd/dt after a step
    // without a known start rate, with an element that entered in the step taking its own rate). A step that ends
    // without contact (force control at zero force: the indenter rides on the recovering surface; a spring's
    // indenter hanging free) carries the indenter's own end rate: an element it reaches in the next step then takes
    // the trapezoidal rate from its own start rate, the law of a free element, so that it enters with a force >= 0
    // exactly where the indenter reaches its free surface. (Unknown there, the entering element took the secant, a
    // different law: riding at zero force it entered past its free surface at a negative force clamped to zero, the
    // indenter sank past the surface by the gap between the two laws, first order in the step, and the elements were
    // flagged in contact on alternate rows; docs/theory.md section 3.)
    std::optional<double> next_rate() const { return foundation_.contact_rate(); }

    const ContactCase& contact_case_;
    foundation::Foundation& foundation_;
    Control control_;
    CoefficientCache cache_;
    std::vector<GridNode> nodes_;
    std::size_t last_node_;
    // g at the half-width (the half-width where g is infinite): a millionth of it is the smallest bracket of a
    // depth solve.
    double depth_scale_ = 0.0;
    bool has_dashpot_;
    bool trapezoidal_;  // a control that solves for the depth, with a parallel dashpot
    bool sine_rate_;    // a prescribed depth under a harmonic, with a parallel dashpot
    // The rate dd/dt at the current node that the dashpots in contact see (Foundation::begin_step, contact_rate):
    // trapezoidal (second order) when the control solves for the depth, zero from rest (the start, a touch); unknown
    // (the secant rate is used for one step) after a force jump with nothing in contact, as the rate is then not
    // tied to the force.
    std::optional<double> rate_;
    double depth_;
    double previous_depth_;
    std::optional<TangentialStepper> tangential_;
    std::optional<TangentialColumns<TangentialStepper>> tangential_columns_;
    std::optional<CycleMeasure> cycle_;
};

/// The load of a history-driven control named `name` (describe_load): its history's points and times, then `own`
/// (the control's own data, " (spring k = ...)"; "" for none), then its harmonic.
std::string describe_history(const ContactCase& contact_case, const std::string& name, const std::string& own,
                             const rheology::UnitNames& unit_names);

/// What the ControlTraits (control_traits.hpp) of every history-driven control `Control` share: HistoryStepping over
/// its step class `Step` (normal_control.hpp, made from the control's data), its grid (history_grid), its default
/// numerics (resolve_history_numerics: graded steps when Step solves for the depth, towards a falling force's zeros
/// when Step::graded_towards_zeros, the half-width from
/// `ControlTraits<Control>::largest_contact_radius`), its description by its row's name (describe_history) and no
/// rules within the run unless its traits have some.
template <class Control, class Step>
struct HistoryControlTraits {
    using Stepping = HistoryStepping<Step>;
    static constexpr bool ends_by_stop_rule = false;  ///< the run ends at the case's end, on the history's grid
    /// Brings nothing: its history and indenter are the case's (complete_control).
    static BroughtParts bring(const Control& control, double /*length_unit*/, double /*force_unit*/) {
        return {.control = control};
    }
    /// Nothing of its own: the case's indenter, no tangential part (brought_by).
    static ControlBrings brings(const Control& /*control*/) { return {}; }
    /// Its row's name, its history and harmonic (describe_history).
    static std::string describe(const ContactCase& contact_case, const Control& control,
                                const rheology::UnitNames& unit_names) {
        return describe_history(contact_case, ControlTraits<Control>::row_name(control), "", unit_names);
    }
    /// t, d, F, a and z when the control has a base column.
    static RowRecorder::Columns columns(const Control& control) {
        return {.velocity = false, .base = Step(control).base_column()};
    }
    static std::vector<GridNode> grid(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                                      const Control& control) {
        return history_grid(contact_case, numerics, Step(control));
    }
    static ResolvedNumerics resolve_numerics(const ContactCase& contact_case, const Control& control) {
        return resolve_history_numerics(
            contact_case, Step::solves_depth, Step::graded_towards_zeros,
            [&](double peak, const ForceRadiusBound& force_bound) {
                return ControlTraits<Control>::largest_contact_radius(contact_case, control, peak, force_bound);
            });
    }
    static void validate_within_run(const ContactCase& /*contact_case*/, const Control& /*control*/) {}
};

}  // namespace mdr::drivers
