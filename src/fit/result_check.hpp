#pragma once
/// \file
/// The finiteness of a fit's result (internal to mdr_fit): what fit() returns, and so every file written from it.

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// Throws std::runtime_error naming the first number of `result` that is not finite among those that must be: the
/// fitted values, the RMS residual and noise, each curve's times, data, model, drive, contact point, baseline, noise
/// and RMS residual, and the material's functions (their grids and values). Standard errors, intervals, correlations
/// and the bands' limits may be NaN: that marks an undetermined parameter (docs/case-format.md); AIC and BIC are -inf
/// for an exact fit (RSS = 0).
void require_finite_result(const FitResult& result);

}  // namespace mdr::fit
