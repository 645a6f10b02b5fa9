#include "mdr/drivers/work_estimate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/control_end.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"

namespace mdr::drivers {
namespace {

// Steps of the time grid of a displacement- or force-controlled run (make_time_grid): each history segment, the
// hold up to the end, one more for each snapshot or tangential or harmonic breakpoint that may cut a step, the graded
// steps after jumps and towards a falling force's zeros where the grid has them.
double indentation_steps(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    const auto& points = contact_case.load.history->points();
    double steps = 0.0;
    double previous = points.front().time;
    for (const auto& point : points) {
        const double until = std::min(point.time, contact_case.end_time);
        if (until > previous) steps += segment_step_count(until - previous, numerics.time_step, numerics.min_segment_steps);
        steps += 1.0;  // a jump, at most
        previous = std::max(previous, until);
    }
    if (contact_case.end_time > previous) {
        steps += segment_step_count(contact_case.end_time - previous, numerics.time_step, numerics.min_segment_steps);
    }
    steps += static_cast<double>(contact_case.snapshots.size());
    if (contact_case.tangential) steps += static_cast<double>(contact_case.tangential->load.breakpoints().size());
    if (contact_case.load.harmonic) steps += static_cast<double>(contact_case.load.harmonic->breakpoints().size() + 2);
    if (numerics.grading_ratio > 0.0) {
        // grade_after_changes: at most ln(time_step / first_graded_step) / ratio more steps after the start and
        // each point.
        const double graded = std::ceil(std::log(std::max(numerics.time_step / numerics.first_graded_step, 1.0)) /
                                        std::log1p(numerics.grading_ratio));
        steps += graded * static_cast<double>(points.size() + 1);
    }
    if (numerics.zero_grading_exponent > 0.0) {
        // cuts_towards_zeros: one more step for each of its cuts, at most.
        steps += count_cuts_towards_zeros(*contact_case.load.history, contact_case.end_time, numerics.time_step,
                                          numerics.min_segment_steps, zero_graded_fraction,
                                          numerics.zero_grading_exponent);
    }
    return steps;
}

// `[numerics] max_memory` or default_max_memory [bytes].
double memory_bound(const ContactCase& contact_case) {
    return contact_case.numerics.max_memory.value_or(default_max_memory);
}

// What a run's work is counted in, for the messages: the half-space's elements (x 2 layers with tangential loading),
// or the cells of a layer's coupled time-stepping.
std::string counted_in(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    if (contact_case.layer) return fmt::format("m = {} cells of the [layer]", layer_cell_count(contact_case));
    return fmt::format("{} elements{}", numerics.elements, contact_case.tangential ? " x 2 layers" : "");
}

// The keys that set the counts of counted_in (on a [layer] with its run of Ting's class: work_counted_in).
const char* count_key(const ContactCase& contact_case) {
    return contact_case.layer ? "numerics.layer_cells or numerics.elements" : "numerics.elements";
}

// The element-steps a run counts: `per_step` each step, and `once` before its first.
struct StepWork {
    double per_step = 0.0;
    double once = 0.0;
};

// A run of Ting's class on a [layer] (LayerTingStepping, LayerImpactStepping): at most layer_solves_per_step elastic
// solves a step (LayerContact::at_radius; measured 2.4 under force control, a creep-recovery by callgrind, 1.2 to 3.6
// under displacement control, docs/performance.md "A layer of finite thickness") on n Gauss nodes, each n^3 / 3
// multiply-adds of the Cholesky factoring counted at multiply_adds_per_element_step: the time of a half-space
// element-step (10 ns, docs/performance.md "Scaling") against 0.10 to 0.17 ns a multiply-add measured at 400 to 96
// nodes (a solve's time over its n^3/3: the fill and the triangular solves included). n is the least, as capped
// within 12 thicknesses of contact (layer_nodes): a thin layer's wider contacts take 4 nodes a thickness and more,
// not counted; counted on every [layer] case, the harmonic ones too (which run on the cells alone: an upper bound).
constexpr double layer_solves_per_step = 4.0;
constexpr double multiply_adds_per_element_step = 32.0;

std::size_t tings_class_nodes(const ContactCase& contact_case) {
    return contact::layer_gauss_points(0, layer_nodes(contact_case));
}

double tings_class_step_work(const ContactCase& contact_case) {
    const double nodes = static_cast<double>(tings_class_nodes(contact_case));
    return layer_solves_per_step * nodes * nodes * nodes / 3.0 / multiply_adds_per_element_step;
}

// What a run's work is counted in (counted_in), on a [layer] with the Gauss nodes of its run of Ting's class and how
// each count enters.
std::string work_counted_in(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    if (!contact_case.layer) return counted_in(contact_case, numerics);
    return fmt::format("{} and n = {} Gauss nodes of its run of Ting's class (m^2 a step for its solve, m^3/3 for the "
                       "factoring of I - K, {:g} n^3/{:g} a step for the elastic solves)",
                       counted_in(contact_case, numerics), tings_class_nodes(contact_case),
                       layer_solves_per_step, 3.0 * multiply_adds_per_element_step);
}

// Every element a step (x 2 layers with tangential loading: its layer steps every element). On a [layer], its coupled
// time-stepping on m cells (LayerCells, eq. L16 to L19), which a harmonic load and a contact that grows again run: I
// - K factored once (Cholesky, m^3 / 3 multiply-adds), then a step's solve on its contact's cells (forward and back
// substitution, at most m^2 multiply-adds; the trial sets of a step share most of it, and a step's updates of the
// cells' branches, O(m), are smaller), each multiply-add counted as an element-step; and a history's run of Ting's
// class before it (tings_class_step_work), which finds the regrowth where the cells take over.
StepWork step_work(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    if (contact_case.layer) {
        const double cells = static_cast<double>(layer_cell_count(contact_case));
        return {cells * cells + tings_class_step_work(contact_case), cells * cells * cells / 3.0};
    }
    return {static_cast<double>(numerics.elements) * (contact_case.tangential ? 2.0 : 1.0), 0.0};
}

}  // namespace

WorkEstimate estimate_work(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    WorkEstimate estimate;
    // A run its control's stop rule ends has no grid: its steps of time_step up to the time limit, at most.
    const bool no_grid = ends_by_stop_rule(contact_case.control);
    estimate.steps = no_grid ? numerics.time_limit / numerics.time_step +
                                   static_cast<double>(contact_case.snapshots.size())
                             : indentation_steps(contact_case, numerics);
    // Per step: a grid node (t, value) and a history row of up to 8 columns every output_every steps.
    const double rows = estimate.steps / static_cast<double>(numerics.output_every);
    const double branches = static_cast<double>(contact_case.material.terms().size());
    estimate.memory = (no_grid ? 0.0 : 16.0 * estimate.steps) + 64.0 * rows;
    const StepWork work = step_work(contact_case, numerics);
    estimate.element_steps = estimate.steps * work.per_step + work.once;
    if (contact_case.layer) {
        // The layer's cells (step_work): I - K, its factor and the factor's transpose (3 m^2 doubles), the record of
        // the steps of the free cells (at most 4 m^2, LayerCells::record), the unit loads of the contact sets (at most
        // m^2 / 2), and per cell the stepping's vectors (8) and a memory value per branch.
        const double cells = static_cast<double>(layer_cell_count(contact_case));
        estimate.memory += 8.0 * (7.5 * cells * cells + cells * (8.0 + branches));
        return estimate;
    }
    // Per element and layer: displacement, stress, next displacement and stress, increment, relaxed sums, event,
    // profile, flag, and one memory value per branch.
    const double layers = contact_case.tangential ? 2.0 : 1.0;
    estimate.memory += layers * static_cast<double>(numerics.elements) * 8.0 * (9.0 + branches);
    return estimate;
}

void require_bounded_work(const ContactCase& contact_case, const ResolvedNumerics& numerics) {
    const double start = contact_case.load.history->start_time();
    const bool open_end = ends_by_stop_rule(contact_case.control);
    if (!std::isfinite(numerics.time_limit - start)) {
        throw InvalidInput(open_end ? "load.end" : "load.history", fmt::format("[{}, {}]", start, numerics.time_limit),
                           "the simulated time span is larger than a double can hold");
    }
    // A run its stop rule ends (an impact) given a late load.end usually ends long before it: its steps are counted
    // while it runs (require_steps_within_bound), not refused from the upper bound here.
    if (open_end && std::isfinite(contact_case.end_time)) return;
    const WorkEstimate estimate = estimate_work(contact_case, numerics);
    const double max_element_steps = element_step_bound(contact_case);
    if (!(estimate.element_steps <= max_element_steps)) {
        throw InvalidInput(
            "numerics.max_element_steps", fmt::format("{:.3g}", max_element_steps),
            fmt::format("exceeded: {:.3g} steps (time step {:.4g} s over [{}, {}] s) on {} = {:.3g} "
                        "element-steps; lengthen numerics.time_step, shorten the simulated time, use fewer "
                        "{}, or raise numerics.max_element_steps if that is meant",
                        estimate.steps, numerics.time_step, start, numerics.time_limit,
                        work_counted_in(contact_case, numerics), estimate.element_steps, count_key(contact_case)));
    }
    const double max_memory = memory_bound(contact_case);
    if (!(estimate.memory <= max_memory)) {
        throw InvalidInput("numerics.max_memory", fmt::format("{:.3g}", max_memory),
                           fmt::format("exceeded: the run would hold about {:.3g} bytes ({:.3g} steps, {}{}); "
                                       "write fewer rows (numerics.output_every), lengthen numerics.time_step, {}or "
                                       "raise numerics.max_memory if the machine has it",
                                       estimate.memory, estimate.steps, counted_in(contact_case, numerics),
                                       contact_case.layer ? ", its dense I - K and factor" : "",
                                       contact_case.layer ? "use fewer numerics.layer_cells, " : ""));
    }
}

void require_kept_states_within_bound(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                                      std::size_t states, std::size_t state_bytes) {
    const WorkEstimate estimate = estimate_work(contact_case, numerics);
    const double memory = estimate.memory + static_cast<double>(states) * static_cast<double>(state_bytes);
    const double max_memory = memory_bound(contact_case);
    if (memory <= max_memory) return;
    throw InvalidInput("numerics.max_memory", fmt::format("{:.3g}", max_memory),
                       fmt::format("exceeded: the run would hold about {:.3g} bytes ({:.3g} steps, {}, and "
                                   "a copy of each of its {} states, {} bytes each, kept for an observer that sees "
                                   "one run on the [layer]); lengthen numerics.time_step, or raise "
                                   "numerics.max_memory if the machine has it",
                                   memory, estimate.steps, counted_in(contact_case, numerics), states,
                                   state_bytes));
}

double element_step_bound(const ContactCase& contact_case) {
    return contact_case.numerics.max_element_steps.value_or(default_max_element_steps);
}

void require_steps_within_bound(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                                std::size_t steps, double time) {
    const double bound = element_step_bound(contact_case);
    const StepWork work = step_work(contact_case, numerics);
    if (static_cast<double>(steps) * work.per_step + work.once <= bound) return;
    throw InvalidInput("numerics.max_element_steps", fmt::format("{:.3g}", bound),
                       fmt::format("reached after {} steps on {} at t = {:.4g} s, before the run ended "
                                   "(at the latest at {:.4g} s); give an earlier load.end, a longer "
                                   "numerics.time_step, or raise numerics.max_element_steps if that is meant",
                                   steps, counted_in(contact_case, numerics), time, numerics.time_limit));
}

}  // namespace mdr::drivers
