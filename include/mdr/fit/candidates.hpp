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
    /// The fitted special case of this model (special_cases) that fits clearly better than this fit
    /// (flag_local_minima): this fit ended in a local minimum, not at its model's best. Empty when there is none.
    std::string better_special_case;
    /// The special case from whose fitted values this model was fitted again, once, after its first fit ended clearly
    /// above that special case (fit_candidates); the result is the lower of the two fits, and a flag says which.
    /// Empty when it was not.
    std::string refitted_from;
    /// Whether this fit may be preferred: converged, with no undetermined parameter, and not a local minimum above a
    /// special case of its model (better_special_case).
    bool preferable() const {
        return result.converged && result.undetermined.empty() && better_special_case.empty();
    }
};

/// The candidates' fits, ranked.
struct ModelChoice {
    std::vector<CandidateFit> fits;  ///< in ascending BIC (the first has the smallest)
    /// Index into `fits` of the preferred model: the smallest BIC among the fits that may be preferred
    /// (CandidateFit::preferable: converged, no undetermined parameter, not a local minimum); the smallest BIC when
    /// there is none such.
    std::size_t preferred = 0;
    double modulus_scale = 0.0;      ///< G_e [Pa]: the elastic fit's modulus, the scale of every start value
    double shortest_interval = 0.0;  ///< finest sampling interval of the curves [s] (the time window's start)
    double longest_record = 0.0;     ///< longest record of the curves [s] (the time window's end)
};

/// The margin of flag_local_minima in chi-square (the noise-weighted residual sum of squares): a fit is clearly
/// above its special case's when its chi-square exceeds it by more than 1 (the special case's own statistical
/// reach: a change of 1 in chi-square is one standard error of one parameter) plus this fraction of it (the
/// solver's stopping, ~1e-8 of the residual in fits of one minimum, and a special case reached only at the edge
/// of a bound, where G(t) is off by ~1e-6 of G_e: special_cases).
inline constexpr double local_minimum_relative_margin = 1e-3;

/// Marks every fit of `fits` whose chi-square exceeds that of a fitted special case of its model (special_cases,
/// by name) by more than 1 + local_minimum_relative_margin times that one's: sets CandidateFit::better_special_case
/// to the special case with the smallest chi-square, and adds a flag to its result, "a local minimum: its special
/// case `X` fits better (r/noise A < B)". Fits of different residual counts, and special cases whose chi-square is
/// not finite, are not compared. Once per set of fits: each call adds the flag again.
void flag_local_minima(std::vector<CandidateFit>& fits);

/// The fitted special case from whose solution fit_candidates fits `fitted` once more: of the direct special cases
/// of its model among `fits` from which its fit can start (start_from_special_case), the one of the smallest
/// chi-square, when that is below `fitted`'s by flag_local_minima's margin; null when there is none. A special case
/// that fits better still but has no such start (an indirect one, maxwell for a prony series) does not hide it.
const CandidateFit* special_case_to_refit_from(const std::vector<CandidateFit>& fits, const CandidateFit& fitted);

/// The flag of flag_local_minima for `fitted`, whose special case `better` fits better: "a local minimum: its
/// special case `X` fits better (r/noise A < B)", with their chi-square in place of r/noise where that does not
/// order them as chi-square does (no noise to measure against: FitResult::residual_to_noise NaN; curves of
/// different noise, over which the RMS ratio and chi-square may disagree).
std::string local_minimum_flag(const CandidateFit& fitted, const CandidateFit& better);

/// Ranks the fitted candidates `choice.fits`: flags the local minima (flag_local_minima), sorts the fits by
/// ascending BIC, sets their delta_aic and delta_bic, and `choice.preferred` (ModelChoice::preferred). At least one
/// fit; once per choice (flag_local_minima).
void rank_candidates(ModelChoice& choice);

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
/// keys start from the elastic fit. A fit that ends clearly above a direct special case of its model
/// (flag_local_minima's rule) is fitted once more from that special case's solution (special_case_to_refit_from,
/// start_from_special_case) and the lower of the two is kept (CandidateFit::refitted_from); then rank_candidates.
/// Throws mdr::InvalidInput as fit() does, and (key `fit.data`) when there is no curve.
ModelChoice fit_candidates(const CandidateProblem& problem, const std::vector<Curve>& curves);

}  // namespace mdr::fit
