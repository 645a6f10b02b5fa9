#pragma once
/// \file
/// The identified material functions with their confidence bands (internal to mdr_fit).

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// G(t), J(t), G'(omega), G''(omega) of the material at result.values on the data's own window (times from the
/// shortest sampling interval to the longest record, 121 log-spaced; omega = 1/t), with 95 % bands
/// f +- 1.96 sqrt(grad f^T Sigma grad f): Sigma_ij = s_i s_j rho_ij from the result's standard errors and
/// correlation, grad f by forward differences of the material built by problem.model (relative step 1e-6).
MaterialBands material_bands(const FitProblem& problem, const FitResult& result);

}  // namespace mdr::fit
