#pragma once
// `mdr fit` with `fit.candidates` or `[fit.spectrum]`: every candidate fitted, ranked and written.

#include <string>
#include <vector>

#include "fit_progress.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/io/result_directory.hpp"

namespace mdr::cli {

/// Prints a fit's flags and each curve's (fit::FitResult::flags, fit::CurveFit::flags), one console line each.
void print_flags(const fit::FitResult& result);

/// `  (E = 482.9 +- 1.6e+02)` for the free key `name` when the fit reports its Young's modulus
/// (fit::FitResult::young_moduli), else "": what the console prints beside a shear modulus.
std::string young_modulus_text(const fit::FitResult& result, const std::string& name);

/// The fit's residual RMS over its noise (fit::FitResult::residual_to_noise) as the console prints it, `noise-free`
/// when its curves are (no ratio).
std::string residual_to_noise_text(const fit::FitResult& result);

/// Fits the candidates of `fit_case` to `curves`, writes them into `directory` (fitcase::write_model_choice) and prints
/// the ranking. Returns true when the preferred candidate's fit converged (the others' status is in the
/// ranking: a term the data do not need often drifts to a bound without converging). `progress` is finished
/// before the ranking is printed.
bool run_model_choice(const fitcase::FitCase& fit_case, const std::vector<fit::Curve>& curves,
                      const io::ResultDirectory& directory, FitProgress& progress);

}  // namespace mdr::cli
