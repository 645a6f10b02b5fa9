// run_sweep_points, the basis of the distributed sweep: rows depend only on their own point, so any split or order
// of the points gives the rows of the whole grid bit for bit (wall_seconds, a measurement, aside).

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "mdr/error.hpp"
#include "mdr/io/summary.hpp"
#include "mdr/io/sweep.hpp"

namespace mdr::io {
namespace {

constexpr const char* light_case = R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.1, 1.0e-4], [0.2, 0.0]]
[numerics]
elements = 50
time_step = 2.0e-3
)";

// The summary without its measured wall time, every value kept exactly.
Summary without_wall_time(Summary summary) {
    std::erase_if(summary, [](const Document::Entry& entry) { return entry.key == "wall_seconds"; });
    return summary;
}

// The number under `key` (-1 when the summary has none).
double number_at(const Summary& summary, const std::string& key) {
    const auto entry = std::find_if(summary.begin(), summary.end(), [&](const auto& e) { return e.key == key; });
    return entry == summary.end() ? -1.0 : std::get<double>(entry->value.value);
}

TEST(SweepPoints, AreTheCartesianProductWithTheLastAxisFastest) {
    const std::vector<SweepAxis> axes{{"a", {1.0, 2.0}}, {"b", {10.0, 20.0, 30.0}}};
    const auto points = sweep_points(axes);
    const std::vector<std::vector<double>> expected{{1, 10}, {1, 20}, {1, 30}, {2, 10}, {2, 20}, {2, 30}};
    EXPECT_EQ(points, expected);
}

TEST(SweepPoints, AnySplitAndOrderGivesTheRowsOfTheWholeGrid) {
    const std::vector<SweepAxis> axes{parse_sweep_axis("material.tau1=1e-3:1:5:log"),
                                      parse_sweep_axis("material.G1=1e6,-1,1e7")};  // G1 = -1 fails
    const auto whole = run_sweep(light_case, "case", axes, 2, {});
    ASSERT_EQ(whole.size(), 15u);
    auto points = sweep_points(axes);
    std::reverse(points.begin(), points.end());
    const std::vector<std::vector<double>> first(points.begin(), points.begin() + 4);
    const std::vector<std::vector<double>> rest(points.begin() + 4, points.end());
    auto rows = run_sweep_points(light_case, "case", {"material.tau1", "material.G1"}, first, 1, {});
    const auto more = run_sweep_points(light_case, "case", {"material.tau1", "material.G1"}, rest, 3, {});
    rows.insert(rows.end(), more.begin(), more.end());
    std::reverse(rows.begin(), rows.end());
    std::size_t failed = 0;
    for (std::size_t r = 0; r < whole.size(); ++r) {
        EXPECT_EQ(rows[r].point, whole[r].point);
        EXPECT_EQ(rows[r].error, whole[r].error);
        if (whole[r].summary.empty()) {
            EXPECT_TRUE(rows[r].summary.empty());
            ++failed;
        } else {
            EXPECT_EQ(without_wall_time(rows[r].summary), without_wall_time(whole[r].summary)) << r;
        }
    }
    EXPECT_EQ(failed, 5u);
}

TEST(SweepPoints, ARowWithTheWrongNumberOfValuesIsRefused) {
    EXPECT_THROW(run_sweep_points(light_case, "case", {"material.tau1"}, {{0.1, 2.0}}, 1, {}), InvalidInput);
    EXPECT_TRUE(run_sweep_points(light_case, "case", {"material.tau1"}, {}, 1, {}).empty());
}


TEST(SweepOrder, RowsKeepGridOrderWhateverTheHandOut) {
    // A parallel sweep hands out its points costliest first (drivers::estimate_work), yet its rows keep grid order
    // and are, bit for bit, those of a sweep on one thread (which runs the points in grid order). The cost falls by
    // 64x along the time-step axis, so the costliest points come first in the hand-out, last in the rows; G1 = -1
    // fails at once (cost 0).
    const std::vector<SweepAxis> axes{parse_sweep_axis("numerics.time_step=1e-5,4e-5,1.6e-4,6.4e-4"),
                                      parse_sweep_axis("material.G1=1e6,-1,3e6")};
    const auto serial = run_sweep(light_case, "case", axes, 1, {});
    const auto parallel = run_sweep(light_case, "case", axes, 3, {});
    const auto points = sweep_points(axes);
    ASSERT_EQ(serial.size(), points.size());
    ASSERT_EQ(parallel.size(), points.size());
    for (std::size_t r = 0; r < points.size(); ++r) {
        EXPECT_EQ(parallel[r].point, points[r]) << r;
        EXPECT_EQ(parallel[r].error, serial[r].error) << r;
        EXPECT_EQ(parallel[r].error.empty(), points[r][1] > 0.0) << r;
        if (!serial[r].summary.empty()) {
            ASSERT_FALSE(parallel[r].summary.empty()) << r;
            EXPECT_EQ(without_wall_time(parallel[r].summary), without_wall_time(serial[r].summary)) << r;
            EXPECT_EQ(number_at(parallel[r].summary, "time_step"), points[r][0]);
        }
    }
}

}  // namespace
}  // namespace mdr::io
