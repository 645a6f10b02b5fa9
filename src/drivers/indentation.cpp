#include "mdr/drivers/indentation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "cycle_measure.hpp"
#include "observer_list.hpp"
#include "normal_control.hpp"
#include "recorders.hpp"
#include "stepping.hpp"
#include "tangential_stepping.hpp"

namespace mdr::drivers {
namespace {

// The indenter's rate after a force jump dF at fixed depth: the dashpots of the n elements in contact take it,
// dF = 8 dx eta n d(rate) (eq. 16, 21); unknown without contact.
std::optional<double> jumped_rate(const foundation::Foundation& foundation, double viscosity, double rate,
                                  double force_jump) {
    const auto contacts = static_cast<double>(foundation.contact_count());
    if (contacts == 0.0) return std::nullopt;
    return rate + force_jump / (8.0 * foundation.spacing() * viscosity * contacts);
}

// The rate at the end of a force-controlled step: the trapezoidal 2 dd/dt - rate0, or the secant dd/dt after a
// step without a known start rate (what the dashpots saw, so that the next step starts in equilibrium).
std::optional<double> next_rate(const foundation::Foundation& foundation, std::optional<double> rate,
                                double depth_start, double depth_end, double time_step) {
    if (foundation.contact_count() == 0) return std::nullopt;
    const double secant = (depth_end - depth_start) / time_step;
    return rate ? 2.0 * secant - *rate : secant;
}

}  // namespace

namespace {

// The time grid of a history-driven control: the history's points, the cuts of the snapshots, the tangential load,
// the harmonic and the control, graded after fast changes, with the harmonic added to the history's values.
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

// The one loop of a history-driven control (normal_control.hpp): the grid (the history's points, the cuts of the
// snapshots, the tangential load, the harmonic and the control), then each step (the control's depth, the
// tangential layer's step), then the observers.
template <class Control>
IndentationResult run_history(const ContactCase& contact_case, Control& control, const ProgressObserver& progress,
                              const StepObservers& extra_observers) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    const auto& material = contact_case.material;
    const auto& indenter = *contact_case.indenter;
    foundation::Foundation foundation(material, indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    std::optional<TangentialStepper> tangential;
    if (contact_case.tangential) {
        tangential.emplace(*contact_case.tangential, material, foundation, contact_case.end_time);
    }
    std::optional<CycleMeasure> cycle;
    if (const auto& harmonic = contact_case.load.harmonic) cycle.emplace(*harmonic, contact_case.end_time);
    const auto nodes = history_grid(contact_case, numerics, control);
    CoefficientCache cache(material);
    const bool has_dashpot = material.viscosity() > 0.0;
    const double depth_scale = std::isfinite(indenter.equivalent(numerics.half_width))
                                   ? std::max(indenter.equivalent(numerics.half_width), 1e-300)
                                   : numerics.half_width;

    // The standard observers fill the result; the caller's follow them.
    ObserverList observers(numerics.output_every);
    RowRecorder rows(result, {.velocity = false, .base = control.base_column()});
    observers.add(rows);
    control.add_observers(observers, result);
    std::optional<TangentialColumns<TangentialStepper>> tangential_columns;
    if (tangential) observers.add(tangential_columns.emplace(*tangential, result));
    SnapshotRecorder::ShearStress shear_stress;
    if (tangential) shear_stress = [&](Snapshot& snapshot) { tangential->add_shear_stress(snapshot); };
    SnapshotRecorder snapshots(contact_case.snapshots, indenter, result, std::move(shear_stress));
    observers.add(snapshots);
    if (cycle) observers.add(*cycle);
    std::optional<ProgressReport> progress_report;
    if (progress) observers.add(progress_report.emplace(progress));
    observers.add(extra_observers);

    double depth = control.start_depth(nodes.front());
    const std::size_t last_node = nodes.size() - 1;
    StepState state{.time = nodes.front().time, .depth = depth, .load = nodes.front().value,
                    .last = last_node == 0, .foundation = &foundation};
    bool stopped = observers.notify(state);

    double previous_depth = depth;
    double shown_depth = depth;
    // A control that solves for the depth, with a parallel dashpot: the indenter's rate dd/dt at the current node,
    // so that the dashpot sees the trapezoidal rate (second order, see Foundation::begin_step). Unknown (the secant
    // rate is used for one step) while nothing is in contact: the rate is then not tied to the force.
    const bool trapezoidal = has_dashpot && Control::solves_depth;
    std::optional<double> rate = trapezoidal ? std::optional<double>(0.0) : std::nullopt;
    const bool sine_rate = has_dashpot && !Control::solves_depth && contact_case.load.harmonic;
    double last_force = 0.0;

    for (std::size_t n = 1; n <= last_node && !stopped; ++n) {
        const double time_step = nodes[n].time - nodes[n - 1].time;
        control.begin_step(nodes[n - 1].time, nodes[n].time);
        const double target = control.target(nodes[n].value);
        double load = target;
        double force = 0.0;
        if (time_step == 0.0 && has_dashpot) {
            // A jump against a dashpot: the dashpot takes the force at once and the depth does not move.
            force = control.jump_force(target, depth, foundation);
            if (rate) rate = jumped_rate(foundation, material.viscosity(), *rate, force - last_force);
            shown_depth = depth;
        } else {
            if (sine_rate) {
                // A prescribed depth under a harmonic with a dashpot: the depth is not linear inside a step, and
                // the secant rate would be first order at the nodes. The dashpot takes the trapezoidal rate from the
                // prescribed rate at the step's start, the history's slope plus the sine's rate (second order).
                const auto& harmonic = *contact_case.load.harmonic;
                const double t0 = nodes[n - 1].time, t1 = nodes[n].time;
                const double history_change =
                    (nodes[n].value - harmonic.value(t1)) - (nodes[n - 1].value - harmonic.value(t0));
                rate = history_change / time_step + harmonic.rate(t0);
            }
            foundation.begin_step(cache.get(time_step), rate);
            const DepthGuess start{.guess = depth + (depth - previous_depth),
                                   .scale = std::max(std::abs(depth - previous_depth), 1e-6 * depth_scale)};
            const double new_depth = control.step_depth(foundation, depth, start, target);
            foundation.advance(depth, new_depth);
            if (trapezoidal) rate = next_rate(foundation, rate, depth, new_depth, time_step);
            if (tangential) tangential->step(cache.get(time_step), nodes[n - 1].time, nodes[n].time);
            previous_depth = depth;
            depth = new_depth;
            force = foundation.total_force();
            shown_depth = control.shown_depth(depth, target, foundation);
            load = control.shown_load(target, depth);
        }
        last_force = force;
        ++result.steps;
        const bool settled = n == last_node || nodes[n + 1].time != nodes[n].time;
        if (settled) control.settled(nodes[n].time, force, depth, nodes[n].value);
        state = {.step = n, .time = nodes[n].time, .depth = shown_depth, .force = force, .load = load,
                 .fraction = static_cast<double>(n) / static_cast<double>(last_node), .settled = settled,
                 .last = n == last_node, .foundation = &foundation};
        stopped = observers.notify(state);
    }
    result.stopped = observers.stopped();
    if (result.stopped) return result;  // the outcomes need the whole run
    if (tangential) result.tangential = tangential->outcome();
    if (cycle) result.harmonic = cycle->outcome();
    return result;
}

// The stepping of each history-driven control; an impact is run_impact's.
struct HistoryRun {
    const ContactCase& contact_case;
    const ProgressObserver& progress;
    const StepObservers& observers;

    IndentationResult operator()(const DisplacementControl&) const {
        DisplacementStepping stepping;
        return run_history(contact_case, stepping, progress, observers);
    }
    IndentationResult operator()(const ForceControl&) const {
        ForceStepping stepping;
        return run_history(contact_case, stepping, progress, observers);
    }
    IndentationResult operator()(const SpringControl& spring) const {
        SpringStepping stepping(spring);
        return run_history(contact_case, stepping, progress, observers);
    }
    IndentationResult operator()(const ImpactControl&) const {
        throw InvalidInput("load.control", "\"impact\"", "is run by run_impact, not run_indentation");
    }
};

// The grid of each history-driven control (indentation_grid); an impact has no history grid.
struct HistoryGrid {
    const ContactCase& contact_case;
    const ResolvedNumerics& numerics;

    std::vector<GridNode> operator()(const DisplacementControl&) const {
        return history_grid(contact_case, numerics, DisplacementStepping{});
    }
    std::vector<GridNode> operator()(const ForceControl&) const {
        return history_grid(contact_case, numerics, ForceStepping{});
    }
    std::vector<GridNode> operator()(const SpringControl& spring) const {
        return history_grid(contact_case, numerics, SpringStepping(spring));
    }
    std::vector<GridNode> operator()(const ImpactControl&) const {
        throw InvalidInput("load.control", "\"impact\"", "has no history grid (run_impact steps it)");
    }
};

}  // namespace

std::vector<GridNode> indentation_grid(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    return std::visit(HistoryGrid{contact_case, numerics}, contact_case.control);
}

IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                  const StepObservers& extra_observers) {
    return std::visit(HistoryRun{contact_case, progress, extra_observers}, contact_case.control);
}

}  // namespace mdr::drivers
