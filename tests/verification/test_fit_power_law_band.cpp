// A power-law material fitted to a record whose depth has measurement noise: the depth dips during the hold, so the
// history leaves Ting's class, the continuum model refuses it and every run is the band model's (its memory bound,
// src/fit/band_model.hpp: G_inf = 0). The data are never mdr's: the force is Lee-Radok's for the noise-free ramp-hold
// into G(t) = G0 (t/t0)^(-beta) (eq. 21), sphere f = r^2 / (2R), incompressible, F1 = (16/3) sqrt(R) d^(3/2):
//   F(t) = 8 sqrt(R) v^(3/2) G0 t0^beta int_0^min(t, T) (t - s)^(-beta) s^(1/2) ds,
// on the ramp (t <= T) t^(3/2 - beta) B(3/2, 1 - beta) (the closed form of test_power_law.cpp), on the hold by
// adaptive Gauss-Kronrod (tests/support/reference/quadrature.hpp) after s = T u^2, which leaves the smooth
// 2 T^(3/2) u^2 (t - T u^2)^(-beta) on [0, 1]. The depth's noise, 1e-6 of the peak depth, moves the force by about
// (T / dt)^beta 1e-6 ~ 4e-6 of it, far below the force's noise (1e-3): the fit must recover G0 and beta within 3
// standard errors and 2 %.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "reference/quadrature.hpp"
#include "power_law_ramp.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-5;          // sphere radius [m]
constexpr double peak = 2e-6;       // depth at the end of the ramp [m]
constexpr double ramp_time = 1.0;   // T [s]
constexpr double speed = peak / ramp_time;
constexpr double G0 = 5e3;          // [Pa]
constexpr double beta = 0.2;
constexpr double t0 = 1.0;          // [s]

double lee_radok_force(double t) {
    const double scale = 8.0 * std::sqrt(R) * std::pow(speed, 1.5) * G0 * std::pow(t0, beta);
    if (t <= ramp_time) {
        return testing::power_law_sphere_ramp_force(G0 * std::pow(t0, beta), beta, R, speed, t);
    }
    const double T = ramp_time;
    const auto integrand = [&](double u) { return 2.0 * std::pow(T, 1.5) * u * u * std::pow(t - T * u * u, -beta); };
    return scale * reference::integrate(integrand, 0.0, 1.0);
}

// A ramp of 1 s and a hold of 4 s sampled every 10 ms; the depth with AR(1) noise (correlation 0.7) of 1e-6 of the
// peak depth, the force with white noise of 1e-3 of the peak force.
fit::Curve noisy_ramp_hold(unsigned seed) {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    const double force_noise = 1e-3 * lee_radok_force(ramp_time);
    fit::Curve curve;
    curve.name = "ramp-hold";
    double correlated = 0.0;
    for (int i = 0; i <= 500; ++i) {
        const double t = 0.01 * i;
        correlated = 0.7 * correlated + std::sqrt(1.0 - 0.49) * 1e-6 * peak * gaussian(random);
        curve.time.push_back(t);
        curve.depth.push_back(speed * std::min(t, ramp_time) + (i == 0 ? 0.0 : correlated));
        curve.force.push_back(lee_radok_force(t) + force_noise * gaussian(random));
    }
    curve.force_noise = force_noise;
    return curve;
}

TEST(FitPowerLawBand, RecoversTheParametersOfANoisyDepthRecordWithBandRuns) {
    const fitcase::FitCase fit_case = fitcase::parse_fit_case(
        "[material]\nmodel = \"power_law\"\nG0 = 2.0e3\nbeta = 0.4\n[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n"
        "[fit]\nfree = [\"material.G0\", \"material.beta\"]\ncontact_point = \"fixed\"\nbaseline = \"fixed\"\n",
        "case", ".");
    const fit::FitResult result = fit::fit(fitcase::make_problem(fit_case, {noisy_ramp_hold(5)}, {}));
    ASSERT_TRUE(result.converged) << result.status;
    ASSERT_EQ(result.names, (std::vector<std::string>{"material.G0", "material.beta"}));
    std::printf("G0 = %.2f +/- %.2f, beta = %.5f +/- %.5f; %zu runs, %zu band runs\n", result.values[0],
                result.standard_errors[0], result.values[1], result.standard_errors[1], result.evaluations,
                result.band_evaluations);
    EXPECT_GT(result.evaluations, 0u);
    EXPECT_EQ(result.band_evaluations, result.evaluations);  // the depth's dips: no continuum run
    EXPECT_NEAR(result.values[0], G0, 3.0 * result.standard_errors[0]);
    EXPECT_NEAR(result.values[1], beta, 3.0 * result.standard_errors[1]);
    EXPECT_NEAR(result.values[0], G0, 0.02 * G0);
    EXPECT_NEAR(result.values[1], beta, 0.02 * beta);
}

}  // namespace
}  // namespace mdr
