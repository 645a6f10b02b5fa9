#pragma once
/// \file
/// Model choice and the spectrum mode: the candidate materials of a fit case (`fit.candidates`,
/// `[fit.spectrum]`), each fitted to the same curves with start values from the data's own scales, and ranked by
/// the Bayesian information criterion.

#include <string>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/io/fit_case.hpp"

namespace mdr::fit {

/// One candidate's fit.
struct CandidateFit {
    std::string name;          ///< "elastic", "standard", "pronyN" or "spectrum"
    FitResult result;          ///< its fit: the indenter's free keys first, then the material's
    /// The case with the fitted material written into `[material]` and the indenter's free keys still free: what
    /// io::write_fit_result writes as fitted.toml (its parameters are the first entries of result.values).
    io::FitCase fitted_case;
    std::vector<double> relaxation_times;  ///< spectrum: the fixed grid [s], ascending (empty otherwise)
    double delta_aic = 0.0;    ///< AIC minus the smallest AIC of the candidates
    double delta_bic = 0.0;    ///< BIC minus the smallest BIC of the candidates
};

/// The candidates' fits, ranked.
struct ModelChoice {
    std::vector<CandidateFit> fits;  ///< in ascending BIC (the first has the smallest)
    /// Index into `fits` of the preferred model: the smallest BIC among the converged fits with no undetermined
    /// parameter; the smallest BIC when there is none such.
    std::size_t preferred = 0;
    double modulus_scale = 0.0;      ///< G_e [Pa]: the elastic fit's modulus, the scale of every start value
    double shortest_interval = 0.0;  ///< finest sampling interval of the curves [s] (the time window's start)
    double longest_record = 0.0;     ///< longest record of the curves [s] (the time window's end)
};

/// The spectrum's relaxation times [s]: T 10^(-j / per_decade) for j = 0, 1, ... down to the finest sampling
/// interval `shortest` (T = `longest`, the longest record), ascending. At least one time.
std::vector<double> spectrum_grid(double shortest, double longest, double per_decade);

/// Fits every candidate of `fit_case.model_choice` (a spectrum alone when only `[fit.spectrum]` is given) to
/// `curves`. The elastic model is fitted first, from the instantaneous modulus of the case's own material; its
/// modulus G_e sets the start values: N Prony terms start at G_inf = G_e / 2, G_k = G_e / N with bounds
/// [1e-6, 1e4] G_e, and times spread evenly in log between the finest sampling interval and the longest record
/// with bounds 1e-2 and 1e2 times those; a spectrum starts at G_inf = G_e / 2 and G_j = G_e / (2 M) for M times,
/// all with bounds [0, 1e3 G_e]. The indenter's free keys start from the elastic fit. Throws mdr::InvalidInput
/// as fit() does, and for a case whose `[material]` is compressible or whose indenter is viscoelastic (the
/// candidates replace the body's shear material).
ModelChoice fit_candidates(const io::FitCase& fit_case, const std::vector<Curve>& curves);

}  // namespace mdr::fit
