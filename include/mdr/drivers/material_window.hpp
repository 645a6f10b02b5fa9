#pragma once
/// \file
/// The lags a problem needs of its material: what a model converted to a Prony series (power law, springpots,
/// tables) must match, from the first time step to the duration, and the frequencies of its harmonic loads.

#include <optional>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/rheology/approximation.hpp"

namespace mdr::drivers {

/// The time window of a problem with the given normal load (its history and harmonic), end time, numerics and
/// tangential load, without its material (the material's series depends on it): longest = end - start; shortest = a
/// fifth of the largest time step (`numerics.time_step`, or the duration over default_steps, at most a harmonic
/// period over default_steps_per_period), the smallest step resolve_numerics takes before snapshots (it shortens
/// the default step to a fifth of a material time at most), and a fifth of the steps of a fast load change (the
/// shortest time between fast_change_times over min_steps_per_segment); frequencies = the angular frequencies
/// 2 pi f of the harmonic loads, at which the complex modulus is certified explicitly. An impact needs `load.end` and
/// `numerics.time_step` (its time scales follow from the material). Throws mdr::InvalidInput naming the key that
/// is missing or makes the window empty.
rheology::TimeWindow material_window(const Load& load, double end_time, const NumericsOptions& numerics,
                                     const std::optional<TangentialLoad>& tangential, bool impact);

}  // namespace mdr::drivers
