#pragma once
/// \file
/// The result directory of a fit (docs/case-format.md, "Fitting"): fit.json, fitted.toml, curves.csv.

#include <filesystem>
#include <string>

#include "mdr/document.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/fit/repeat_spread.hpp"
#include "mdr/fitcase/fit_case.hpp"

namespace mdr::fitcase {

/// fit.json as a document: status, converged, parameters, standard_errors, intervals_95, correlation,
/// undetermined, curves (contact point, baseline, noise, RMS residual), rms_residual, noise, residual_to_noise, aic,
/// bic, points, free_count, iterations, evaluations, element_evaluations, band_evaluations, wall_seconds, and
/// `units`, the case's declared unit system in which its numbers are (for the figures). NaN (an undetermined error)
/// is null.
Document fit_document(const fit::FitResult& result, const std::string& units = "SI");

/// fit.json: fit_document as JSON text.
std::string fit_json(const fit::FitResult& result, const std::string& units = "SI");

/// each.json of `mdr fit --each` (and the dict of Python's mdr.spread_of_repeats): `spread`, per free key its
/// count, mean, standard_deviation, standard_error_of_mean, typical_error, error_to_spread and consistent_range
/// (fit::KeySpread), and `flags`. NaN is null.
Document spread_document(const fit::RepeatSpread& spread);

/// The case with the fitted values; its `[load]` is the case's own, or the first curve's driving history (the
/// contact point removed), or for rebound data alone the first impact (its speed, the data set's mass as
/// `indenter.mass`), so that it runs. Python's FitResult.fitted_tree is its tree.
io::CaseTemplate fitted_case(const FitCase& fit_case, const fit::FitResult& result);

/// fitted.toml's text: fitted_case as TOML under a comment line. Python's FitResult.fitted_case is this text.
std::string fitted_toml(const FitCase& fit_case, const fit::FitResult& result);

/// Writes fit.json, fitted.toml (the case with the fitted values; its load is the case's own, or the first
/// curve's driving history, the contact point removed) and curves.csv (curve,t,measured,model,residual,drive:
/// drive is fit::CurveFit::drive, nan for rebound data) into `directory`.
void write_fit_result(const std::filesystem::path& directory, const FitCase& fit_case, const fit::FitResult& result);

}  // namespace mdr::fitcase
