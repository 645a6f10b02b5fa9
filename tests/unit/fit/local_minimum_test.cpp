// A candidate whose fit ends clearly above a fitted special case of its model is flagged as a local minimum and is
// not preferred (fit::special_cases, fit::flag_local_minima, fit::rank_candidates), on constructed fits: no fitting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mdr/fit/candidates.hpp"
#include "mdr/fit/special_cases.hpp"
#include "mdr/fitcase/model_choice_files.hpp"
#include "mdr/rheology/material_models.hpp"

namespace mdr::fit {
namespace {

constexpr std::size_t points = 10000;

// A fit of `free_count` parameters with the residual over the noise `ratio` on `points` residuals: chi-square
// n ratio^2, its AIC and BIC as fit() writes them (n ln(RSS / n) + 2k, + k ln n).
CandidateFit fit_of(const std::string& name, double ratio, std::size_t free_count, bool converged = true,
                    std::size_t n = points) {
    CandidateFit fitted;
    fitted.name = name;
    fitted.result.converged = converged;
    fitted.result.status = converged ? "converged" : "maximum iterations";
    fitted.result.residual_to_noise = ratio;
    fitted.result.points = n;
    fitted.result.free_count = free_count;
    const double log_mean_square = 2.0 * std::log(ratio);
    fitted.result.aic = static_cast<double>(n) * log_mean_square + 2.0 * static_cast<double>(free_count);
    fitted.result.bic =
        static_cast<double>(n) * log_mean_square + static_cast<double>(free_count) * std::log(static_cast<double>(n));
    return fitted;
}

// A fit whose chi-square is `chi_square` (on `points` residuals).
CandidateFit fit_of_chi_square(const std::string& name, double chi_square, std::size_t free_count) {
    return fit_of(name, std::sqrt(chi_square / static_cast<double>(points)), free_count);
}

const CandidateFit& named(const std::vector<CandidateFit>& fits, const std::string& name) {
    return *std::find_if(fits.begin(), fits.end(), [&](const CandidateFit& fitted) { return fitted.name == name; });
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(SpecialCases, LimitsWithinTheBoundsAndTheirClosure) {
    const auto standard_solid = special_cases("fractional_standard");
    EXPECT_TRUE(contains(standard_solid, "fractional_maxwell"));
    EXPECT_TRUE(contains(standard_solid, "elastic"));
    // reached only beyond a bound (G1 -> inf, alpha -> 1): not a special case within the bounds
    EXPECT_FALSE(contains(standard_solid, "fractional_kelvin_voigt"));
    EXPECT_FALSE(contains(standard_solid, "standard"));
    EXPECT_FALSE(contains(standard_solid, "springpot"));

    const auto prony3 = special_cases("prony3");
    for (const char* name : {"prony2", "standard", "prony1", "elastic", "maxwell"}) {
        EXPECT_TRUE(contains(prony3, name)) << name;
    }
    EXPECT_FALSE(contains(prony3, "prony3"));
    EXPECT_EQ(special_cases("prony1"), special_cases("standard"));

    const auto voigt = special_cases("fractional_kelvin_voigt");
    EXPECT_TRUE(contains(voigt, "springpot"));
    EXPECT_TRUE(contains(voigt, "elastic"));
    EXPECT_TRUE(contains(special_cases("spectrum"), "elastic"));
    EXPECT_TRUE(special_cases("springpot").empty());
    EXPECT_TRUE(special_cases("power_law").empty());
    EXPECT_TRUE(special_cases("elastic").empty());
    // an unknown name, whatever its digits (before, std::stoul threw out_of_range beyond size_t)
    EXPECT_TRUE(special_cases("prony99999999999999999999").empty());
    EXPECT_TRUE(special_cases("prony2x").empty());
}

TEST(SpecialCases, AStartFromASpecialCasePutsTheLimitsKeysOnTheirBounds) {
    using From = KeyStart::From;
    const auto maxwell = start_from_special_case("fractional_standard", "fractional_maxwell");
    ASSERT_TRUE(maxwell);
    ASSERT_EQ(maxwell->size(), 2U);
    EXPECT_EQ((*maxwell)[0].key, "G_inf");
    EXPECT_EQ((*maxwell)[0].from, From::lower_bound);
    EXPECT_EQ((*maxwell)[1].key, "G1");
    EXPECT_EQ((*maxwell)[1].value_of, "G");  // c and alpha: their own names
    const auto prony3 = start_from_special_case("prony3", "prony2");
    ASSERT_TRUE(prony3);
    ASSERT_EQ(prony3->size(), 1U);
    EXPECT_EQ(prony3->front().key, "terms[2][0]");
    EXPECT_EQ(prony3->front().from, From::lower_bound);
    EXPECT_TRUE(start_from_special_case("prony2", "prony1"));
    EXPECT_TRUE(start_from_special_case("prony1", "elastic"));
    // pronyN -> elastic is one limit (every G_k on its lower bound, G_inf from G), as docs/case-format.md lists it:
    // a prony3 above elastic is refitted from it even without prony2 or standard among the candidates
    const auto elastic3 = start_from_special_case("prony3", "elastic");
    ASSERT_TRUE(elastic3);
    ASSERT_EQ(elastic3->size(), 4U);
    EXPECT_EQ((*elastic3)[0].key, "G_inf");
    EXPECT_EQ((*elastic3)[0].from, From::value);
    EXPECT_EQ((*elastic3)[0].value_of, "G");
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ((*elastic3)[k + 1].key, "terms[" + std::to_string(k) + "][0]");
        EXPECT_EQ((*elastic3)[k + 1].from, From::lower_bound);
    }
    // an indirect or a missing special case, a spectrum's grid, maxwell in a series of two terms: no start
    EXPECT_FALSE(start_from_special_case("prony3", "standard"));
    EXPECT_FALSE(start_from_special_case("fractional_standard", "fractional_kelvin_voigt"));
    EXPECT_FALSE(start_from_special_case("spectrum", "elastic"));
    EXPECT_FALSE(start_from_special_case("prony2", "maxwell"));
    // every special case of a registry candidate is direct and has a start, whose keys are the registry's keys of
    // the model, and whose values come from the special case's keys (a misspelt key would leave its start unchanged)
    const auto has_key = [](const std::string& model, const std::string& key) {
        const auto& parameters = rheology::material_model(model).parameters;
        return std::any_of(parameters.begin(), parameters.end(),
                           [&](const rheology::ModelParameter& parameter) { return parameter.key == key; });
    };
    for (const char* model : {"kelvin_voigt", "fractional_kelvin_voigt", "fractional_maxwell", "fractional_standard"}) {
        for (const auto& special : special_cases(model)) {
            const auto start = start_from_special_case(model, special);
            ASSERT_TRUE(start) << model << " from " << special;
            for (const auto& key : *start) {
                EXPECT_TRUE(has_key(model, key.key)) << model << " from " << special << ": " << key.key;
                if (key.from == From::value) {
                    EXPECT_TRUE(has_key(special, key.value_of)) << model << " from " << special << ": " << key.value_of;
                }
            }
        }
    }
}

// The JPK power-law-probe candidates (docs/performance.md, "A shared parameter on its bound"): fractional_standard
// ended at r/noise 770.48, above its special cases fractional_maxwell (101.76) and elastic (766.96).
TEST(LocalMinimum, FlaggedWhenClearlyAboveAFittedSpecialCaseNamingTheBestOne) {
    std::vector<CandidateFit> fits{fit_of("elastic", 766.96, 2),
                                   fit_of("standard", 95.43, 4),
                                   fit_of("springpot", 130.3080215314, 3),
                                   fit_of("fractional_kelvin_voigt", 130.308021532, 4),
                                   fit_of("fractional_maxwell", 101.76, 4),
                                   fit_of("fractional_standard", 770.48, 5)};
    flag_local_minima(fits);
    const CandidateFit& flagged = named(fits, "fractional_standard");
    EXPECT_EQ(flagged.better_special_case, "fractional_maxwell");
    ASSERT_EQ(flagged.result.flags.size(), 1U);
    EXPECT_EQ(flagged.result.flags.front(),
              "a local minimum: its special case `fractional_maxwell` fits better (r/noise 101.76 < 770.48)");
    EXPECT_FALSE(flagged.preferable());
    // fractional_kelvin_voigt 6e-12 of its r/noise above its special case springpot: the same minimum
    for (const char* name : {"elastic", "standard", "springpot", "fractional_kelvin_voigt", "fractional_maxwell"}) {
        EXPECT_TRUE(named(fits, name).better_special_case.empty()) << name;
        EXPECT_TRUE(named(fits, name).result.flags.empty()) << name;
    }
}

// A special case whose chi-square is not finite (an AIC that is not) is no evidence: it neither flags the fit nor
// masks a finite special case that fits better.
TEST(LocalMinimum, ASpecialCaseWithoutAFiniteChiSquareIsPassedOver) {
    CandidateFit broken = fit_of("fractional_maxwell", 101.76, 4);
    broken.result.aic = std::nan("");
    std::vector<CandidateFit> fits{broken, fit_of("elastic", 766.96, 2), fit_of("fractional_standard", 770.48, 5)};
    flag_local_minima(fits);
    EXPECT_EQ(named(fits, "fractional_standard").better_special_case, "elastic");
    std::vector<CandidateFit> alone{broken, fit_of("fractional_standard", 770.48, 5)};
    flag_local_minima(alone);
    EXPECT_TRUE(named(alone, "fractional_standard").better_special_case.empty());
}

// The flag's r/noise (the RMS residual over the RMS noise of all curves) need not order two fits as chi-square does
// where the curves' noises differ: chi-square 100 n against 400 n, r/noise 5.2 against 5.1 (say a curve of small
// noise fitted better, one of large noise worse). The flag then shows chi-square, never "r/noise 5.2 < 5.1".
TEST(LocalMinimum, TheFlagNeverShowsAnRNoiseThatContradictsIt) {
    std::vector<CandidateFit> fits{fit_of_chi_square("elastic", 100.0 * points, 2),
                                   fit_of_chi_square("standard", 400.0 * points, 4)};
    fits[0].result.residual_to_noise = 5.2;
    fits[1].result.residual_to_noise = 5.1;
    flag_local_minima(fits);
    ASSERT_EQ(named(fits, "standard").result.flags.size(), 1U);
    EXPECT_EQ(named(fits, "standard").result.flags.front(),
              "a local minimum: its special case `elastic` fits better (chi-square 1e+06 < 4e+06)");
}

// Clearly above: chi-square larger by more than 1 + local_minimum_relative_margin of the special case's.
TEST(LocalMinimum, NotFlaggedWithinTheMargin) {
    const double margin = local_minimum_relative_margin;
    const double large = 1e6;  // the relative margin dominates
    std::vector<CandidateFit> within{fit_of_chi_square("elastic", large, 2),
                                     fit_of_chi_square("standard", large * (1.0 + 0.9 * margin), 4)};
    flag_local_minima(within);
    EXPECT_TRUE(named(within, "standard").better_special_case.empty());
    std::vector<CandidateFit> beyond{fit_of_chi_square("elastic", large, 2),
                                     fit_of_chi_square("standard", large * (1.0 + 1.1 * margin), 4)};
    flag_local_minima(beyond);
    EXPECT_EQ(named(beyond, "standard").better_special_case, "elastic");

    const double small = 100.0;  // the unit of chi-square dominates: 1 + 0.1
    std::vector<CandidateFit> near{fit_of_chi_square("elastic", small, 2), fit_of_chi_square("standard", 101.0, 4)};
    flag_local_minima(near);
    EXPECT_TRUE(named(near, "standard").better_special_case.empty());
    std::vector<CandidateFit> far{fit_of_chi_square("elastic", small, 2), fit_of_chi_square("standard", 101.2, 4)};
    flag_local_minima(far);
    EXPECT_EQ(named(far, "standard").better_special_case, "elastic");
}

TEST(LocalMinimum, NotFlaggedAboveAModelThatIsNotItsSpecialCase) {
    std::vector<CandidateFit> fits{fit_of("elastic", 10.0, 2),
                                   fit_of("springpot", 50.0, 3),    // no special case among the candidates
                                   fit_of("power_law", 60.0, 3),
                                   fit_of("fractional_maxwell", 9.0, 4),
                                   fit_of("fractional_kelvin_voigt", 40.0, 4),  // above fractional_maxwell: not its
                                   fit_of("standard", 30.0, 4, true, points + 1)};  // other residuals: not compared
    flag_local_minima(fits);
    EXPECT_TRUE(named(fits, "springpot").better_special_case.empty());
    EXPECT_TRUE(named(fits, "power_law").better_special_case.empty());
    EXPECT_TRUE(named(fits, "standard").better_special_case.empty());
    // above elastic, its special case
    EXPECT_EQ(named(fits, "fractional_kelvin_voigt").better_special_case, "elastic");
}

// fit_candidates refits a fit from a direct special case with a start that fits clearly better, even where a special
// case without one (indirect, or maxwell for a series) fits better still: prony3 ends above prony2 (itself a local
// minimum above standard) and above standard, which is not direct for it; it is refitted from prony2 (before, from
// none: only the best special case, standard, was tried) and flagged above standard.
TEST(LocalMinimum, RefittedFromTheBestDirectSpecialCaseThatHasAStart) {
    std::vector<CandidateFit> fits{fit_of_chi_square("elastic", 1e3 * points, 2),
                                   fit_of_chi_square("standard", 1e2 * points, 4),
                                   fit_of_chi_square("prony2", 5e2 * points, 6),
                                   fit_of_chi_square("prony3", 8e2 * points, 8)};
    const CandidateFit* from = special_case_to_refit_from(fits, named(fits, "prony3"));
    ASSERT_NE(from, nullptr);
    EXPECT_EQ(from->name, "prony2");
    flag_local_minima(fits);
    EXPECT_EQ(named(fits, "prony3").better_special_case, "standard");
    // elastic, its only direct special case with a start besides prony2, is not clearly better: none
    std::vector<CandidateFit> above_standard{fit_of_chi_square("elastic", 1e3 * points, 2),
                                             fit_of_chi_square("standard", 1e2 * points, 4),
                                             fit_of_chi_square("prony3", 9.995e2 * points, 8)};
    EXPECT_EQ(special_case_to_refit_from(above_standard, named(above_standard, "prony3")), nullptr);
    // maxwell has no start for prony2 (which of its terms it is is not determined)
    std::vector<CandidateFit> above_maxwell{fit_of_chi_square("maxwell", 1e2 * points, 3),
                                            fit_of_chi_square("prony2", 5e2 * points, 6)};
    EXPECT_EQ(special_case_to_refit_from(above_maxwell, named(above_maxwell, "prony2")), nullptr);
}

// A flagged fit is not preferred even where its better special case may not be: fractional_maxwell has the smallest
// BIC but did not converge; fractional_standard, next, ended above it; the preferred model is the next one.
TEST(LocalMinimum, AFlaggedFitIsNotPreferred) {
    ModelChoice choice;
    choice.fits = {fit_of("elastic", 766.96, 2), fit_of("fractional_maxwell", 101.76, 4, false),
                   fit_of("fractional_standard", 150.0, 5)};
    rank_candidates(choice);
    ASSERT_EQ(choice.fits.size(), 3U);
    EXPECT_EQ(choice.fits[0].name, "fractional_maxwell");
    EXPECT_EQ(choice.fits[1].name, "fractional_standard");
    EXPECT_EQ(choice.fits[1].better_special_case, "fractional_maxwell");
    EXPECT_EQ(choice.fits[choice.preferred].name, "elastic");
    EXPECT_DOUBLE_EQ(choice.fits[0].delta_bic, 0.0);
}

TEST(LocalMinimum, RankingJsonNamesTheBetterSpecialCaseAndTheRefit) {
    ModelChoice choice;
    choice.fits = {fit_of("elastic", 766.96, 2), fit_of("fractional_standard", 770.48, 5),
                   fit_of("fractional_maxwell", 101.76, 4)};
    choice.fits[2].refitted_from = "elastic";
    rank_candidates(choice);
    const std::string json = fitcase::ranking_json(choice);
    EXPECT_NE(json.find("\"better_special_case\": \"fractional_maxwell\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"refitted_from\": \"elastic\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"better_special_case\": null"), std::string::npos) << json;
}

}  // namespace
}  // namespace mdr::fit
