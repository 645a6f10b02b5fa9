// A parallel sweep hands out its points costliest first (drivers::estimate_work), yet its rows keep grid order and
// are, bit for bit, those of a sweep on one thread (which runs the points in grid order).

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "mdr/io/summary.hpp"
#include "mdr/io/sweep.hpp"

namespace mdr::io {
namespace {

// The time step grows along the grid, so the costliest points come first in the hand-out, last in the rows.
constexpr const char* stepped_case = R"(
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
time_step = 1.0e-3
)";

Summary without_wall_time(Summary summary) {
    std::erase_if(summary, [](const SummaryEntry& entry) { return entry.key == "wall_seconds"; });
    return summary;
}

double value_of(const Summary& summary, const std::string& key) {
    const auto entry = std::find_if(summary.begin(), summary.end(), [&](const auto& e) { return e.key == key; });
    return entry == summary.end() ? -1.0 : std::get<double>(entry->value);
}

TEST(SweepOrder, RowsKeepGridOrderWhateverTheHandOut) {
    // Costs from about 1 to 1/64 along the time-step axis; G1 = -1 fails at once (cost 0).
    const std::vector<SweepAxis> axes{parse_sweep_axis("numerics.time_step=1e-5,4e-5,1.6e-4,6.4e-4"),
                                      parse_sweep_axis("material.G1=1e6,-1,3e6")};
    const auto serial = run_sweep(stepped_case, "case", axes, 1, {});
    const auto parallel = run_sweep(stepped_case, "case", axes, 3, {});
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
            EXPECT_EQ(value_of(parallel[r].summary, "time_step"), points[r][0]);
        }
    }
}

}  // namespace
}  // namespace mdr::io
