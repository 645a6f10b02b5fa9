#pragma once
/// \file
/// What a run will cost, estimated from the resolved numerics before anything is allocated, and the bounds that
/// keep a mistyped number (a time step of 1e-15 s, a history over 1e308 s, a harmonic of 10 MHz over a second) from
/// running for hours or exhausting memory: such a case is refused in one line naming the bound and the keys to
/// change.

#include <cstddef>

#include "mdr/drivers/contact_case.hpp"

namespace mdr::drivers {

/// Default bound on steps x elements (x 2 with tangential loading): about ten minutes of one core at the
/// foundation's measured 1-2e8 element updates per second (docs/performance.md). `[numerics] max_element_steps`
/// raises or lowers it.
inline constexpr double default_max_element_steps = 1e11;
/// Default bound on the memory of a run [bytes]: the time grid, the history rows and the element state.
/// `[numerics] max_memory` raises or lowers it.
inline constexpr double default_max_memory = 8e9;

/// The estimated cost of a run.
struct WorkEstimate {
    double steps = 0.0;          ///< time steps; for an impact, up to its time limit (an upper bound)
    /// steps x elements, x 2 with tangential loading (its layer steps every element); on a `[layer]` of m cells
    /// (layer_cell_count) steps x m^2 (a step's solve on the contact's cells) + m^3 / 3 (I - K factored once), and
    /// steps x 4 n^3 / 96 for its run of Ting's class on n Gauss nodes (layer_nodes: 4 elastic solves a step, each
    /// n^3 / 3 multiply-adds at 32 to an element-step's time)
    double element_steps = 0.0;
    double memory = 0.0;  ///< bytes: time grid, history rows, element state (on a `[layer]` its cells' dense I - K)
};

/// Estimates the cost of running `contact_case` with `numerics` (as resolve_numerics gives them).
WorkEstimate estimate_work(const ContactCase& contact_case, const ResolvedNumerics& numerics);

/// Throws mdr::InvalidInput when the simulated time span is not finite (key `load.history`, or `load.end` for a run
/// its control's stop rule ends, ends_by_stop_rule), or when the estimate exceeds the bounds of
/// `contact_case.numerics` (keys `numerics.max_element_steps`, `numerics.max_memory`); the message names the
/// estimate and the keys that change it. A run its stop rule ends (an impact) with a given `load.end` is bounded while
/// it runs instead (require_steps_within_bound): the end is only the latest time allowed.
void require_bounded_work(const ContactCase& contact_case, const ResolvedNumerics& numerics);

/// Throws mdr::InvalidInput (key `numerics.max_memory`) when the run's memory (estimate_work) with a copy of each of
/// its `states` states kept besides, `state_bytes` each, exceeds the bound: a [layer]'s run of Ting's class keeps its
/// states for the observers that need one run (StateLog, src/drivers/observer_list.hpp). Called where they are kept,
/// before they are.
void require_kept_states_within_bound(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                                      std::size_t states, std::size_t state_bytes);

/// The bound on steps x elements of `contact_case`: `[numerics] max_element_steps` or default_max_element_steps.
double element_step_bound(const ContactCase& contact_case);

/// Throws mdr::InvalidInput (key `numerics.max_element_steps`) once `steps` steps at time `time` [s] exceed the
/// bound: for a driver whose step count is known only while it runs (an impact).
void require_steps_within_bound(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                                std::size_t steps, double time);

}  // namespace mdr::drivers
