// fit::curves_window: the lags a fit's runs of its curves need, for any contact point and baseline. The expectation
// is the case's own rule (drivers::material_window, the check drivers::validate makes) applied to each run the
// forward model makes (driving_points and drive, as run_curve builds them) at many contact points and baselines:
// every such window lies inside curves_window.

#include "mdr/fit/curve_window.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fit/curve_model.hpp"
#include "mdr/drivers/material_window.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::fit {
namespace {

drivers::ContactCase model_case() {
    return {.title = "curve window",
            .material = rheology::Rheology::elastic(1e6),
            .indenter = profile::make_sphere(1e-3),
            .control = drivers::DisplacementControl{},
            .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
            .end_time = 1.0};
}

// The window of the run of `curve` at a contact point and baseline, as run_curve drives it.
rheology::TimeWindow run_window(const Curve& curve, bool depth_driven, double contact, double baseline) {
    std::vector<double> values(curve.time.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] = depth_driven ? curve.depth[i] - contact : std::max(curve.force[i] - baseline, 0.0);
    }
    drivers::ContactCase run = model_case();
    drive(run, driving_points(curve.time, values), curve.time, depth_driven);
    return drivers::material_window(run);
}

// An approach, a ramp to 1 um in 1 s and a hold to 30 s, sampled unevenly (10 ms, then 1 ms around the top, then
// 50 ms); the force of a creep test: a step to 1 mN over one 1 ms row at the top (a fast change), held.
Curve ramp_hold() {
    std::vector<double> time, depth, force;
    for (double t = -0.5; t < 0.9; t += 0.01) time.push_back(t);
    for (double t = 0.9; t < 1.1; t += 0.001) time.push_back(t);
    for (double t = 1.1; t <= 30.0; t += 0.05) time.push_back(t);
    for (const double t : time) {
        depth.push_back(1e-6 * std::clamp(t, 0.0, 1.0));
        force.push_back(t < 1.0 ? 1e-6 * t : 1e-3);
    }
    return make_curve("ramp hold", time, depth, force);
}

TEST(CurvesWindow, CoversEveryRunOfTheCurveWhateverItsContactPointAndBaseline) {
    const Curve curve = ramp_hold();
    for (const Fitted fitted : {Fitted::force, Fitted::depth}) {
        const rheology::TimeWindow window = curves_window({curve}, fitted, model_case());
        EXPECT_TRUE(window.frequencies.empty());
        const bool depth_driven = fitted == Fitted::force;
        for (double shift = -2e-6; shift <= 2e-6; shift += 1e-7) {  // contact points; baselines (in N) likewise
            const auto needed = run_window(curve, depth_driven, shift, shift * 1e3);
            EXPECT_LE(window.shortest, needed.shortest) << "shift " << shift;
            EXPECT_GE(window.longest, needed.longest) << "shift " << shift;
        }
    }
}

TEST(CurvesWindow, IsTheUnionOverTheCurves) {
    const Curve long_one = ramp_hold();
    std::vector<double> time, depth, force;
    for (int i = 0; i < 10; ++i) {  // 1 ms in 0.1 ms rows
        time.push_back(1e-4 * i);
        depth.push_back(1e-9 * i);
        force.push_back(1e-6 * i);
    }
    const Curve short_one = make_curve("short", time, depth, force);
    const auto both = curves_window({long_one, short_one}, Fitted::force, model_case());
    const auto first = curves_window({long_one}, Fitted::force, model_case());
    const auto second = curves_window({short_one}, Fitted::force, model_case());
    EXPECT_EQ(both.shortest, std::min(first.shortest, second.shortest));
    EXPECT_EQ(both.longest, std::max(first.longest, second.longest));
    // The long curve's duration and the interval its run starts early (its first row out of contact).
    const auto& rows = long_one.time;
    EXPECT_DOUBLE_EQ(first.longest, rows.back() - (rows.front() - (rows[1] - rows[0])));
}

}  // namespace
}  // namespace mdr::fit
