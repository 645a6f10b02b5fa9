#pragma once
/// \file
/// What a fit's optimum tells (internal to mdr_fit): covariance from the Jacobian, standard errors, confidence
/// intervals, correlations, information criteria, and the parameters the data cannot determine.

#include <memory>
#include <vector>

#include "curve_cost.hpp"
#include "rebound_cost.hpp"
#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// Fills the statistics of `result` (values and names already set) at the optimum `shared`, `nuisance` (the curves'
/// rows, then the rebound data's, one entry of FitResult::curves per quantity): the
/// covariance s^2 (J^T J)^+ with s^2 = RSS / (n - k) (so that a misjudged noise level does not bias the errors),
/// inflated for curves whose residuals are autocorrelated (effective points, FitResult::error_kind), the misfit flags,
/// the 95 % intervals (Student's t quantile with the effective points less k degrees of freedom; on the scale on
/// which each parameter's domain is the whole line, interval_scale.hpp), the curves'
/// data and model, AIC and BIC, and Undetermined entries for: directions the data do not constrain (singular
/// values below 1e-8 of the largest), a value at its bound, a standard error above the value, |correlation| > 0.99, a time parameter
/// outside the measured window (above 10 times the longest record or below a tenth of the shortest sampling
/// interval), two time parameters within 25 % of each other.
void describe_uncertainty(const FitProblem& problem, const ParameterScales& scales,
                          const std::vector<std::unique_ptr<CurveCost>>& costs,
                          const std::vector<std::unique_ptr<ReboundCost>>& rebounds, const std::vector<double>& shared,
                          const std::vector<std::vector<double>>& nuisance, FitResult& result);

}  // namespace mdr::fit
