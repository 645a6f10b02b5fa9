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

TEST(CutsTowardsZeros, NodesGradedAsAPowerOnTheLastFractionOfEachFallToZero) {
    // A fall from 1 to 0 over [1, 2] on steps of 0.01 (100 a segment): the last 0.2 s on t_k = 2 - 0.2 (k/n)^1.5,
    // n = ceil(1.5 0.2 / 0.01) = 30; a jump to zero and a fall after the end are not graded.
    const auto load = history({{0.0, 0.0}, {1.0, 1.0}, {2.0, 0.0}, {3.0, 1.0}, {3.0, 0.0}, {4.0, 1.0}, {5.0, 0.0}});
    const auto cuts = cuts_towards_zeros(load, 4.5, 0.01, 20, 0.2, 1.5);
    ASSERT_EQ(cuts.size(), 30u);
    for (std::size_t k = 1; k <= cuts.size(); ++k) {
        EXPECT_DOUBLE_EQ(cuts[k - 1], 2.0 - 0.2 * std::pow(static_cast<double>(k) / 30.0, 1.5));
    }
    EXPECT_DOUBLE_EQ(cuts.back(), 1.8);
    // No graded step longer than the segment's own step.
    EXPECT_LE(cuts[cuts.size() - 2] - cuts.back(), 0.01);
    // The grid with these cuts takes one step between them: 80 uniform steps up to 1.8, then the 30 graded ones.
    const auto nodes = make_time_grid(load, 2.0, 0.01, 20, cuts);
    EXPECT_EQ(nodes.size(), 1u + 100u + 80u + 30u);
    EXPECT_DOUBLE_EQ(nodes[nodes.size() - 2].time, cuts.front());
}

TEST(CutsTowardsZeros, ASegmentsLeastStepCountSetsTheGradedStep) {
    // A short fall (0.1 s, 20 steps of 5 ms at least, against a time step of 1 s): n = ceil(2 x 0.02 / 0.005) = 8.
    const auto load = history({{0.0, 0.0}, {1.0, 1.0}, {1.1, 0.0}});
    EXPECT_EQ(cuts_towards_zeros(load, 2.0, 1.0, 20, 0.2, 2.0).size(), 8u);
}

TEST(CutsTowardsZeros, CountedWithoutBeingMadeAsMany) {
    // Two falls to zero (a ramp and a dense fall) and a jump to zero, which is not graded.
    const auto load = history({{0.0, 0.0}, {1.0, 2.0}, {2.0, 0.0}, {3.0, 1.0}, {3.0, 0.0}, {4.0, 1.0}, {4.5, 0.0}});
    for (const double step : {0.1, 0.013, 1e-3}) {
        for (const double exponent : {1.5, 2.0}) {
            const auto cuts = cuts_towards_zeros(load, 4.5, step, 2, 0.2, exponent);
            EXPECT_EQ(count_cuts_towards_zeros(load, 4.5, step, 2, 0.2, exponent), static_cast<double>(cuts.size()))
                << step << " " << exponent;
        }
    }
    // A step that would make 4.5e12 cuts is counted at once (the work bound refuses it before any is made).
    EXPECT_NEAR(count_cuts_towards_zeros(load, 4.5, 1e-13, 2, 0.2, 1.5), 4.5e12, 1e9);
}

}  // namespace
}  // namespace mdr::drivers
