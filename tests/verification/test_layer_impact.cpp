// An impact on a viscoelastic layer (docs/theory.md, "Layers"): a very thick layer against the half-space impact, and
// an elastic layer's restitution against energy conservation (e = 1, to the time step's order), its largest depth and
// contact time against the energy integral of the elastic layer's force.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/profile/profile.hpp"
#include "reference/quadrature.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

// A 10 g sphere of radius 1 cm at 0.1 m/s (as test_impact_cross_method): a contact radius of ~1.2 mm.
std::string impact_case(const std::string& material, const std::string& rest) {
    return fmt::format(R"(
[material]
{}
[indenter]
shape = "sphere"
R = 0.01
mass = 0.01
[load]
control = "impact"
velocity = 0.1
{})",
                       material, rest);
}

const std::string standard_solid = "model = \"standard\"\nG_inf = 1.0e6\nG1 = 1.0e6\ntau1 = 1.0e-4";

TEST(LayerImpact, VeryThickLayerIsTheHalfSpaceImpact) {
    const auto half_space = run_toml(impact_case(standard_solid, ""));
    const auto thick = run_toml(impact_case(standard_solid, "[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n"));
    ASSERT_TRUE(half_space.impact && thick.impact);
    ASSERT_EQ(half_space.time.size(), thick.time.size());
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    double depth_error = 0.0;
    for (std::size_t i = 0; i < half_space.time.size(); ++i) {
        depth_error = std::max(depth_error, std::abs(half_space.depth[i] - thick.depth[i]) / deepest);
    }
    // Observed: e 0.88584858 against 0.88584866 (7.6e-8), T to 5.1e-7 of itself, the depth to 1.4e-6 of the largest
    // (the half-space's elements, its contact edge between them; the same integrator and steps).
    EXPECT_NEAR(thick.impact->restitution, half_space.impact->restitution, 1e-6);
    EXPECT_NEAR(thick.impact->contact_time, half_space.impact->contact_time, 1e-6 * half_space.impact->contact_time);
    EXPECT_LT(depth_error, 3e-6);
    EXPECT_EQ(thick.force.back(), 0.0);
    EXPECT_LT(thick.velocity.back(), 0.0);  // rebounding
}

TEST(LayerImpact, ElasticLayerReturnsTheEnergy) {
    // An elastic body returns all the energy it was given: e = 1, here on a bonded layer as thick as the contact is
    // wide (a ~ 1.2 h), up to the trapezoidal rule's error in the nonlinear contact, second order in the time step.
    std::vector<double> losses;
    for (const double step : {4e-6, 2e-6, 1e-6}) {
        const auto result = run_toml(impact_case("model = \"elastic\"\nG = 1.0e6",
                                                 fmt::format("end = 1.0\n[numerics]\ntime_step = {}\n[layer]\n"
                                                             "thickness = 1.0e-3\ninterface = \"bonded\"\n", step)));
        ASSERT_TRUE(result.impact);
        losses.push_back(1.0 - result.impact->restitution);
    }
    // Observed 2.4e-8, 4.5e-9, 6.2e-10 (T = 2.347 ms, 587 to 2347 steps): orders 2.4 and 2.9.
    EXPECT_LT(std::abs(losses.back()), 2e-9);
    EXPECT_GT(testing::observed_order(losses[0], losses[1]), 1.8);
    EXPECT_GT(testing::observed_order(losses[1], losses[2]), 1.8);
}

TEST(LayerImpact, ElasticLayerMeetsTheEnergyIntegralOfItsForce) {
    // An elastic layer: m d'' = -F(d), F = E* F_1(d) with F_1 the elastic layer's force at unit E* (eq. L3-L6,
    // LayerContact, 96 nodes; E* = 4 G). Energy: W(d) = int_0^d F, the largest depth D from W(D) = m v0^2 / 2, and
    // the contact time T = 2 int_0^D dd / sqrt(v0^2 - 2 W(d)/m) (loading and unloading alike), by adaptive
    // Gauss-Kronrod in d = D s^2 (W) and d = D (1 - u^2) (T, whose 1/sqrt singularity at D this removes).
    const double shear_modulus = 1.0e6, plane_modulus = 4.0 * shear_modulus, mass = 0.01, speed = 0.1;
    const contact::LayerContact layer(contact::Layer{1.0e-3, contact::LayerInterface::bonded}, 0.5,
                                      profile::make_sphere(0.01), 4.0e-3, 96);
    const auto force = [&](double depth) { return plane_modulus * layer.at_depth(depth).force; };
    const auto work = [&](double from, double to) {  // int_from^to F, 0 <= from < to
        return reference::integrate([&](double s) { return force(from + (to - from) * s * s) * 2.0 * s; }, 0.0, 1.0,
                                    1e-8) * (to - from);
    };
    const double energy = 0.5 * mass * speed * speed;
    const double deepest = reference::find_root([&](double d) { return work(0.0, d) - energy; }, 1e-5, 2e-4, 1e-13);
    const double contact_time = 2.0 * reference::integrate(
        [&](double u) {
            if (u == 0.0) return 2.0 * deepest / std::sqrt(2.0 * force(deepest) * deepest / mass);
            const double depth = deepest * (1.0 - u * u);
            return 2.0 * deepest * u / std::sqrt(2.0 * work(depth, deepest) / mass);
        },
        0.0, 1.0, 1e-8);
    const auto result = run_toml(impact_case("model = \"elastic\"\nG = 1.0e6",
                                             "end = 1.0\n[numerics]\ntime_step = 1.0e-6\n[layer]\n"
                                             "thickness = 1.0e-3\ninterface = \"bonded\"\n"));
    ASSERT_TRUE(result.impact);
    const double driven = *std::max_element(result.depth.begin(), result.depth.end());
    // Observed 2.3e-7 and 3.4e-7 (the largest of the steps' depths; T = 2.347 ms, D = 84.7 um, a/h ~ 1.2; the
    // half-space's D would be 140 um).
    EXPECT_NEAR(result.impact->contact_time / contact_time, 1.0, 1e-6);
    EXPECT_NEAR(driven / deepest, 1.0, 1e-6);
}

}  // namespace
}  // namespace mdr
