#pragma once
/// \file
/// The model choice of a fit case (`fit.candidates`, `[fit.spectrum]`): the case translated into a
/// fit::CandidateProblem, and each candidate's fitted case.

#include <vector>

#include "mdr/fit/candidates.hpp"
#include "mdr/fitcase/fit_case.hpp"

namespace mdr::fitcase {

/// fit::fit_candidates of the candidates of `fit_case.model_choice` on `curves`: the model is the case with an
/// elastic body (its start modulus fit::candidate_start_modulus of the case's own material), the indenter's free keys
/// free. Throws mdr::InvalidInput as fit::fit_candidates does, and (key `fit.candidates`) for a case whose
/// `[material]` is compressible or whose indenter is viscoelastic (the candidates replace the body's shear material).
fit::ModelChoice fit_candidates(const FitCase& fit_case, const std::vector<fit::Curve>& curves);

/// The case with the candidate's fitted material in `[material]` (fit::CandidateFit::material_table) and the
/// indenter's free keys still free: what write_model_choice writes as the candidate's fitted.toml (its free values
/// are the first entries of `candidate.result.values`).
FitCase fitted_case(const FitCase& fit_case, const fit::CandidateFit& candidate);

}  // namespace mdr::fitcase
