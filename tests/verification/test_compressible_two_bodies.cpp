// Compressible bodies (eq. 56) and two bodies in contact (eq. 8), against closed forms derived here.

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "reference/closed_forms.hpp"
#include "reference/prony_material.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

TEST(Compressible, ElasticHertzWithPoissonRatio) {
    const double G = 1e6, K = 2e6, R = 0.01, d = 1e-4;
    const auto result = run_toml(fmt::format(R"(
[material]
model = "elastic"
G = {}
K = {}
[indenter]
shape = "sphere"
R = {}
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {}]]
)",
                                             G, K, R, d));
    // nu from K and G; E* = 2G/(1 - nu) = 4 G_eff (eq. 56, elastic check), Hertz with G_eff.
    const double nu = (3 * K - 2 * G) / (2 * (3 * K + G));
    const double g_eff = 2 * G / (1 - nu) / 4;
    EXPECT_NEAR(1 / g_eff, 1 / G + 3 / (3 * K + G), 1e-15 / G);
    EXPECT_NEAR(result.force.back(), reference::hertz_force(R, g_eff, d), 1e-6 * result.force.back());
}

// Eq. (57)-(61): a Kelvin-Voigt body in shear (G, eta) and bulk (K, xi) under a flat punch of radius a, d = v0 t.
// Each element is a Kelvin-Voigt unit (G, eta) in series with one (K + G/3, xi + eta/3) (Fig. 5). With u the
// displacement of the first unit: (eta + eta2) u' + (G + G2) u = G2 v0 t + eta2 v0, u(0) = 0, so
// u = A t + B (1 - exp(-t/tau)), tau = (eta + eta2)/(G + G2) = (3 xi + 4 eta)/(3K + 4G) (eq. 59), and the force is
// F = 8 a (G u + eta u') (eq. 60).
double kelvin_voigt_punch_force(double G, double eta, double K, double xi, double a, double v0, double t) {
    const double G2 = K + G / 3, eta2 = xi + eta / 3;
    const double tau = (eta + eta2) / (G + G2);
    const double A = G2 * v0 / (G + G2);
    const double B = (eta2 * v0 - (eta + eta2) * A) / (G + G2);
    const double u = A * t + B * (1 - std::exp(-t / tau));
    const double rate = A + B / tau * std::exp(-t / tau);
    return 8 * a * (G * u + eta * rate);
}

class KelvinVoigtPunch : public ::testing::TestWithParam<double> {};

TEST_P(KelvinVoigtPunch, Eq57To61) {
    const double G = 1e6, eta = 1e5, K = 3e6, xi = GetParam(), a = 1e-3, v0 = 1e-4;
    const std::string bulk = xi > 0 ? fmt::format("[material.bulk]\nmodel = \"kelvin_voigt\"\nK = {}\neta = {}", K, xi)
                                    : fmt::format("K = {}", K);
    // The bulk part sits after the [material] keys in both forms: `K = ...` or a [material.bulk] table.
    const auto run = run_toml(fmt::format(R"(
[material]
model = "kelvin_voigt"
G = {}
eta = {}
{}
[indenter]
shape = "flat"
a = {}
[load]
control = "displacement"
history = [[0.0, 0.0], [2.0, {}]]
)",
                                          G, eta, bulk, a, 2 * v0));
    const double tau = (3 * xi + 4 * eta) / (3 * K + 4 * G);
    for (std::size_t i = 1; i < run.time.size(); ++i) {
        const double exact = kelvin_voigt_punch_force(G, eta, K, xi, a, v0, run.time[i]);
        // From the first step to the long-time limit (61): 1e-3 relative (displacement control is exact).
        EXPECT_NEAR(run.force[i], exact, 1e-3 * std::abs(exact)) << "t = " << run.time[i] << ", tau = " << tau;
    }
    // Long-time limit (61): F -> 8 a v0 [G c t + ...] grows linearly with slope 8 a G G2 v0 / (G + G2).
    const double G2 = K + G / 3;
    const std::size_t n = run.time.size() - 1;
    const double slope = (run.force[n] - run.force[n - 1]) / (run.time[n] - run.time[n - 1]);
    EXPECT_NEAR(slope, 8 * a * G * G2 * v0 / (G + G2), 1e-6 * slope);
}

INSTANTIATE_TEST_SUITE_P(ElasticAndViscousBulk, KelvinVoigtPunch, ::testing::Values(0.0, 2e5));

TEST(TwoBodies, SphereCreepWithSummedCreepFunctions) {
    // Standard-solid half-space and an elastic indenter (G2): J = J1 + 1/G2 (eq. 8); creep under F0 by eq. (34).
    const double G_inf = 1e6, G1 = 3e6, tau1 = 0.2, G2 = 5e6, R = 0.01, F0 = 0.5;
    const auto result = run_toml(fmt::format(R"(
[material]
model = "standard"
G_inf = {}
G1 = {}
tau1 = {}
[indenter]
shape = "sphere"
R = {}
[indenter.material]
model = "elastic"
G = {}
[load]
control = "force"
history = [[0.0, {}], [1.0, {}]]
)",
                                             G_inf, G1, tau1, R, G2, F0, F0));
    const auto depth = [&](double t) {
        const double creep = reference::standard_solid_creep(G_inf, G1, tau1, t) + 1 / G2;
        return std::pow(3 * F0 * creep / (16 * std::sqrt(R)), 2.0 / 3.0);
    };
    for (std::size_t i = 1; i < result.time.size(); ++i) {
        EXPECT_NEAR(result.depth[i], depth(result.time[i]), 1e-4 * depth(1.0)) << "t = " << result.time[i];
    }
}

TEST(TwoBodies, SphereCreepWithTwoViscoelasticBodies) {
    // A standard-solid half-space and a standard-solid indenter: J = J1 + J2 (eq. 8), both from Table 1; creep
    // under a constant force F0 by eq. (34).
    const double R = 0.01, F0 = 0.5;
    const auto result = run_toml(fmt::format(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.2
[indenter]
shape = "sphere"
R = {}
[indenter.material]
model = "standard"
G_inf = 4.0e6
G1 = 2.0e6
tau1 = 0.05
[load]
control = "force"
history = [[0.0, {}], [1.0, {}]]
)",
                                             R, F0, F0));
    const auto depth = [&](double t) {
        const double creep = reference::standard_solid_creep(1e6, 3e6, 0.2, t) +
                             reference::standard_solid_creep(4e6, 2e6, 0.05, t);
        return std::pow(3 * F0 * creep / (16 * std::sqrt(R)), 2.0 / 3.0);
    };
    for (std::size_t i = 1; i < result.time.size(); ++i) {
        // 1e-4 of the final depth at every written time.
        EXPECT_NEAR(result.depth[i], depth(result.time[i]), 1e-4 * depth(1.0)) << "t = " << result.time[i];
    }
}

}  // namespace
}  // namespace mdr
