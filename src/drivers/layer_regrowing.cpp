#include "layer_regrowing.hpp"

#include <algorithm>

#include "mdr/drivers/layer_indentation.hpp"
#include "layer_snapshot.hpp"
#include "run_loop.hpp"

namespace mdr::drivers {

LayerCellsStepping::LayerCellsStepping(const ContactCase& contact_case, const LayerLoading& loading,
                                       LayerCells& cells, const ResolvedNumerics& numerics)
    : contact_case_(contact_case),
      loading_(loading),
      cells_(cells),
      grid_(indentation_grid(contact_case, numerics)),
      sine_rate_(loading.prescribes_depth && contact_case.load.harmonic &&
                 contact_case.material.viscosity() > 0.0) {
    // A force pause holds the force reached at its start (k = 0, as under force control; eq. L22), and the base
    // history resumes shifted from the z reached (PausedBase, as on the half-space).
    if (loading.paused()) paused_.emplace(*loading.force_pauses, loading.spring_constant);
}

void LayerCellsStepping::add_observers(ObserverList& observers, IndentationResult& /*result*/) {
    if (const auto& harmonic = contact_case_.load.harmonic) {
        observers.add(cycle_.emplace(*harmonic, contact_case_.end_time, last_));
    }
}

StepState LayerCellsStepping::step(std::size_t n) {
    const GridNode& node = grid_[n];
    const double time_step = n == 0 ? 0.0 : node.time - grid_[n - 1].time;
    const bool holding = paused_ && n > 0 && paused_->holding(grid_[n - 1].time, node.time);
    const double value = paused_ ? paused_->base(node.value) : node.value;
    // A prescribed depth under a harmonic with a dashpot is not linear inside a step: the dashpot takes the
    // trapezoidal rate from the prescribed rate at the step's start, the history's slope plus the sine's rate
    // (second order, as on the half-space, history_stepping.hpp).
    std::optional<double> start_rate;
    if (sine_rate_ && time_step > 0.0) {
        start_rate = contact_case_.load.start_rate(grid_[n - 1].time, grid_[n - 1].value, node.time, value);
    }
    // A force's round-off below zero is no pull; a spring's right side is k z.
    const double k = loading_.spring_constant;
    const double right_side = loading_.spring_base() ? k * value : std::max(value, 0.0);
    const LayerCellState& state = last_ =
        loading_.prescribes_depth ? cells_.step(time_step, value, start_rate)
        : holding                 ? cells_.step_loaded(time_step, paused_->held_force(), 0.0, value)
                                  : cells_.step_loaded(time_step, right_side, k, value);
    const std::size_t last_node = grid_.size() - 1;
    const bool settled = n == last_node || grid_[n + 1].time != node.time;
    const double shown_base = holding ? paused_->base_in_pause(state.depth) : value;
    if (paused_ && settled) paused_->passed(node.time, state.force, state.depth, node.value);
    return {.step = n,
            .time = node.time,
            .depth = state.depth,
            .force = state.force,
            .load = loading_.spring_base() ? shown_base : value,
            .fraction = static_cast<double>(n) / static_cast<double>(std::max<std::size_t>(last_node, 1)),
            .settled = settled,
            .last = n == last_node,
            .layer_contact_radius = state.contact_radius};
}

void LayerCellsStepping::add_outcomes(IndentationResult& result) const {
    if (cycle_) result.harmonic = cycle_->outcome();
}

IndentationResult run_layer_regrowing(const ContactCase& contact_case, const LayerLoading& loading,
                                      double largest_radius, const ProgressObserver& progress,
                                      const StepObservers& observers) {
    IndentationResult result;
    result.numerics = resolve_numerics(contact_case);
    const std::size_t cells = contact_case.numerics.elements.value_or(default_layer_cells);
    result.numerics.elements = cells;
    result.numerics.half_width = largest_radius;  // reported: the cells' range
    LayerCells layer(contact_case.material, *contact_case.layer, layer_poisson_ratio(contact_case),
                     *contact_case.indenter, largest_radius, cells);
    LayerCellsStepping stepping(contact_case, loading, layer, result.numerics);
    CellSnapshots snapshot_source(layer);
    run_stepping(stepping, contact_case, snapshot_source, progress, observers, result);
    return result;
}

}  // namespace mdr::drivers
