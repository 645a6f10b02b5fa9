// Cross-method verification of the impact (eq. 37-40): the library's coefficient of restitution, computed on the
// MDR foundation with its default numerics, against the oracle sphere_impact_ting (3D Lee–Radok loading and Ting
// unloading as an integro-differential equation, tests/support/reference/impact_ode.hpp, accurate to ~1e-9 in e),
// over the restitution map of the standard solid (eq. 40) and for Kelvin–Voigt bodies.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "reference/impact_ode.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

constexpr double mass = 0.01;    // sphere mass m [kg]
constexpr double radius = 0.01;  // sphere radius R [m]
constexpr double speed = 0.1;    // approach speed v0 [m/s]
constexpr double modulus = 1e6;  // G∞ (standard solid), G (Kelvin–Voigt) [Pa]

std::string impact_case(const std::string& material) {
    return fmt::format(R"(
[material]
{}
[indenter]
shape = "sphere"
R = {}
mass = {}
[load]
control = "impact"
velocity = {}
)",
                       material, radius, mass, speed);
}

/// τ1 [s] of the standard solid at p1 = τ1 v0^{1/5} (G∞/ρ)^{2/5} / R, ρ = 3m/(4πR³) (eq. 40).
double relaxation_time(double p1) {
    const double density = 3.0 * mass / (4.0 * std::numbers::pi * std::pow(radius, 3));
    return p1 * radius / (std::pow(speed, 0.2) * std::pow(modulus / density, 0.4));
}

struct MapPoint {
    double p1, p2;
};

class ImpactStandardSolid : public ::testing::TestWithParam<MapPoint> {};

TEST_P(ImpactStandardSolid, MatchesTingOracle) {
    // e of the library (default numerics) and of the oracle agree to 1e-4 at every point of the map.
    const auto [p1, p2] = GetParam();
    const double tau = relaxation_time(p1);
    const auto result = run_toml(impact_case(
        fmt::format("model = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}", modulus, p2 * modulus, tau)));
    ASSERT_TRUE(result.impact);
    const reference::PronyMaterial material{modulus, 0.0, {{p2 * modulus, tau}}};
    const auto oracle = reference::sphere_impact_ting(material, mass, radius, speed);
    RecordProperty("e_oracle", fmt::format("{:.9f}", oracle.restitution));
    RecordProperty("e_mdr", fmt::format("{:.9f}", result.impact->restitution));
    EXPECT_NEAR(result.impact->restitution, oracle.restitution, 1e-4) << "p1 = " << p1 << ", p2 = " << p2;
}

// Three decades of p1 per p2, 1e-3 to 1e2 over the map, including the deepest dip (p1 = 0.1, p2 = 9: e = 0.34).
INSTANTIATE_TEST_SUITE_P(RestitutionMap, ImpactStandardSolid,
                         ::testing::Values(MapPoint{1e-3, 0.5}, MapPoint{1e-1, 0.5}, MapPoint{1e1, 0.5},
                                           MapPoint{1e-2, 1.0}, MapPoint{1.0, 1.0}, MapPoint{1e2, 1.0},
                                           MapPoint{1e-1, 3.0}, MapPoint{1.0, 3.0}, MapPoint{1e1, 3.0},
                                           MapPoint{1e-2, 9.0}, MapPoint{1e-1, 9.0}, MapPoint{1e2, 9.0}));

std::string kelvin_voigt(double eta) { return fmt::format("model = \"kelvin_voigt\"\nG = {}\neta = {}", modulus, eta); }

class ImpactKelvinVoigt : public ::testing::TestWithParam<double> {};

TEST_P(ImpactKelvinVoigt, MatchesTingOracle) {
    // e from 0.99 (η = 5 Pa·s) to 0.31 (η = 1300 Pa·s); library (default numerics) and oracle agree to 1e-4.
    const double eta = GetParam();
    const auto result = run_toml(impact_case(kelvin_voigt(eta)));
    ASSERT_TRUE(result.impact);
    const auto oracle = reference::sphere_impact_ting(reference::PronyMaterial{modulus, eta, {}}, mass, radius, speed);
    RecordProperty("e_oracle", fmt::format("{:.9f}", oracle.restitution));
    RecordProperty("e_mdr", fmt::format("{:.9f}", result.impact->restitution));
    EXPECT_NEAR(result.impact->restitution, oracle.restitution, 1e-4) << "eta = " << eta;
}

INSTANTIATE_TEST_SUITE_P(Damping, ImpactKelvinVoigt, ::testing::Values(5.0, 50.0, 200.0, 500.0, 1300.0));

TEST(ImpactKelvinVoigt, StrongDampingIsAccurateAtDefaultAndFinerSteps) {
    // The strongest damping above (eta = 1300 Pa s, e = 0.307) is where the dashpot matters most. With the
    // trapezoidal rate of the indenter the library is within 4e-6 of the oracle at its default step (~2.1 us) and
    // within 1.5e-6 at 1 us and finer, where the error no longer falls monotonically (event location and end of
    // contact, ~1e-6). With the step's secant rate it was first order: 8.5e-5 at the default step.
    const double eta = 1300.0;
    const double oracle =
        reference::sphere_impact_ting(reference::PronyMaterial{modulus, eta, {}}, mass, radius, speed).restitution;
    const auto by_default = run_toml(impact_case(kelvin_voigt(eta)));
    EXPECT_NEAR(by_default.impact->restitution, oracle, 1e-5);
    for (const double step : {1e-6, 2.5e-7}) {
        const auto result =
            run_toml(impact_case(kelvin_voigt(eta)) + fmt::format("[numerics]\ntime_step = {}\n", step));
        EXPECT_NEAR(result.impact->restitution, oracle, 2e-6) << "time_step = " << step;
    }
}

}  // namespace
}  // namespace mdr
