#pragma once
/// \file
/// The result directory of a model choice or a spectrum (docs/case-format.md, "Fitting"): one fit per candidate,
/// the ranking (models.csv, ranking.json) and the spectrum's moduli (spectrum.csv).

#include <filesystem>
#include <string>

#include "mdr/fit/candidates.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/document.hpp"

namespace mdr::fitcase {

/// ranking.json as a document: `criterion` ("bic"), `preferred`, `modulus_scale`, `time_window` [s, s], and
/// `candidates` in ascending BIC, each with `name`, `status`, `converged`, `free_count`, `rms_residual`, `noise`,
/// `residual_to_noise`, `aic`, `bic`, `delta_aic`, `delta_bic`, `undetermined` (names), `better_special_case` (the
/// special case that fits clearly better: fit::CandidateFit::better_special_case, or null), `refitted_from` (the
/// special case from whose solution it was fitted again: fit::CandidateFit::refitted_from, or null), `evaluations`,
/// `wall_seconds`.
Document ranking_document(const fit::ModelChoice& choice);

/// ranking.json: ranking_document as JSON text.
std::string ranking_json(const fit::ModelChoice& choice);

/// Writes the model choice into `directory`: per candidate a folder NAME/ with fit.json, fitted.toml, curves.csv
/// (and spectrum.csv for a spectrum), models.csv (rank,candidate,free_count,rms_residual,residual_to_noise,aic,
/// bic,delta_aic,delta_bic,converged,undetermined,wall_seconds,better_special_case,refitted_from: empty when none)
/// and ranking.json. A spectrum alone (no candidates) is written as one fit: fit.json, fitted.toml, curves.csv,
/// spectrum.csv in `directory` itself.
void write_model_choice(const std::filesystem::path& directory, const FitCase& fit_case,
                        const fit::ModelChoice& choice);

}  // namespace mdr::fitcase
