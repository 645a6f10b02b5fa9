#pragma once
/// \file
/// The lags a problem needs of its material: what a model converted to a Prony series (power law, springpots,
/// tables) must match, from the first time step to the duration, and the frequencies of its harmonic loads.

#include <cstddef>
#include <optional>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/rheology/approximation.hpp"

namespace mdr::drivers {

/// The time window of a problem with the given normal load (its history and harmonic), end time, numerics and
/// tangential load, without its material (the material's series depends on it): longest = end - start; shortest = a
/// fifth of the largest time step (`numerics.time_step`, or the duration over default_steps, at most a harmonic
/// period over default_steps_per_period), the smallest step resolve_numerics takes before snapshots (it shortens
/// the default step to a fifth of a material time at most), and a fifth of the steps of a fast load change (the
/// shortest time between fast_change_times over min_steps_per_segment); frequencies = the angular frequencies
/// 2 pi f of the harmonic loads, at which the complex modulus is certified explicitly. A run that `stops_itself`
/// (ends_by_stop_rule: an impact) needs `load.end` and `numerics.time_step` (its time scales follow from the
/// material). Throws mdr::InvalidInput naming the key that is missing or makes the window empty.
rheology::TimeWindow material_window(const Load& load, double end_time, const NumericsOptions& numerics,
                                     const std::optional<TangentialLoad>& tangential, bool stops_itself);

/// material_window of a case: its load, end time, numerics, tangential load and control (ends_by_stop_rule).
rheology::TimeWindow material_window(const ContactCase& contact_case);

/// True when `origin` is a model converted to a series (its certificate's kind "model": a power law, a springpot),
/// which stands for the model only over its certificate's window.
bool converted_model(const rheology::MaterialOrigin& origin);

/// Throws mdr::InvalidInput (key `material`) when `origin` is a model converted to a series (its certificate's kind
/// "model": a power law, a springpot) whose certificate does not cover `needed` (material_window of the case): lags
/// before its window's start or past its end, or a harmonic frequency outside [1 / longest, 1 / shortest] that it
/// does not name. Outside its window the series is not the model's, and a run would not say so. A case file's reader
/// converts over the case's own window, which this always accepts; a series fitted to data (kind "fit residual")
/// keeps its data's window there as here, and an exact series has no certificate. validate(const ContactCase&) checks
/// every case with it.
void require_certified_over(const rheology::MaterialOrigin& origin, const rheology::TimeWindow& needed);

/// The rows at `time` that follow a jump of `history` (two points at one time, or a first value other than 0) by
/// less than the window's start `shortest`, the row after the jump at its time included (the first row at that time,
/// the state before the jump, is exact and not counted): the converted series is not certified
/// there (a power law's creep J(0+) = 0 where the series' is 1 / G(0) > 0; docs/case-format.md, "Models that are
/// not a finite Prony series"). 0 without a jump. `time` ascends (a result's rows); O(rows + jumps).
std::size_t rows_before_window(const LoadHistory& history, const std::vector<double>& time, double shortest);

}  // namespace mdr::drivers
