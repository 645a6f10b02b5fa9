// LayerCells (src/drivers/layer_cells.hpp, docs/theory.md eq. L16 to L19) on cases with closed forms: an elastic flat
// punch on a very thick layer (Sneddon: F = 2 E* a d, E* = 4G), and its lift-off located inside a step; with a
// parallel dashpot under a solved depth, the depth continuous and monotone in the force across an entry.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

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

TEST(LayerCells, WithADashpotTheSolvedDepthIsContinuousAndMonotoneInTheForceAcrossAnEntry) {
    // A Kelvin-Voigt sphere on a bonded layer under force control: from one state, the next step's depth for forces
    // on a fine grid across the entry of several cells. More force presses deeper (F(d) grows on every contact
    // set), continuously: an entering cell's line load grows from zero where the indenter meets its free surface. With the indenter's rate in the entering cell's dashpot F(d) jumped up there by that dashpot's part,
    // and the solved depth fell back as the force crossed the jump (by 0.44 nm, 16 % of the rise over the grid).
    const auto material = mdr::rheology::Rheology::kelvin_voigt(1.0e3, 50.0);
    const auto sphere = mdr::profile::make_sphere(1.0e-5);
    mdr::drivers::LayerCells cells(material, {.thickness = 2.0e-6}, 0.5, *sphere, 6.0e-6, 60);
    const double time_step = 1.0e-3;
    for (int n = 1; n <= 20; ++n) static_cast<void>(cells.step_loaded(time_step, 5.0e-10 * n, 0.0, 0.0));
    std::vector<double> depths;
    const std::size_t samples = 2000;
    for (std::size_t j = 0; j <= samples; ++j) {
        auto trial = cells;  // the same state for every force
        const double force = 1.0e-8 * (1.0 + static_cast<double>(j) / static_cast<double>(samples));
        depths.push_back(trial.step_loaded(time_step, force, 0.0, 0.0).depth);
    }
    const double mean_increment = (depths.back() - depths.front()) / static_cast<double>(samples);
    double smallest = mean_increment, largest = 0.0;
    for (std::size_t j = 0; j < samples; ++j) {
        smallest = std::min(smallest, depths[j + 1] - depths[j]);
        largest = std::max(largest, depths[j + 1] - depths[j]);
    }
    EXPECT_GT(smallest, 0.0) << smallest / mean_increment;
    EXPECT_LT(largest, 2.0 * mean_increment) << largest / mean_increment;
}

}  // namespace
