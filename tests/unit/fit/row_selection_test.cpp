// select_rows: windows, `until = "pull_off"` and the adhesion of a retract. The record is closed form, made here: a
// Hertz approach F = k d^1.5, k = 16/3 G sqrt(R) (Johnson eq. 4.22, nu = 1/2), from d = -3 um to 2 um and back
// to -3 um, on a baseline b0 with Gaussian noise (fixed seed). The retract carries a linear pull-off ramp of
// adhesion F_a: F - b0 = k d^1.5 - F_a for d >= 0, -F_a (d + delta) / delta for -delta <= d < 0, 0 below. So the
// pull-off force is -F_a, the retract first falls below the baseline where k d^1.5 = F_a (d* = (F_a / k)^(2/3)),
// and the work of adhesion is F_a delta / 2 + 0.6 F_a d* (the integral of F_a - k d^1.5 from 0 to d*).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "mdr/error.hpp"
#include "mdr/fit/curve.hpp"

namespace mdr::fit {
namespace {

constexpr double stiffness = 16.0 / 3.0 * 2e3 * 2.2360679774997896e-3;  // k = 16/3 G sqrt(R), G = 2 kPa, R = 5 um
constexpr double sigma = 1e-11;     // N
constexpr double offset = 1e-9;     // b0 [N]
constexpr double delta = 0.5e-6;    // m
constexpr double depth_step = 2e-9; // m per row
constexpr double time_step = 1e-3;  // s

double pull_off_depth(double adhesion) { return std::pow(adhesion / stiffness, 2.0 / 3.0); }

Curve retract_record(double adhesion) {
    std::mt19937_64 random(11);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> time, depth, force;
    const auto row = [&](double d, bool retract) {
        double relative = d > 0.0 ? stiffness * std::pow(d, 1.5) : 0.0;
        if (retract && d >= -delta) relative -= d >= 0.0 ? adhesion : adhesion * (d + delta) / delta;
        time.push_back(static_cast<double>(time.size()) * time_step);
        depth.push_back(d);
        force.push_back(offset + relative + sigma * normal(random));
    };
    for (int i = 0; i <= 2500; ++i) row(-3e-6 + i * depth_step, false);
    for (int i = 1; i <= 2500; ++i) row(2e-6 - i * depth_step, true);
    return make_curve("retract", std::move(time), std::move(depth), std::move(force));
}

// The retract rows (of 2500) whose depth is below d*: those from the pull-off on.
std::size_t rows_after_pull_off(double adhesion) {
    return static_cast<std::size_t>(std::ceil((pull_off_depth(adhesion) + 3e-6) / depth_step));
}

bool has_note(const Curve& curve, const std::string& part) {
    return std::any_of(curve.notes.begin(), curve.notes.end(),
                       [&](const std::string& note) { return note.find(part) != std::string::npos; });
}

std::string notes_of(const Curve& curve) {
    std::string text;
    for (const auto& note : curve.notes) text += note + "\n";
    return text;
}

// Adhesion measured; by default the adhesive part is left out (before select_rows every row was fitted, unflagged).
TEST(RowSelection, AdhesiveRetractIsCutAtPullOffByDefault) {
    const double adhesion = 5e-9;
    Curve curve = retract_record(adhesion);
    const std::size_t rows = curve.time.size();
    select_rows(curve, {});
    EXPECT_NEAR(curve.adhesion.pull_off_force, -adhesion, 4.0 * sigma);
    const double work = adhesion * delta / 2.0 + 0.6 * adhesion * pull_off_depth(adhesion);
    EXPECT_NEAR(curve.adhesion.work, work, 0.03 * work);
    EXPECT_NEAR(static_cast<double>(curve.rows_left_out), static_cast<double>(rows_after_pull_off(adhesion)), 2.0);
    EXPECT_EQ(curve.time.size(), rows - curve.rows_left_out);
    EXPECT_TRUE(has_note(curve, "the retract is adhesive")) << notes_of(curve);
    EXPECT_TRUE(has_note(curve, "by default; until = \"end\" keeps them")) << notes_of(curve);
}

TEST(RowSelection, UntilEndKeepsTheAdhesiveRetractAndSaysSo) {
    Curve curve = retract_record(5e-9);
    const std::size_t rows = curve.time.size();
    select_rows(curve, {.until = Until::end});
    EXPECT_EQ(curve.time.size(), rows);
    EXPECT_EQ(curve.rows_left_out, 0u);
    EXPECT_TRUE(has_note(curve, "fitted through (until = \"end\")")) << notes_of(curve);
}

// No adhesion: nothing measured, nothing cut by default; until = "pull_off" cuts where the force first falls below
// the baseline, at the contact (d = 0) within the noise: the rows of the retract below d = 0, give or take a few.
TEST(RowSelection, UntilPullOffWithoutAdhesion) {
    Curve curve = retract_record(0.0);
    const std::size_t rows = curve.time.size();
    Curve whole = curve;
    select_rows(whole, {});
    EXPECT_EQ(whole.time.size(), rows);
    EXPECT_EQ(whole.adhesion.pull_off_force, 0.0);
    EXPECT_TRUE(whole.notes.empty()) << notes_of(whole);
    select_rows(curve, {.until = Until::pull_off});
    EXPECT_NEAR(static_cast<double>(curve.rows_left_out), 1500.0, 20.0);
    EXPECT_TRUE(has_note(curve, "until = \"pull_off\"")) << notes_of(curve);
}

// A time window keeps the rows inside it (ends included); a depth and a force window likewise; too few rows and a
// reversed window are refused naming the key.
TEST(RowSelection, Windows) {
    Curve curve = retract_record(0.0);
    select_rows(curve, {.time = std::array<double, 2>{1.0, 2.0}, .until = Until::end});
    EXPECT_NEAR(static_cast<double>(curve.time.size()), 1001.0, 1.0);
    EXPECT_NEAR(curve.time.front(), 1.0, 1e-3);
    EXPECT_TRUE(has_note(curve, "rows outside the window are left out")) << notes_of(curve);

    Curve deep = retract_record(0.0);
    select_rows(deep, {.depth = std::array<double, 2>{-1e-6, 3e-6}, .until = Until::end});
    EXPECT_TRUE(std::all_of(deep.depth.begin(), deep.depth.end(), [](double d) { return d >= -1e-6 && d <= 3e-6; }));

    Curve strong = retract_record(0.0);
    select_rows(strong, {.force = std::array<double, 2>{0.0, 2e-8}, .until = Until::end});
    EXPECT_TRUE(std::all_of(strong.force.begin(), strong.force.end(), [](double f) { return f <= 2e-8; }));

    Curve few = retract_record(0.0);
    try {
        select_rows(few, {.time = std::array<double, 2>{0.0, 0.0055}});
        ADD_FAILURE() << "no error";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(std::string(error.what()), "window = 6 rows kept: a curve needs at least 10 rows");
    }
    try {
        select_rows(few, {.force = std::array<double, 2>{1.0, 0.0}});
        ADD_FAILURE() << "no error";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "window.force");
    }
}

}  // namespace
}  // namespace mdr::fit
