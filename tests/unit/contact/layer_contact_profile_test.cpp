// LayerContact::profile (docs/theory.md eq. L3, L25, L26): the elastic layer's line loads and surface at any point,
// against rules they must meet: 2 int_0^a q = the force and 2 int_0^a q_d = the stiffness (eq. L5), the force-free
// edge q(a) = 0 (eq. L6), w1 = d - g inside and continuous at the edge, and the half-space's w1 = 0 outside (K = 0).

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/numerics/gauss_rule.hpp"
#include "mdr/profile/profile.hpp"

namespace {

using mdr::contact::Layer;
using mdr::contact::LayerContact;
using mdr::contact::LayerInterface;

constexpr double sphere_radius = 1e-5, thickness = 2e-6, contact_radius = 3e-6;

// The nodes of `rule` (on [0, 1]) on [0, a].
std::vector<double> gauss_points(double a, const mdr::numerics::GaussRule& rule) {
    std::vector<double> points;
    for (const double node : rule.nodes) points.push_back(a * node);
    return points;
}

TEST(LayerContactProfile, LineLoadsCarryTheForceAndTheStiffness) {
    const std::shared_ptr<const mdr::profile::Profile> sphere = mdr::profile::make_sphere(sphere_radius);
    for (const auto interface : {LayerInterface::bonded, LayerInterface::sliding}) {
        const LayerContact layer(Layer{thickness, interface}, 0.5, sphere, 2.0 * contact_radius);
        const auto state = layer.at_radius(contact_radius);
        const auto rule = mdr::numerics::make_gauss_rule(64);
        const auto points = gauss_points(contact_radius, rule);
        const auto profile = layer.profile(state, points);
        double force = 0.0, stiffness = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            force += 2.0 * contact_radius * rule.weights[i] * profile.load[i];
            stiffness += 2.0 * contact_radius * rule.weights[i] * profile.unit_depth_load[i];
            EXPECT_NEAR(profile.surface[i], state.depth - sphere->equivalent(points[i]), 1e-15);
        }
        EXPECT_NEAR(force / state.force, 1.0, 1e-9);
        EXPECT_NEAR(stiffness / state.stiffness, 1.0, 1e-9);
    }
}

TEST(LayerContactProfile, TheEdgeIsForceFreeAndTheSurfaceContinuous) {
    const std::shared_ptr<const mdr::profile::Profile> sphere = mdr::profile::make_sphere(sphere_radius);
    const LayerContact layer(Layer{thickness, LayerInterface::bonded}, 0.5, sphere, 2.0 * contact_radius);
    const auto state = layer.at_radius(contact_radius);
    const double step = 1e-6 * contact_radius;
    const std::vector<double> points{contact_radius, contact_radius + step, 1.5 * contact_radius};
    const auto profile = layer.profile(state, points);
    const double scale = state.depth;  // q / E* has the unit of a depth
    EXPECT_NEAR(profile.load[0], 0.0, 1e-9 * scale);
    EXPECT_EQ(profile.load[1], 0.0);
    EXPECT_EQ(profile.unit_depth_load[1], 0.0);
    // w1 is continuous at the edge, where its slope jumps (q'(a) / E*, eq. L19): d - g(a) from outside to O(step).
    EXPECT_NEAR(profile.surface[1], state.depth - sphere->equivalent(contact_radius), 1e-5 * scale);
    // The layer is stiffer than the half-space: the surface beyond the contact is drawn below w1 = 0 (-K q, K > 0).
    EXPECT_LT(profile.surface[2], 0.0);
}

TEST(LayerContactProfile, AVeryThickLayerIsTheHalfSpacesMdr) {
    // K = O(1/h) -> 0 (errors O(a/h) = 3e-9): q = E* (d - g) inside (the half-space's q = E* w1D) and w1 = 0 outside.
    const std::shared_ptr<const mdr::profile::Profile> sphere = mdr::profile::make_sphere(sphere_radius);
    const LayerContact layer(Layer{1e3, LayerInterface::sliding}, 0.5, sphere, 2.0 * contact_radius);
    const auto state = layer.at_radius(contact_radius);
    EXPECT_NEAR(state.depth, contact_radius * contact_radius / sphere_radius, 1e-8 * state.depth);
    const std::vector<double> points{0.0, 0.5 * contact_radius, 1.5 * contact_radius};
    const auto profile = layer.profile(state, points);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(profile.load[i], state.depth - sphere->equivalent(points[i]), 1e-8 * state.depth);
        EXPECT_NEAR(profile.unit_depth_load[i], 1.0, 1e-8);
    }
    EXPECT_NEAR(profile.surface[2], 0.0, 1e-8 * state.depth);
}

}  // namespace
