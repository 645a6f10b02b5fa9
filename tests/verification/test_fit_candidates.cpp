// Model choice and the spectrum mode (mdr::fitcase::fit_candidates) against data made by the independent Lee-Radok
// quadrature of tests/support/reference, never by mdr itself: a second relaxation time is found warranted when
// the data have one and not when they do not, and a spectrum on a fixed grid reproduces G(t) over the window.

#include <gtest/gtest.h>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <random>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/model_choice.hpp"
#include "reference/closed_forms.hpp"
#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-3;      // sphere radius [m]
constexpr double depth = 2e-5;  // held depth [m]

// A ramp of 0.1 s to `depth` and a hold to 5 s, sampled every 10 ms; Gaussian force noise of `noise` [N].
fit::Curve ramp_hold(const reference::PronyMaterial& material, double noise, unsigned seed) {
    const reference::PiecewiseLinear history{{0.0, 0.1, 5.0}, {0.0, depth, depth}};
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    fit::Curve curve;
    curve.name = "ramp-hold";
    for (std::size_t i = 0; i <= 500; ++i) {
        const double t = 0.01 * static_cast<double>(i);
        curve.time.push_back(t);
        curve.depth.push_back(history.value(t));
        const double force = reference::lee_radok_force(reference::sphere_indenter(R), material, history, t);
        curve.force.push_back(force + noise * gaussian(random));
    }
    curve.force_noise = noise;
    return curve;
}

fitcase::FitCase candidate_case(const std::string& fit_keys) {
    const std::string text = "[material]\nmodel = \"elastic\"\nG = 3.0e5\n"
                             "[indenter]\nshape = \"sphere\"\nR = 1.0e-3\n"
                             "[fit]\ncontact_point = \"fixed\"\nbaseline = \"fixed\"\nelements = 500\n" +
                             fit_keys;
    return fitcase::parse_fit_case(text, "case", ".");
}

const fit::CandidateFit& named(const fit::ModelChoice& choice, const std::string& name) {
    for (const auto& fitted : choice.fits) {
        if (fitted.name == name) return fitted;
    }
    throw std::logic_error("no candidate " + name);
}

// Peak force of the data ~0.05 N; noise 1e-3 of it, as an indentation instrument gives.
constexpr double noise = 5e-5;

TEST(FitCandidates, SecondRelaxationTimeIsWarrantedWhenTheDataHaveOne) {
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.05}, {1e6, 1.0}}};
    const auto curve = ramp_hold(truth, noise, 11);
    const std::clock_t start = std::clock();
    const auto choice =
        fitcase::fit_candidates(candidate_case("candidates = [\"elastic\", \"standard\", \"prony2\"]\n"), {curve});
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    ASSERT_EQ(choice.fits.size(), 3u);
    EXPECT_EQ(choice.fits.front().name, "prony2");
    EXPECT_EQ(choice.fits[choice.preferred].name, "prony2");
    const auto& two = named(choice, "prony2");
    const auto& one = named(choice, "standard");
    // One time leaves residuals far above the noise; two reach it, and their BIC is lower by far more than the
    // 10 that counts as very strong evidence.
    EXPECT_NEAR(two.result.rms_residual / noise, 1.0, 0.1);
    EXPECT_GT(one.result.rms_residual / noise, 2.0);
    EXPECT_GT(one.delta_bic, 10.0);
    EXPECT_TRUE(two.result.undetermined.empty()) << two.result.undetermined.front().reason;
    // The two times are recovered within four standard errors (terms may come in either order).
    std::vector<double> times{two.result.values[2], two.result.values[4]};
    std::vector<double> errors{two.result.standard_errors[2], two.result.standard_errors[4]};
    if (times[0] > times[1]) {
        std::swap(times[0], times[1]);
        std::swap(errors[0], errors[1]);
    }
    EXPECT_NEAR(times[0], 0.05, 4.0 * errors[0]);
    EXPECT_NEAR(times[1], 1.0, 4.0 * errors[1]);
    std::printf("model choice of 3 candidates, 501 points: %.3f s of CPU\n", seconds);
    for (const auto& f : choice.fits) {
        std::printf("  %s: %.3f s, %zu iterations, %zu runs, BIC %.1f\n", f.name.c_str(), f.result.wall_seconds,
                    f.result.iterations, f.result.evaluations, f.result.bic);
    }
}

TEST(FitCandidates, OneRelaxationTimeSufficesWhenTheDataHaveOne) {
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.3}}};
    const auto choice = fitcase::fit_candidates(candidate_case("candidates = [\"standard\", \"prony2\"]\n"),
                                            {ramp_hold(truth, noise, 5)});
    EXPECT_EQ(choice.fits[choice.preferred].name, "standard");
    const auto& two = named(choice, "prony2");
    // The second term cannot improve the fit beyond the noise: either its BIC is higher or it is flagged.
    EXPECT_TRUE(choice.fits.front().name == "standard" || !two.result.undetermined.empty());
    EXPECT_NEAR(named(choice, "standard").result.values[2], 0.3, 0.01);
}

// The largest relative error of the spectrum's G(t) against the truth, log-spaced over the window from the
// ramp's end (0.1 s: before it the data average G over the ramp) to the record's end (5 s).
double relaxation_error(const fit::CandidateFit& spectrum, const reference::PronyMaterial& truth) {
    double worst = 0.0;
    for (int i = 0; i <= 40; ++i) {
        const double t = 0.1 * std::pow(50.0, i / 40.0);
        double G = spectrum.result.values[0];
        for (std::size_t j = 0; j < spectrum.relaxation_times.size(); ++j) {
            G += spectrum.result.values[1 + j] * std::exp(-t / spectrum.relaxation_times[j]);
        }
        worst = std::max(worst, std::abs(G / truth.relaxation(t) - 1.0));
    }
    return worst;
}

// Sum of squared differences of neighbouring moduli (what the smoothing penalises).
double roughness(const fit::CandidateFit& spectrum) {
    double sum = 0.0;
    for (std::size_t j = 2; j < spectrum.result.values.size(); ++j) {
        sum += std::pow(spectrum.result.values[j] - spectrum.result.values[j - 1], 2);
    }
    return sum;
}

TEST(FitCandidates, SpectrumReproducesTheRelaxationFunction) {
    // Two relaxation times off the grid; force noise 1e-4 of the peak. The error of G(t) falls as the grid
    // refines (measured: 1.6e-2 at 2 per decade, 2.5e-3 at 4, 9.7e-4 at 8).
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.05}, {1e6, 1.0}}};
    const auto curve = ramp_hold(truth, 5e-6, 1);
    std::vector<double> errors;
    for (const double per_decade : {2.0, 4.0}) {
        const std::clock_t start = std::clock();
        const auto choice = fitcase::fit_candidates(
            candidate_case(fmt::format("[fit.spectrum]\nper_decade = {}\n", per_decade)), {curve});
        const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
        ASSERT_EQ(choice.fits.size(), 1u);
        const auto& spectrum = choice.fits.front();
        ASSERT_TRUE(spectrum.result.converged) << spectrum.result.status;
        const auto& grid = spectrum.relaxation_times;
        EXPECT_NEAR(grid.back(), 5.0, 1e-12);  // from the record's length down to the sampling interval
        EXPECT_GE(grid.front(), 0.01);
        EXPECT_LT(grid.front(), 0.01 * std::pow(10.0, 1.0 / per_decade));
        // The force to 5e-3 (2 per decade) and 1e-3 (4 per decade) of its peak (~0.05 N; measured 2.8e-3, 4.4e-4).
        EXPECT_LT(spectrum.result.rms_residual, (per_decade < 3.0 ? 5e-3 : 1e-3) * 0.05);
        for (std::size_t j = 0; j < grid.size(); ++j) EXPECT_GE(spectrum.result.values[1 + j], 0.0);
        errors.push_back(relaxation_error(spectrum, truth));
        std::printf("spectrum, %g per decade (%zu times): G(t) within %.2e; %.3f s of CPU (with the elastic fit), %zu iterations, %zu runs\n",
                    per_decade, grid.size(), errors.back(), seconds, spectrum.result.iterations,
                    spectrum.result.evaluations);
    }
    EXPECT_LT(errors[0], 3e-2);
    EXPECT_LT(errors[1], 1e-2);
    EXPECT_LT(errors[1], errors[0]);
}

TEST(FitCandidates, SpectrumModuliIntervalsEndAtZero) {
    // A spectrum's moduli are fitted linearly (each may be 0): their intervals x -/+ t se reached below 0 where a
    // grid time holds little of G(t) (a modulus below 0, which no material has). The domain [0, inf) ends them at 0:
    // [max(x - t se, 0), x + t se]; the part cut holds no value of the modulus, so the coverage stays.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.05}, {1e6, 1.0}}};
    const auto choice =
        fitcase::fit_candidates(candidate_case("[fit.spectrum]\nper_decade = 4\n"), {ramp_hold(truth, 5e-5, 1)});
    const auto& spectrum = choice.fits.front().result;
    ASSERT_TRUE(spectrum.converged) << spectrum.status;
    std::size_t crossing = 0;
    for (std::size_t j = 0; j < spectrum.names.size(); ++j) {
        ASSERT_EQ(spectrum.interval_scales[j], "linear") << spectrum.names[j];
        const double value = spectrum.values[j], error = spectrum.standard_errors[j];
        if (!std::isfinite(error)) continue;  // undetermined: no interval
        EXPECT_GE(spectrum.lower_95[j], 0.0) << spectrum.names[j];
        EXPECT_GT(spectrum.upper_95[j], value + 1.96 * error) << spectrum.names[j];  // x + t se, t >= 1.96
        if (value - 1.96 * error < 0.0) {
            ++crossing;
            EXPECT_EQ(spectrum.lower_95[j], 0.0) << spectrum.names[j];
        }
    }
    std::printf("%zu of %zu moduli have x - 1.96 se < 0\n", crossing, spectrum.names.size());
    EXPECT_GT(crossing, 0u) << "some x - t se must pass 0 for this test to test anything";
}

TEST(FitCandidates, SpectrumIsNeverWorseThanTheOneTermFit) {
    // A standard solid with its time off the grid (0.37 s; 2 per decade put times at 0.316 and 1 s), force noise
    // 1e-5 of the peak: on its own grid the spectrum's residuals exceed the standard solid's (the grid cannot hold
    // exp(-t / 0.37)); its grid now holds the one-term fit's time, and its residuals are at most the standard's.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.37}}};
    const auto curve = ramp_hold(truth, 5e-7, 5);
    const auto choice = fitcase::fit_candidates(candidate_case("candidates = [\"standard\", \"spectrum\"]\n"), {curve});
    const auto& one = named(choice, "standard");
    const auto& spectrum = named(choice, "spectrum");
    ASSERT_TRUE(one.result.converged) << one.result.status;
    EXPECT_LE(spectrum.result.rms_residual, one.result.rms_residual * (1.0 + 1e-6));
    const auto& grid = spectrum.relaxation_times;
    EXPECT_NE(std::find_if(grid.begin(), grid.end(), [&](double tau) { return std::abs(tau / 0.37 - 1.0) < 1e-3; }),
              grid.end());
}

TEST(FitCandidates, EachCandidatesContactIsFlaggedAgainstTheDataNotAgainstTheElasticFit) {
    // A standard solid pressed after an approach of 0.2 s out of contact (true contact: depth 0). The elastic
    // candidate cannot follow the relaxation and moves its contact point far before the onset, and is flagged for
    // it. The other candidates start from the elastic fit's contact point; they were once also flagged against it,
    // as if it were where the data's force leaves the baseline ("estimate" = the elastic fit's contact), although
    // the standard solid's contact lies at the true one. The rule (contact_flags.hpp): the distance to the data's
    // own onset estimate.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const reference::PiecewiseLinear history{{0.0, 0.2, 0.3, 5.0}, {0.0, 0.0, depth, depth}};
    std::mt19937_64 random(7);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    std::vector<double> time, depths, forces;
    for (std::size_t i = 0; i <= 500; ++i) {
        const double t = 0.01 * static_cast<double>(i);
        time.push_back(t);
        depths.push_back(t < 0.2 ? -0.5 * depth * (1.0 - t / 0.2) : history.value(t));
        forces.push_back(reference::lee_radok_force(reference::sphere_indenter(R), truth, history, t) +
                         noise * gaussian(random));
    }
    const fit::Curve curve = fit::make_curve("approach", time, depths, forces);
    const std::string text = "[material]\nmodel = \"elastic\"\nG = 3.0e5\n"
                             "[indenter]\nshape = \"sphere\"\nR = 1.0e-3\n"
                             "[fit]\nelements = 500\ncandidates = [\"elastic\", \"standard\"]\n";
    const auto choice = fitcase::fit_candidates(fitcase::parse_fit_case(text, "case", "."), {curve});
    const auto far_from_onset = [](const fit::CandidateFit& fitted) {
        const auto& flags = fitted.result.curves.at(0).flags;
        return std::count_if(flags.begin(), flags.end(), [](const std::string& flag) {
            return flag.find("noise-equivalent depths") != std::string::npos;
        });
    };
    const auto& elastic = named(choice, "elastic");
    const auto& standard = named(choice, "standard");
    ASSERT_TRUE(standard.result.converged) << standard.result.status;
    EXPECT_EQ(far_from_onset(elastic), 1);  // the start of the standard solid's contact is far from the onset
    EXPECT_NEAR(standard.result.curves[0].contact_depth, 0.0, 0.01 * depth);
    EXPECT_EQ(far_from_onset(standard), 0) << fmt::format("{}", fmt::join(standard.result.curves[0].flags, "; "));
}

TEST(FitCandidates, SmoothingEvensTheSpectrum) {
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.05}, {1e6, 1.0}}};
    const auto curve = ramp_hold(truth, 5e-6, 1);
    const auto plain = fitcase::fit_candidates(candidate_case("[fit.spectrum]\nper_decade = 4\n"), {curve});
    const auto smooth =
        fitcase::fit_candidates(candidate_case("[fit.spectrum]\nper_decade = 4\nsmoothing = 1\n"), {curve});
    const auto& a = plain.fits.front();
    const auto& b = smooth.fits.front();
    std::printf("smoothing 1: roughness %.3g -> %.3g, residual/noise %.3f -> %.3f, G(t) within %.2e\n",
                roughness(a), roughness(b), a.result.rms_residual / 5e-6, b.result.rms_residual / 5e-6,
                relaxation_error(b, truth));
    EXPECT_LT(roughness(b), roughness(a));
    EXPECT_GE(b.result.rms_residual, a.result.rms_residual * (1.0 - 1e-9));
}

TEST(FitCandidates, EveryRegistryModelOfNumbersIsACandidate) {
    // Once refused ("one of elastic, standard, prony1 ... prony8, spectrum"): power_law, the default model of cell
    // mechanics, springpots and fractional models. Maxwell data (G(t) = G exp(-t/tau), Lee-Radok quadrature): the
    // maxwell candidate recovers G and tau within 4 standard errors and has the smallest BIC.
    EXPECT_NO_THROW(candidate_case("candidates = [\"springpot\", \"fractional_kelvin_voigt\", \"fractional_maxwell\", "
                                   "\"fractional_standard\", \"viscous\"]\n"));
    EXPECT_THROW(candidate_case("candidates = [\"prony\"]\n"), InvalidInput);  // its terms are pairs: prony1 ... prony8
    EXPECT_THROW(candidate_case("candidates = [\"table\"]\n"), InvalidInput);
    const reference::PronyMaterial truth{0.0, 0.0, {{2e6, 0.5}}};
    const auto curve = ramp_hold(truth, noise, 21);
    const fitcase::FitCase fit_case = candidate_case("candidates = [\"maxwell\", \"power_law\", \"kelvin_voigt\"]\n");
    const auto choice = fitcase::fit_candidates(fit_case, {curve});
    ASSERT_EQ(choice.fits.size(), 3u);
    EXPECT_EQ(choice.fits.front().name, "maxwell");
    const auto& maxwell = named(choice, "maxwell");
    ASSERT_TRUE(maxwell.result.converged) << maxwell.result.status;
    ASSERT_EQ(maxwell.result.names, (std::vector<std::string>{"material.G", "material.tau"}));
    EXPECT_NEAR(maxwell.result.values[0], 2e6, 4.0 * maxwell.result.standard_errors[0]);
    EXPECT_NEAR(maxwell.result.values[1], 0.5, 4.0 * maxwell.result.standard_errors[1]);
    const auto& power_law = named(choice, "power_law");
    EXPECT_EQ(power_law.result.names, (std::vector<std::string>{"material.G0", "material.beta"}));
    const std::string fitted_text = fitcase::fitted_case(fit_case, power_law).model.text();
    EXPECT_NE(fitted_text.find("model = 'power_law'"), std::string::npos) << fitted_text;
    EXPECT_NE(fitted_text.find("beta = "), std::string::npos) << fitted_text;
}

TEST(FitCandidates, BadCandidatesAreRefused) {
    EXPECT_THROW(candidate_case("candidates = [\"prony9\"]\n"), InvalidInput);
    EXPECT_THROW(candidate_case("candidates = [\"standard\", \"standard\"]\n"), InvalidInput);
    EXPECT_THROW(candidate_case("candidates = []\n"), InvalidInput);
    EXPECT_THROW(candidate_case("candidates = [\"standard\"]\nfree = [\"material.G\"]\n"), InvalidInput);
    EXPECT_THROW(candidate_case("candidates = [\"standard\"]\n[fit.spectrum]\n"), InvalidInput);
    EXPECT_THROW(candidate_case("[fit.spectrum]\nper_decade = 0\n"), InvalidInput);
    EXPECT_THROW(candidate_case("[fit.spectrum]\nsmoothing = -1\n"), InvalidInput);
    EXPECT_THROW(candidate_case("[fit.spectrum]\nterms = 3\n"), InvalidInput);
    EXPECT_NO_THROW(candidate_case("candidates = [\"elastic\", \"prony8\", \"spectrum\"]\nfree = [\"indenter.R\"]\n"));
}

}  // namespace
}  // namespace mdr
