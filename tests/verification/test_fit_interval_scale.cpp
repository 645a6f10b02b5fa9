// The 95 % intervals of mdr::fit lie inside each parameter's domain (issue 24, "bounds are reported truthfully"): a
// springpot's order alpha, domain (0, 1), gets its interval on the logit scale, a positive c on the log scale. Data
// from the closed form of a springpot under a sphere driven at constant speed (never from mdr):
//   G(t) = c t^-alpha / Gamma(1 - alpha) (springpot), h(t) = v t, incompressible (Lee-Radok, F = 16 sqrt(R)/3
//   int_0^t G(t - s) d(h^3/2)/ds ds):  F(t) = 8 sqrt(R) v^3/2 c Gamma(3/2) / Gamma(5/2 - alpha) t^(3/2 - alpha).

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "power_law_ramp.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-5;      // sphere radius [m]
constexpr double speed = 1e-6;  // v [m/s]
constexpr double c = 1e3;       // springpot quasi-property [Pa s^alpha]
constexpr double alpha = 0.8;   // springpot order, near the end 1 of its domain

double springpot_ramp_force(double t) {
    return testing::power_law_sphere_ramp_force(c / std::tgamma(1.0 - alpha), alpha, R, speed, t);
}

// 31 rows of the ramp over 2 s with white force noise of `noise` [N] (the peak force is ~2.4e-8 N).
fit::Curve noisy_ramp(double noise, unsigned seed) {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gaussian(0.0, noise);
    fit::Curve curve;
    curve.name = "ramp";
    for (int i = 0; i <= 30; ++i) {
        const double t = 2.0 * i / 30.0;
        curve.time.push_back(t);
        curve.depth.push_back(speed * t);
        curve.force.push_back(springpot_ramp_force(t) + gaussian(random));
    }
    curve.force_noise = noise;
    return curve;
}

fit::FitResult fit_springpot(const fit::Curve& curve) {
    const fitcase::FitCase fit_case = fitcase::parse_fit_case(
        "[material]\nmodel = \"springpot\"\nc = 1.0e3\nalpha = 0.5\n[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n"
        "[fit]\nfree = [\"material.c\", \"material.alpha\"]\ncontact_point = \"fixed\"\nbaseline = \"fixed\"\n",
        "case", ".");
    return fit::fit(fitcase::make_problem(fit_case, {curve}, {}));
}

TEST(FitIntervalScale, AnOrderNearOneHasItsIntervalInsideZeroToOne) {
    // Noise 15 % of the peak: alpha's standard error is large enough that the linear interval alpha +/- t se (t >=
    // 1.96) and the logarithmic one alpha exp(+/- t se / alpha) (before this rule) both reach past 1. On the logit
    // scale g = ln(alpha / (1 - alpha)) the interval is g^-1(g(alpha) -/+ t se / (alpha (1 - alpha))).
    const fit::FitResult result = fit_springpot(noisy_ramp(8e-9, 7));
    ASSERT_TRUE(result.converged) << result.status;
    ASSERT_EQ(result.names, (std::vector<std::string>{"material.c", "material.alpha"}));
    EXPECT_EQ(result.interval_scales, (std::vector<std::string>{"log", "logit"}));
    const double value = result.values[1];
    const double error = result.standard_errors[1];
    std::printf("alpha = %.4f +/- %.4f, interval [%.4f, %.4f]\n", value, error, result.lower_95[1], result.upper_95[1]);
    ASSERT_GT(value + 1.96 * error, 1.0) << "the linear interval must cross 1 for this test to test anything";
    ASSERT_GT(value * std::exp(1.96 * error / value), 1.0) << "as must the logarithmic one";
    EXPECT_GT(result.lower_95[1], 0.0);
    EXPECT_LT(result.upper_95[1], 1.0);
    EXPECT_LE(result.lower_95[1], alpha);  // still covers the truth
    EXPECT_GE(result.upper_95[1], alpha);
    // Symmetric about g(alpha) on the logit scale, half width t se g'(alpha) with the same t as c's log interval.
    const auto logit = [](double x) { return std::log(x / (1.0 - x)); };
    const double half = 0.5 * (logit(result.upper_95[1]) - logit(result.lower_95[1]));
    EXPECT_NEAR(logit(value), 0.5 * (logit(result.upper_95[1]) + logit(result.lower_95[1])), 1e-9);
    const double quantile = 0.5 * std::log(result.upper_95[0] / result.lower_95[0]) * result.values[0] /
                            result.standard_errors[0];
    EXPECT_GE(quantile, 1.96);
    EXPECT_NEAR(half, quantile * error / (value * (1.0 - value)), 1e-9 * half);
}

TEST(FitIntervalScale, LogitIntervalsOfAnOrderNearOneCoverTheTruth) {
    // The same ramp and noise over 200 realisations. Measured: alpha's log interval (before) passed 1 in 178 of
    // them; the logit intervals cover alpha = 0.8 in 196 and all lie in [0, 1]. In 12 the fit puts alpha at its
    // bound 1 - 5e-5 (flagged: the data push it beyond): g'(alpha) = 2e4 there, and the interval is the whole
    // domain, [0, 1] once rounded to doubles; every other one lies strictly inside (0, 1).
    constexpr int seeds = 200;
    int covered = 0, strictly_inside = 0, at_bound = 0;
    for (int seed = 0; seed < seeds; ++seed) {
        const fit::FitResult result = fit_springpot(noisy_ramp(8e-9, 100u + static_cast<unsigned>(seed)));
        ASSERT_TRUE(result.converged) << seed << ": " << result.status;
        const double lower = result.lower_95[1], upper = result.upper_95[1];
        covered += lower <= alpha && alpha <= upper;
        EXPECT_TRUE(lower >= 0.0 && upper <= 1.0) << seed << ": [" << lower << ", " << upper << "]";
        bool flagged_at_bound = false;
        for (const auto& entry : result.undetermined) {
            flagged_at_bound |= entry.name == "material.alpha" && entry.reason.find("upper bound") != std::string::npos;
        }
        at_bound += flagged_at_bound;
        strictly_inside += lower > 0.0 && upper < 1.0;
        if (!flagged_at_bound) {
            EXPECT_TRUE(lower > 0.0 && upper < 1.0) << seed << ": [" << lower << ", " << upper << "]";
        }
    }
    std::printf("alpha covered in %d of %d; strictly inside (0, 1) %d; at its bound %d\n", covered, seeds,
                strictly_inside, at_bound);
    EXPECT_GE(covered, 180);
    EXPECT_LE(covered, 198);
}

}  // namespace
}  // namespace mdr
