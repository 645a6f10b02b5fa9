// LayerStepper::grow_to (src/drivers/layer_stepping.hpp): a growing step solved over the contact radius against the
// same step solved over the depth, and at the edge of the radius the layer was prepared for.

#include <gtest/gtest.h>

#include <memory>

#include "drivers/layer_stepping.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace {

using mdr::contact::Layer;
using mdr::contact::LayerContact;
using mdr::contact::LayerInterface;

TEST(LayerGrowTo, MeetsTheForceAndRefusesBeyondThePreparedRadius) {
    const auto material = mdr::rheology::Rheology::standard(1.0e3, 3.0e3, 0.2);
    const double largest_radius = 4.0e-6;
    const LayerContact layer(Layer{2.0e-6, LayerInterface::bonded}, 0.5, mdr::profile::make_sphere(1.0e-5),
                             largest_radius);
    const mdr::drivers::LayerStepper stepper(material, layer, 4.0, 0.0, 1.0e-6);
    // The force at the widest contact prepared for, from a step over the depth: a root just inside is found (the
    // bracket grows past the largest radius on its way), one just beyond is refused naming `layer`.
    const auto widest = layer.at_radius(largest_radius);
    const double widest_force = stepper.grow(0.1, widest.depth).force;
    const auto inside = stepper.grow_to(0.1, 0.0, 0.999 * widest_force, 1e-12 * widest_force);
    EXPECT_NEAR(inside.force, 0.999 * widest_force, 1e-12 * widest_force);
    EXPECT_NEAR(stepper.grow(0.1, inside.centre).force, inside.force, 1e-7 * widest_force);  // over the depth
    EXPECT_LT(inside.contact.contact_radius, largest_radius);
    EXPECT_THROW(stepper.grow_to(0.1, 0.0, 1.001 * widest_force, 1e-12 * widest_force), mdr::InvalidInput);
    // With a spring, F + k d = k z.
    const double k = 0.05, z = 2.0 * widest.depth;
    const auto spring = stepper.grow_to(0.1, k, k * z, 1e-12 * widest_force);
    EXPECT_NEAR(spring.force, k * (z - spring.centre), 1e-12 * widest_force);
}

}  // namespace
