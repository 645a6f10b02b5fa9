// The fast load changes of a history and the steps graded after them (src/drivers/load_history.cpp).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mdr/drivers/load_history.hpp"

namespace mdr::drivers {
namespace {

LoadHistory history(std::vector<LoadPoint> points) { return LoadHistory(std::move(points), "load.history"); }

TEST(FastChangeTimes, TheStartJumpsAndBothEndsOfAShortLargeRamp) {
    // A ramp of 1e-4 s (shorter than the step 0.01 s) to the full load, a slow ramp, a jump, a hold.
    const auto load = history({{0.0, 0.0}, {1e-4, 1.0}, {1.0, 2.0}, {1.0, 1.5}, {3.0, 1.5}});
    EXPECT_EQ(fast_change_times(load, 3.0, 0.01, 20), (std::vector<double>{0.0, 1e-4, 1.0}));
}

TEST(FastChangeTimes, SmallChangesBetweenDenseSamplesAreNotFast) {
    // A measured-like ramp: 1000 points 1e-3 s apart, each moving the load by 1/1000 of its peak (< 1/20).
    std::vector<LoadPoint> points;
    for (int i = 0; i <= 1000; ++i) points.push_back({1e-3 * i, 1e-3 * i});
    EXPECT_EQ(fast_change_times(history(points), 1.0, 0.01, 20), (std::vector<double>{0.0}));
}

TEST(FastChangeTimes, PointsAfterTheEndAreIgnored) {
    const auto load = history({{0.0, 0.0}, {1.0, 1.0}, {2.0, 1.0}, {2.0, 0.0}});
    EXPECT_EQ(fast_change_times(load, 1.5, 0.01, 20), (std::vector<double>{0.0}));
}

TEST(GradeAfterChanges, StepsGrowAsTheRatioTimesTheTimeSinceTheChangeUpToTheGrid) {
    const std::vector<GridNode> nodes{{0.0, 0.0}, {1.0, 1.0}, {2.0, 1.0}, {3.0, 1.0}};
    const double ratio = 0.5, first = 1e-3;
    const auto graded = grade_after_changes(nodes, {1.0}, ratio, first);
    // Nothing before the change; from it the steps are max(first, ratio (t - 1)).
    ASSERT_GE(graded.size(), 5u);
    EXPECT_EQ(graded[0].time, 0.0);
    EXPECT_EQ(graded[1].time, 1.0);
    EXPECT_DOUBLE_EQ(graded[2].time, 1.0 + first);
    for (std::size_t n = 3; n < graded.size(); ++n) {
        const double step = graded[n].time - graded[n - 1].time;
        // The step into a grid node may be up to half a graded step longer.
        EXPECT_LE(step, 2.0 * std::max(first, ratio * (graded[n - 1].time - 1.0))) << "node " << n;
        EXPECT_GT(step, 0.0);
    }
    EXPECT_EQ(graded.back().time, 3.0);
    // Grid nodes stay; the load stays linear between them (held at 1 here).
    for (const auto& node : graded) {
        if (node.time >= 1.0) {
            EXPECT_EQ(node.value, 1.0);
        }
    }
    // About ln(1 / first) / ln(1 + ratio) graded steps, not more.
    EXPECT_LT(graded.size(), nodes.size() + static_cast<std::size_t>(std::log(1.0 / first) / std::log1p(ratio)) + 3);
}

TEST(GradeAfterChanges, AJumpInTheGridIsKept) {
    const std::vector<GridNode> nodes{{0.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}};
    const auto graded = grade_after_changes(nodes, {0.0}, 0.1, 1e-2);
    ASSERT_GE(graded.size(), 4u);
    EXPECT_EQ(graded[0].value, 0.0);
    EXPECT_EQ(graded[1].time, 0.0);
    EXPECT_EQ(graded[1].value, 1.0);
    EXPECT_DOUBLE_EQ(graded[2].time, 1e-2);
}

}  // namespace
}  // namespace mdr::drivers
