// An impact on a viscoelastic layer (docs/theory.md, "Layers"): a very thick layer against the half-space impact, and
// an elastic layer's restitution against energy conservation (e = 1, to the time step's order).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

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

}  // namespace
}  // namespace mdr
