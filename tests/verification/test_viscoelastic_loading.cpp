// Viscoelastic loading with a growing contact: the handbook's examples (eq. 28, eq. 33) and the general creep law
// (eq. 34), against closed forms and against Lee-Radok quadrature. Default numerics unless a test says otherwise.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "mdr/rheology/rheology.hpp"
#include "reference/closed_forms.hpp"
#include "reference/piecewise_linear.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

TEST(ViscoelasticLoading, ConeOnStandardSolidEq28) {
    const double G_inf = 1e6, G1 = 3e6, tau1 = 0.2, v0 = 1e-4;
    const double theta = 10.0 * std::numbers::pi / 180.0;
    const auto result = run_toml(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.2
[indenter]
shape = "cone"
slope_deg = 10.0
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4]]
)");
    const double peak = reference::cone_ramp_force_standard_solid(theta, v0, G_inf, G1, tau1, 1.0);
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        const double exact = reference::cone_ramp_force_standard_solid(theta, v0, G_inf, G1, tau1, result.time[i]);
        // Eq. (28): 1e-5 of the peak force at every written time (the contact spans few elements only early on).
        EXPECT_NEAR(result.force[i], exact, 1e-5 * peak) << "t = " << result.time[i];
    }
    // Eq. (26): a = 2 v0 t / (pi tan(theta)) to one element.
    EXPECT_NEAR(result.radius.back(), 2 * v0 / (std::numbers::pi * std::tan(theta)), result.numerics.half_width / 2000.0);
}

TEST(ViscoelasticLoading, KelvinVoigtSphereCreepEq33) {
    const double G = 1e6, eta = 2e5, R = 0.01, F0 = 0.5, tau = eta / G;
    const auto result = run_toml(R"(
[material]
model = "kelvin_voigt"
G = 1.0e6
eta = 2.0e5
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "force"
history = [[0.0, 0.5], [1.0, 0.5]]
)");
    const double final_radius = std::cbrt(3 * F0 * R / (16 * G));
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        const double t = result.time[i];
        if (t < 0.05 * tau) continue;
        // Eq. (33) with a^2 = R d (eq. 31): the contact radius from the depth, to 1e-3 of its final value.
        const double a = std::sqrt(R * result.depth[i]);
        EXPECT_NEAR(a, reference::kelvin_voigt_sphere_creep_radius(R, G, eta, F0, t), 1e-3 * final_radius)
            << "t = " << t;
    }
}

TEST(ViscoelasticLoading, StandardSolidCreepUnderConstantForceEq34) {
    const double G_inf = 1e6, G1 = 3e6, tau1 = 0.2, R = 0.01, F0 = 0.5;
    const auto result = run_toml(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.2
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "force"
history = [[0.0, 0.5], [1.0, 0.5]]
)");
    const auto creep = [&](double t) { return reference::standard_solid_creep(G_inf, G1, tau1, t); };
    const double final_depth = reference::sphere_creep_depth(creep, R, F0, 0.0, 1.0);
    for (std::size_t i = 1; i < result.time.size(); ++i) {
        // Table 1 creep function in eq. (34): 1e-4 of the final depth.
        EXPECT_NEAR(result.depth[i], reference::sphere_creep_depth(creep, R, F0, 0.0, result.time[i]), 1e-4 * final_depth)
            << "t = " << result.time[i];
    }
}

TEST(ViscoelasticLoading, PronySeriesCreepUnderRampedForceEq34) {
    const double R = 0.005, F0 = 0.2, ramp = 0.5;
    const std::string text = R"(
[material]
model = "prony"
G_inf = 0.5e6
terms = [[1.0e6, 1.0e-3], [0.8e6, 1.0e-2], [0.6e6, 1.0e-1], [0.4e6, 1.0]]
[indenter]
shape = "sphere"
R = 0.005
[load]
control = "force"
history = [[0.0, 0.0], [0.5, 0.2], [2.0, 0.2]]
)";
    const auto result = run_toml(text);
    const auto material = rheology::Rheology::prony(0.5e6, {{1.0e6, 1e-3}, {0.8e6, 1e-2}, {0.6e6, 1e-1}, {0.4e6, 1.0}});
    const auto creep = [&](double t) { return material.creep(t); };
    const auto depth = [&](double t) { return reference::sphere_creep_depth(creep, R, F0, ramp, t); };
    const double final_depth = depth(2.0);
    for (std::size_t i = 1; i < result.time.size(); ++i) {
        // Eq. (34) with the exact Prony creep function: 1e-4 of the final depth.
        EXPECT_NEAR(result.depth[i], depth(result.time[i]), 1e-4 * final_depth) << "t = " << result.time[i];
    }
}

TEST(ViscoelasticLoading, LeeRadokSphereRampAndHold) {
    const reference::PowerLawIndenter sphere = reference::sphere_indenter(0.01);
    const reference::PronyMaterial material{1e6, 0.0, {{2e6, 0.05}, {1e6, 0.5}}};
    const reference::PiecewiseLinear depth{{0.0, 0.3, 1.0}, {0.0, 1e-4, 1e-4}};
    const auto result = run_toml(R"(
[material]
model = "prony"
G_inf = 1.0e6
terms = [[2.0e6, 0.05], [1.0e6, 0.5]]
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.3, 1.0e-4], [1.0, 1.0e-4]]
)");
    const double peak = reference::lee_radok_force(sphere, material, depth, 0.3);
    for (std::size_t i = 0; i < result.time.size(); i += 10) {
        // Lee-Radok quadrature (eq. 15, 16): 1e-5 of the peak force, relaxation during the hold included.
        EXPECT_NEAR(result.force[i], reference::lee_radok_force(sphere, material, depth, result.time[i]), 1e-5 * peak)
            << "t = " << result.time[i];
    }
}

}  // namespace
}  // namespace mdr
