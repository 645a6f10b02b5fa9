#pragma once
/// \file
/// The force baseline determined by the rows before contact (internal to mdr_fit): `[fit] baseline = "constant"`
/// or `"line"` (docs/case-format.md, "Fitting").

#include <optional>

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// `problem` with each curve's baseline taken from its rows before contact (Curve::baseline_rows) and fixed
/// (BaselineMode::estimate): for BaselineMode::constant their mean force; for BaselineMode::line the estimate's
/// straight line in time, whose tilt slope (t - contact_time) is taken off every row's force so that the line's
/// value at the contact time is the constant baseline left. Any other mode returns nullopt: `problem` stands as it
/// is, and is not copied (its curves may hold 10^7 rows). Throws mdr::InvalidInput (key `fit.baseline`) for a curve
/// with no rows before contact (it starts in contact): its baseline cannot come from the data.
std::optional<FitProblem> with_pre_contact_baselines(const FitProblem& problem);

}  // namespace mdr::fit
