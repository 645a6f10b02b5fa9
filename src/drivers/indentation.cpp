#include "mdr/drivers/indentation.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "cycle_measure.hpp"
#include "observer_list.hpp"
#include "paused_base.hpp"
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

IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress,
                                  const StepObservers& extra_observers) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const auto& numerics = result.numerics;
    const auto& material = contact_case.material;
    const auto& indenter = *contact_case.indenter;
    foundation::Foundation foundation(material, indenter,
                                      numerics.half_width / static_cast<double>(numerics.elements), numerics.elements);
    std::vector<double> cuts = contact_case.snapshots;
    std::optional<TangentialStepper> tangential;
    if (contact_case.tangential) {
        tangential.emplace(*contact_case.tangential, material, foundation, contact_case.end_time);
        const auto breakpoints = contact_case.tangential->load.breakpoints();
        cuts.insert(cuts.end(), breakpoints.begin(), breakpoints.end());
    }
    std::optional<CycleMeasure> cycle;
    if (const auto& harmonic = contact_case.load.harmonic) {
        cycle.emplace(*harmonic, contact_case.end_time);
        const auto breakpoints = harmonic->breakpoints();
        cuts.insert(cuts.end(), breakpoints.begin(), breakpoints.end());
        if (const auto last = harmonic->last_full_cycle(contact_case.end_time)) {
            cuts.insert(cuts.end(), {last->first, last->second});  // the measured cycle on uniform steps
        }
    }
    const SpringControl* spring_control = contact_case.spring();
    const ShoreTest* shore = contact_case.shore();
    if (shore) {
        for (const double time : shore_reading_times) {
            if (time <= contact_case.end_time) cuts.push_back(time);  // each reading on a node of its own
        }
    }
    std::optional<PausedBase> paused;
    if (spring_control && !spring_control->force_pauses.empty()) {
        paused.emplace(spring_control->force_pauses, spring_control->spring_constant);
        for (const ForcePause& pause : spring_control->force_pauses) cuts.insert(cuts.end(), {pause.start, pause.end});
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    auto nodes = make_time_grid(*contact_case.load.history, contact_case.end_time, numerics.time_step,
                                numerics.min_segment_steps, cuts);
    const bool spring = spring_control != nullptr;
    if (spring && !shore && nodes.size() > 1 && nodes[1].time == nodes[0].time) {
        nodes.erase(nodes.begin());  // the base starts where it is (z <= 0, validated): no jump from z = 0
    }
    if (numerics.grading_ratio > 0.0) {
        const auto changes = fast_change_times(*contact_case.load.history, contact_case.end_time, numerics.time_step,
                                               min_steps_per_segment);
        nodes = grade_after_changes(nodes, changes, numerics.grading_ratio, numerics.first_graded_step);
    }
    if (const auto& harmonic = contact_case.load.harmonic) {
        for (auto& node : nodes) node.value += harmonic->value(node.time);
    }
    CoefficientCache cache(material);
    const bool has_dashpot = material.viscosity() > 0.0;
    const double depth_scale = std::isfinite(indenter.equivalent(numerics.half_width))
                                   ? std::max(indenter.equivalent(numerics.half_width), 1e-300)
                                   : numerics.half_width;

    // The standard observers fill the result; the caller's follow them.
    ObserverList observers(numerics.output_every);
    RowRecorder rows(result, {.velocity = false, .base = spring && !shore});
    observers.add(rows);
    std::optional<ShoreRecorder> shore_readings;
    if (shore) observers.add(shore_readings.emplace(shore->instrument, result));
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

    // Spring control: the massless indenter rests on the unloaded spring, d = z, until it touches the surface.
    double depth = spring ? nodes.front().value : 0.0;
    const std::size_t last_node = nodes.size() - 1;
    StepState state{.time = nodes.front().time, .depth = depth, .load = nodes.front().value,
                    .last = last_node == 0, .foundation = &foundation};
    bool stopped = observers.notify(state);

    double previous_depth = depth;
    double shown_depth = depth;
    // Force or spring control with a parallel dashpot: the indenter's rate dd/dt at the current node, so that the
    // dashpot sees the trapezoidal rate (second order, see Foundation::begin_step). Unknown (the secant rate is
    // used for one step) while nothing is in contact: the rate is then not tied to the force.
    const bool displacement = std::holds_alternative<DisplacementControl>(contact_case.control);
    const bool force_control = std::holds_alternative<ForceControl>(contact_case.control);
    const bool trapezoidal = has_dashpot && !displacement;
    const double stiffness = spring ? spring_control->spring_constant : 0.0;
    std::optional<double> rate = trapezoidal ? std::optional<double>(0.0) : std::nullopt;
    const bool sine_rate = has_dashpot && displacement && contact_case.load.harmonic;
    double last_force = 0.0;

    for (std::size_t n = 1; n <= last_node && !stopped; ++n) {
        const double time_step = nodes[n].time - nodes[n - 1].time;
        // Force control: the sine's round-off at a zero of the validated (>= 0) prescribed force is no pull.
        // Spring control: the base, the history shifted by the pauses passed (PausedBase); a pause holds the force.
        const bool holding = paused && paused->holding(nodes[n - 1].time, nodes[n].time);
        const double target = force_control ? std::max(nodes[n].value, 0.0)
                              : paused      ? paused->base(nodes[n].value)
                                            : nodes[n].value;
        double base = target;
        double force = 0.0;
        if (time_step == 0.0 && has_dashpot) {
            // A jump against a dashpot: the dashpot takes the force at once and the depth does not move (spring
            // control has no jumps after the start).
            // (Under spring control only a Shore test has a jump, at the foot's landing: the spring's force.)
            force = force_control ? target : spring ? stiffness * (target - depth) : foundation.total_force();
            if (rate) rate = jumped_rate(foundation, material.viscosity(), *rate, force - last_force);
            shown_depth = depth;
        } else {
            if (sine_rate) {
                // Displacement control under a harmonic with a dashpot: the depth is not linear inside a step, and
                // the secant rate would be first order at the nodes. The dashpot takes the trapezoidal rate from the
                // prescribed rate at the step's start, the history's slope plus the sine's rate (second order).
                const auto& harmonic = *contact_case.load.harmonic;
                const double t0 = nodes[n - 1].time, t1 = nodes[n].time;
                const double history_change =
                    (nodes[n].value - harmonic.value(t1)) - (nodes[n - 1].value - harmonic.value(t0));
                rate = history_change / time_step + harmonic.rate(t0);
            }
            foundation.begin_step(cache.get(time_step), rate);
            double new_depth = target;
            if (!displacement) {
                // Force control: F(d) = target. Spring control: F(d) = k (z - d), i.e. F(d) + k d = k z. A force
                // pause: F(d) = the force held, as under force control (eq. 19).
                const double guess = depth + (depth - previous_depth);
                const double scale = std::max(std::abs(depth - previous_depth), 1e-6 * depth_scale);
                const double right_side = holding ? paused->held_force() : spring ? stiffness * target : target;
                new_depth = solve_depth(foundation, depth, guess, scale, right_side, holding ? 0.0 : stiffness, 0.0);
                // A durometer's indenter stops at its full extension (reading 0): the stop takes the rest.
                if (shore) new_depth = std::min(new_depth, shore->instrument.full_extension());
            }
            foundation.advance(depth, new_depth);
            if (trapezoidal) rate = next_rate(foundation, rate, depth, new_depth, time_step);
            if (tangential) tangential->step(cache.get(time_step), nodes[n - 1].time, nodes[n].time);
            previous_depth = depth;
            depth = new_depth;
            force = foundation.total_force();
            // Riding on the recovering surface without force: the depth shown is where the surface touches,
            // located between the centres (the foundation keeps stepping from its own depth).
            shown_depth = force_control && target == 0.0
                              ? std::min(depth, foundation.touching_depth())
                              : depth;
            if (holding) base = paused->base_in_pause(depth);  // the feedback's base: z = d + F / k
        }
        last_force = force;
        ++result.steps;
        const bool settled = n == last_node || nodes[n + 1].time != nodes[n].time;
        if (paused && settled) paused->passed(nodes[n].time, force, depth, nodes[n].value);
        state = {.step = n, .time = nodes[n].time, .depth = shown_depth, .force = force, .load = base,
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

}  // namespace mdr::drivers
