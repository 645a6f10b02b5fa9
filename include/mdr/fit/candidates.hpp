#pragma once
/// \file
/// Model choice and the spectrum mode: the candidate materials of a fit case (`fit.candidates`,
/// `[fit.spectrum]`), each fitted to the same curves with start values from the data's own scales, and ranked by
/// the Bayesian information criterion. A fit case reaches it through fitcase::fit_candidates.

#include <string>
#include <vector>

#include "mdr/fit/candidate_settings.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::fit {

/// One candidate's fit.
struct CandidateFit {
    std::string name;          ///< "elastic", "standard", "pronyN", "spectrum" or a registry model's name
    FitResult result;          ///< its fit: the indenter's free keys first, then the material's
    /// The fitted material as the body of a case's `[material]` table (`model = "prony"`, `G_inf`, `terms`; or the
    /// registry model's name and keys), from which fitcase::fitted_case writes the candidate's fitted.toml.
    std::string material_table;
    std::vector<double> relaxation_times;  ///< spectrum: the fixed grid [s], ascending (empty otherwise)
    double delta_aic = 0.0;    ///< AIC minus the smallest AIC of the candidates
    double delta_bic = 0.0;    ///< BIC minus the smallest BIC of the candidates
    /// Whether this fit may be preferred: converged, with no undetermined parameter.
    bool preferable() const { return result.converged && result.undetermined.empty(); }
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

/// The start modulus of the model choice: G(0+) of `material` (the case's own), or eta / T for a viscous body, T the
/// longest record of `curves` [Pa]. Throws mdr::InvalidInput (key `fit.data`) when there is no curve.
double candidate_start_modulus(const rheology::Rheology& material, const std::vector<Curve>& curves);

/// What the model choice needs of a fit case (fitcase::fit_candidates fills it from one).
struct CandidateProblem {
    /// The model for the values of `parameters`: the case with an elastic body of modulus `start_modulus`, whose
    /// material (drivers::ContactCase::material) each candidate replaces. Its load is replaced by each curve's.
    ModelBuilder model;
    std::vector<FreeParameter> parameters;  ///< the indenter's free keys (the candidates add the material's)
    FitSettings settings;                   ///< see FitSettings
    CandidateSettings choice;               ///< the candidates, or the spectrum alone
    double start_modulus = 0.0;             ///< the elastic fit's start (candidate_start_modulus) [Pa]
    PlausibilityUnits units;                ///< the case's units (add_plausibility_flags of every candidate)
};

/// Fits every candidate of `problem.choice` (a spectrum alone when only `[fit.spectrum]` is given) to `curves`.
/// The elastic model is fitted first, from `problem.start_modulus`; its modulus G_e sets the start values: N Prony
/// terms start at G_inf = G_e / 2, G_k = G_e / N with bounds [1e-6, 1e4] G_e, and times spread evenly in log
/// between the finest sampling interval and the longest record with bounds 1e-2 and 1e2 times those; a spectrum
/// starts at G_inf = G_e / 2 and G_j = G_e / (2 M) for M times, all with bounds [0, 1e3 G_e]. The indenter's free
/// keys start from the elastic fit. Throws mdr::InvalidInput as fit() does, and (key `fit.data`) when there is no
/// curve.
ModelChoice fit_candidates(const CandidateProblem& problem, const std::vector<Curve>& curves);

}  // namespace mdr::fit
