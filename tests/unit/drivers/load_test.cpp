// drivers::Load, the one load of normal and tangential loading: a piecewise-linear history, a harmonic, or both
// (value, end time, the times the grid steps on, the measured cycle), against values written out by hand.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "mdr/drivers/load.hpp"

namespace mdr::drivers {
namespace {

const LoadHistory ramp({{0.0, 0.0}, {1.0, 2.0}, {3.0, 2.0}}, "load.history");
const HarmonicLoad sine{0.5, 2.0, 1.0, 2.25};  // 0.5 sin(4 pi (t - 1)) for 1 <= t <= 2.25: 2.5 cycles

TEST(Load, AHistoryAlone) {
    const Load load{.history = ramp};
    EXPECT_EQ(load.value(0.5), 1.0);
    EXPECT_EQ(load.value(5.0), 2.0);
    EXPECT_EQ(load.end_time(), 3.0);
    EXPECT_EQ(load.breakpoints(), (std::vector<double>{0.0, 1.0, 3.0}));
    EXPECT_FALSE(load.last_full_cycle(3.0));
}

TEST(Load, AHarmonicAlone) {
    const Load load{.harmonic = sine};
    EXPECT_EQ(load.value(0.5), 0.0);
    EXPECT_NEAR(load.value(1.125), 0.5, 1e-15);  // a quarter period after the start
    EXPECT_EQ(load.end_time(), 2.25);
    // Start, end and the last full cycle [1.5, 2].
    EXPECT_EQ(load.breakpoints(), (std::vector<double>{1.0, 2.25, 1.5, 2.0}));
    const auto cycle = load.last_full_cycle(10.0);
    ASSERT_TRUE(cycle);
    EXPECT_DOUBLE_EQ(cycle->first, 1.5);
    EXPECT_DOUBLE_EQ(cycle->second, 2.0);
    EXPECT_FALSE(load.last_full_cycle(1.4));  // not one full cycle by then
}

TEST(Load, TheHarmonicAddsToTheHistory) {
    const Load load{.history = ramp, .harmonic = sine};
    EXPECT_EQ(load.value(0.5), 1.0);                     // before the harmonic
    EXPECT_NEAR(load.value(1.375), 2.0 - 0.5, 1e-15);    // three quarters of a period: sin = -1
    const double held = 0.5 * std::sin(2.0 * std::numbers::pi * 2.0 * 1.25);  // after its end: its end value
    EXPECT_NEAR(load.value(2.8), 2.0 + held, 1e-15);
    EXPECT_EQ(load.end_time(), 3.0);                     // the later of the two ends
    EXPECT_EQ(Load({.history = ramp, .harmonic = HarmonicLoad{0.5, 2.0, 1.0, 4.0}}).end_time(), 4.0);
    EXPECT_EQ(load.breakpoints(), (std::vector<double>{0.0, 1.0, 3.0, 1.0, 2.25, 1.5, 2.0}));
    EXPECT_TRUE(load.last_full_cycle(3.0));
}

}  // namespace
}  // namespace mdr::drivers
