#pragma once
/// \file
/// The finiteness of a fit's result (internal to mdr_fit): what fit() returns, and so every file written from it.

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// Throws std::runtime_error naming the first number of `result` that is not finite among those that must be: the
/// fitted values, the statistics (RMS residual, noise, AIC, BIC), each curve's times, data, model, drive, contact
/// point, baseline, noise and RMS residual, and the material's functions (their grids and values). Standard errors,
/// intervals, correlations and the bands' limits may be NaN: that marks an undetermined parameter (docs/case-format.md).
void require_finite_result(const FitResult& result);

}  // namespace mdr::fit
