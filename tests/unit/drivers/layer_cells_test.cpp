// LayerCells (src/drivers/layer_cells.hpp, docs/theory.md eq. L16 to L19) on cases with closed forms: an elastic flat
// punch on a very thick layer (Sneddon: F = 2 E* a d, E* = 4G), and its lift-off located inside a step.

#include <gtest/gtest.h>

#include <cmath>

#include "drivers/layer_cells.hpp"
#include "mdr/contact/layer.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace {

TEST(LayerCells, AnElasticFlatPunchOnAVeryThickLayerIsSneddons) {
    // h = 1 km: K = O(a/h) ~ 1e-9 (eq. L3); every cell takes q = E* d, F = 2 E* a d exactly on any cell count.
    const auto material = mdr::rheology::Rheology::elastic(1.0e3);
    const auto punch = mdr::profile::make_flat_punch(2.0e-6);
    mdr::drivers::LayerCells cells(material, {.thickness = 1.0e3}, 0.5, *punch, 2.0e-6, 50);
    const double depth = 1.0e-7;
    const auto state = cells.step(0.1, depth);
    EXPECT_NEAR(state.force, 2.0 * 4.0e3 * 2.0e-6 * depth, 1e-8 * state.force);
    EXPECT_DOUBLE_EQ(state.contact_radius, 2.0e-6);
    EXPECT_TRUE(state.touching);
}

TEST(LayerCells, ALiftOffIsLocatedInsideTheStep) {
    // Elastic: the line load is proportional to the depth, so the axis's edge function crosses zero where the
    // depth, linear over the step from 1e-7 to -3e-7, does: a quarter of the way.
    const auto material = mdr::rheology::Rheology::elastic(1.0e3);
    const auto punch = mdr::profile::make_flat_punch(2.0e-6);
    mdr::drivers::LayerCells cells(material, {.thickness = 1.0e3}, 0.5, *punch, 2.0e-6, 50);
    static_cast<void>(cells.step(0.1, 1.0e-7));
    const auto state = cells.step(0.1, -3.0e-7);
    EXPECT_EQ(state.force, 0.0);
    EXPECT_FALSE(state.touching);
    EXPECT_NEAR(state.touching_part.second, 0.25, 1e-6);
}

}  // namespace
