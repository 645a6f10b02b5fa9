// Coverage of mdr::fit's 95 % intervals when the residuals are not white noise (issue 24, "honest uncertainties"):
// data from an independent model (the Lee-Radok quadrature of tests/support/reference, never mdr) with AR(1)
// correlated noise, and with a model misfit (a two-term material fitted by one term). White noise is covered by
// Fit.NinetyFivePercentIntervalsCoverTheTruth (tests/verification/test_fit.cpp).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "mdr/fit/fit.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "reference/closed_forms.hpp"
#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/prony_material.hpp"
#include "reference/ting.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-3;      // sphere radius [m]
constexpr double depth = 2e-5;  // peak depth [m]; the peak force is ~0.1 N

// A load-hold (ramp to 1 s, hold to 3 s), `points` samples, force by Lee-Radok quadrature.
fit::Curve clean_curve(const reference::PronyMaterial& material, std::size_t points) {
    const reference::PiecewiseLinear history{{0.0, 1.0, 3.0}, {0.0, depth, depth}};
    fit::Curve curve;
    curve.name = "load-hold";
    for (std::size_t i = 0; i < points; ++i) {
        const double t = 3.0 * static_cast<double>(i) / static_cast<double>(points - 1);
        curve.time.push_back(t);
        curve.depth.push_back(history.value(t));
        curve.force.push_back(reference::lee_radok_force(reference::sphere_indenter(R), material, history, t));
    }
    return curve;
}

// The standard solid (G_inf, G1, tau1) on a sphere, contact point and baseline known.
fit::FitProblem standard_solid_problem(fit::Curve curve) {
    fit::FitProblem problem;
    problem.model = [](const std::vector<double>& values) {
        return drivers::ContactCase{.title = "fit model",
                                    .material = rheology::Rheology::standard(values[0], values[1], values[2]),
                                    .indenter = profile::make_sphere(R),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    problem.parameters = {{"material.G_inf", 1e6, 1e3, 1e9}, {"material.G1", 2e6, 1e3, 1e9},
                          {"material.tau1", 0.5, 1e-3, 1e3}};
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    return problem;
}

// AR(1) noise of standard deviation sigma and lag-1 correlation rho: x_i = rho x_(i-1) + sqrt(1 - rho^2) sigma e_i.
void add_correlated_noise(std::vector<double>& values, double sigma, double rho, std::mt19937_64& random) {
    std::normal_distribution<double> gaussian(0.0, 1.0);
    double noise = sigma * gaussian(random);
    for (double& value : values) {
        value += noise;
        noise = rho * noise + std::sqrt(1.0 - rho * rho) * sigma * gaussian(random);
    }
}

// The effective points of AR(1) errors with coefficient rho over n points: n (1 - rho) / (1 + rho).
double effective_points(double n, double rho) { return n * (1.0 - rho) / (1.0 + rho); }

TEST(FitErrorCoverage, CorrelatedNoiseIntervalsCoverTheTruth) {
    // 301 points with AR(1) noise, rho = 0.9 (n_eff = 301 x 0.1 / 1.9 = 15.8), sigma 2e-3 (2 % of the peak) stated as
    // the curve's noise. Chi-square errors alone (as before issue 24) are ~4 times too small and cover the truth in
    // about a third of the realisations (measured: 66, 66, 76 of 200); the AR(1) sandwich with Student's t covers it
    // in 90-98 % (measured: G_inf 194, G1 189, tau1 194 of 200; over 10 000 realisations 95.4, 95.1, 95.7 %). The
    // residuals' lag-1 correlation alone (0.867 on average) misses what the fit absorbs of the noise: with it
    // put back the mean n_eff is 15.5 (the closed form 15.8); without, 18.9, and coverage 93-94 %.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const std::vector<double> exact{1e6, 2e6, 0.5};
    const fit::Curve clean = clean_curve(truth, 301);
    std::vector<int> covered(3, 0), chi_square_covered(3, 0);
    double effective = 0.0;
    constexpr int seeds = 200;
    for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937_64 random(static_cast<unsigned>(seed) + 1000u);
        fit::Curve curve = clean;
        add_correlated_noise(curve.force, 2e-3, 0.9, random);
        curve.force_noise = 2e-3;
        const auto result = fit::fit(standard_solid_problem(curve));
        ASSERT_TRUE(result.converged) << result.status;
        EXPECT_FALSE(result.misfit) << seed << ": " << result.curves[0].rms_residual / 2e-3;
        EXPECT_NE(result.error_kind.find("inflated for correlated residuals"), std::string::npos) << result.error_kind;
        effective += result.curves[0].effective_points / seeds;
        // About the chi-square errors alone (the code before issue 24): n_eff / n times the variance, quantile 1.96.
        const double shrink = std::sqrt(result.curves[0].effective_points / 301.0);
        for (std::size_t j = 0; j < 3; ++j) {
            covered[j] += result.lower_95[j] <= exact[j] && exact[j] <= result.upper_95[j];
            const double half = 1.96 * shrink * result.standard_errors[j] / result.values[j];  // logarithmic scale
            chi_square_covered[j] += std::abs(std::log(exact[j] / result.values[j])) <= half;
        }
    }
    for (std::size_t j = 0; j < 3; ++j) {
        EXPECT_GE(covered[j], 180) << j;
        EXPECT_LE(covered[j], 196) << j;
        EXPECT_LT(chi_square_covered[j], 120) << j;  // measured: see the test's first comment
        std::printf("%s: covered %d of %d (chi-square errors alone: %d)\n", j == 0 ? "G_inf" : j == 1 ? "G1" : "tau1",
                    covered[j], seeds, chi_square_covered[j]);
    }
    std::printf("rho 0.9: mean n_eff %.2f (closed form %.2f)\n", effective, effective_points(301.0, 0.9));
    EXPECT_NEAR(effective, effective_points(301.0, 0.9), 0.1 * effective_points(301.0, 0.9));
}

TEST(FitErrorCoverage, StronglyCorrelatedNoiseIntervalsCoverTheTruth) {
    // 1501 points with AR(1) noise, rho = 0.99 (a decorrelation length of ~100 rows: n_eff = 1501 x 0.01 / 1.99 =
    // 7.5), sigma 2e-3 stated as the curve's noise: the noise is a slow drift, and the fit absorbs about a third of
    // its variance (tr(H P) ~ 500 of 1501). The residuals' lag-1 correlation alone, even with its Marriott-Pope
    // bias removed, gave phi ~ 0.9855 and n_eff ~ 11 on average: errors too small, G1 covered in 179 of these 200
    // (91.9 % over 10 000 realisations). With the absorbed share put back (unabsorbed_correlations): mean n_eff 7.8,
    // covered G_inf 193, G1 187, tau1 192 of 200 (95.5, 95.2, 95.8 % over 10 000).
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const std::vector<double> exact{1e6, 2e6, 0.5};
    const fit::Curve clean = clean_curve(truth, 1501);
    std::vector<int> covered(3, 0);
    double effective = 0.0;
    constexpr int seeds = 200;
    for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937_64 random(static_cast<unsigned>(seed) + 4000u);
        fit::Curve curve = clean;
        add_correlated_noise(curve.force, 2e-3, 0.99, random);
        curve.force_noise = 2e-3;
        const auto result = fit::fit(standard_solid_problem(curve));
        ASSERT_TRUE(result.converged) << result.status;
        effective += result.curves[0].effective_points / seeds;
        for (std::size_t j = 0; j < 3; ++j) {
            covered[j] += result.lower_95[j] <= exact[j] && exact[j] <= result.upper_95[j];
        }
    }
    std::printf("rho 0.99: mean n_eff %.2f (closed form %.2f)\n", effective, effective_points(1501.0, 0.99));
    EXPECT_NEAR(effective, effective_points(1501.0, 0.99), 0.15 * effective_points(1501.0, 0.99));
    for (std::size_t j = 0; j < 3; ++j) {
        std::printf("rho 0.99: %s covered %d of %d\n", j == 0 ? "G_inf" : j == 1 ? "G1" : "tau1", covered[j], seeds);
        EXPECT_GE(covered[j], 180) << j;
        EXPECT_LE(covered[j], 196) << j;
    }
}

TEST(FitErrorCoverage, OneTermFitOfATwoTermMaterialIsAFlaggedMisfit) {
    // A standard solid cannot follow a material with two relaxation times a decade apart: with white noise 2e-4
    // (0.2 % of the peak) its residual RMS is several times the noise, in every realisation. The fit converges (the
    // best one-term fit), says "converged, misfit", flags the curve, and its errors are those of correlated residuals.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.1}, {2e6, 1.5}}};
    const fit::Curve clean = clean_curve(truth, 151);
    constexpr int seeds = 50;
    for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937_64 random(static_cast<unsigned>(seed) + 2000u);
        std::normal_distribution<double> gaussian(0.0, 2e-4);
        fit::Curve curve = clean;
        for (double& f : curve.force) f += gaussian(random);
        curve.force_noise = 2e-4;
        const auto result = fit::fit(standard_solid_problem(curve));
        ASSERT_TRUE(result.converged) << result.status;
        ASSERT_TRUE(result.misfit) << seed << ": ratio " << result.curves[0].rms_residual / 2e-4;
        EXPECT_EQ(result.status, "converged, misfit");
        ASSERT_EQ(result.curves[0].flags.size(), 1u);
        EXPECT_EQ(result.curves[0].flags[0].rfind("misfit: residual RMS", 0), 0u) << result.curves[0].flags[0];
        EXPECT_NE(result.error_kind.find("inflated for correlated residuals"), std::string::npos) << result.error_kind;
    }
}

TEST(FitErrorCoverage, WhiteNoiseKeepsChiSquareErrorsAndNoMisfit) {
    // White noise: the residuals' lag-1 correlation stays within chance (2 / sqrt(n)) in most realisations, the
    // errors are the chi-square ones and no curve is a misfit.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const fit::Curve clean = clean_curve(truth, 151);
    int white = 0;
    constexpr int seeds = 40;
    for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937_64 random(static_cast<unsigned>(seed) + 3000u);
        std::normal_distribution<double> gaussian(0.0, 2e-3);
        fit::Curve curve = clean;
        for (double& f : curve.force) f += gaussian(random);
        curve.force_noise = 2e-3;
        const auto result = fit::fit(standard_solid_problem(curve));
        ASSERT_TRUE(result.converged) << result.status;
        EXPECT_EQ(result.status, "converged");
        EXPECT_FALSE(result.misfit);
        white += result.error_kind == "white noise (chi-square)";
        // Young's moduli of the two shear moduli, E = 2 (1 + 0.5) G for the incompressible body.
        ASSERT_EQ(result.young_moduli.size(), 2u);
        for (std::size_t j = 0; j < 2; ++j) {
            EXPECT_EQ(result.young_moduli[j].name, result.names[j]);
            EXPECT_DOUBLE_EQ(result.young_moduli[j].value, 3.0 * result.values[j]);
            EXPECT_DOUBLE_EQ(result.young_moduli[j].standard_error, 3.0 * result.standard_errors[j]);
        }
    }
    EXPECT_GE(white, 36);  // the one-sided 2 / sqrt(n) test rejects white residuals in ~2.5 % of the realisations
}

}  // namespace
}  // namespace mdr
