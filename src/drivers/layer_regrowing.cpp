#include "layer_regrowing.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>

#include "cycle_measure.hpp"
#include "layer_cells.hpp"
#include "layer_loading.hpp"
#include "layer_snapshot.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/error.hpp"
#include "observer_list.hpp"
#include "paused_base.hpp"
#include "recorders.hpp"

namespace mdr::drivers {

IndentationResult run_layer_regrowing(const ContactCase& contact_case, double largest_radius,
                                      const ProgressObserver& progress, const StepObservers& observers) {
    const auto& material = contact_case.material;
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const std::size_t cells = contact_case.numerics.elements.value_or(default_layer_cells);
    result.numerics.elements = cells;
    result.numerics.half_width = largest_radius;  // reported: the cells' range
    LayerCells layer(material, *contact_case.layer, layer_poisson_ratio(contact_case), *contact_case.indenter,
                     largest_radius, cells);
    std::optional<CycleMeasure> cycle;
    if (const auto& harmonic = contact_case.load.harmonic) cycle.emplace(*harmonic, contact_case.end_time);
    const auto grid = indentation_grid(contact_case, result.numerics);
    const LayerLoading loading = layer_loading(contact_case);
    const bool displacement = loading.driven == LayerDriven::depth;
    const bool spring = loading.driven == LayerDriven::spring_base;
    const double spring_constant = loading.spring_constant;
    // A force pause holds the force reached at its start (k = 0, as under force control; eq. L22), and the base
    // history resumes shifted from the z reached (PausedBase, as on the half-space).
    std::optional<PausedBase> paused;
    if (loading.paused()) paused.emplace(*loading.force_pauses, spring_constant);
    CellRunObservers run_observers(contact_case, layer, result, observers);
    ObserverList& observed = run_observers.list();
    const std::size_t last_node = grid.size() - 1;
    const bool sine_rate = displacement && contact_case.load.harmonic && material.viscosity() > 0.0;
    std::size_t reported = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
        const double time_step = i == 0 ? 0.0 : grid[i].time - grid[i - 1].time;
        const bool holding = paused && i > 0 && paused->holding(grid[i - 1].time, grid[i].time);
        const double value = paused ? paused->base(grid[i].value) : grid[i].value;
        // A prescribed depth under a harmonic with a dashpot is not linear inside a step: the dashpot takes the
        // trapezoidal rate from the prescribed rate at the step's start, the history's slope plus the sine's rate
        // (second order, as on the half-space, history_stepping.hpp).
        std::optional<double> start_rate;
        if (sine_rate && time_step > 0.0) {
            start_rate = contact_case.load.start_rate(grid[i - 1].time, grid[i - 1].value, grid[i].time, value);
        }
        // A force's round-off below zero is no pull; a spring's right side is k z.
        const LayerCellState state =
            displacement ? layer.step(time_step, value, start_rate)
            : holding    ? layer.step_loaded(time_step, paused->held_force(), 0.0, value)
                         : layer.step_loaded(time_step, spring ? spring_constant * value : std::max(value, 0.0),
                                             spring_constant, value);
        if (i > 0) ++result.steps;
        const bool settled = i == last_node || grid[i + 1].time != grid[i].time;
        const double shown_base = holding ? paused->base_in_pause(state.depth) : value;
        StepState observed_state{
            .step = i,
            .time = grid[i].time,
            .depth = state.depth,
            .force = state.force,
            .load = spring ? shown_base : value,
            .fraction = static_cast<double>(i) / static_cast<double>(std::max<std::size_t>(last_node, 1)),
            .settled = settled,
            .last = i == last_node,
            .layer_contact_radius = state.contact_radius};
        const bool ends = observed.notify(observed_state);
        if (paused && settled) paused->passed(grid[i].time, state.force, state.depth, grid[i].value);
        if (cycle) cycle->record(grid[i].time, state.depth, state.force, state.touching, state.touching_part);
        const auto percent = static_cast<std::size_t>(100.0 * static_cast<double>(i + 1) /
                                                      static_cast<double>(grid.size()));
        if (progress && percent > reported) {
            reported = percent;
            progress(static_cast<double>(i + 1) / static_cast<double>(grid.size()));
        }
        if (ends) break;
    }
    result.stopped = observed.stopped();
    if (cycle && !result.stopped) result.harmonic = cycle->outcome();  // the outcome needs the whole run
    return result;
}

}  // namespace mdr::drivers
