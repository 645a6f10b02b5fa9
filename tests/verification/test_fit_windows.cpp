// Windows of a measured curve (`[[fit.data]] window`, issue 24): the rows outside a window leave the residual but
// still drive the model. A viscoelastic force depends on the whole depth history, so a fit of a window that starts
// after the contact, or that leaves out the peak, recovers the material only with that history. Data from the
// independent Lee-Radok quadrature of tests/support/reference, never from mdr.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "mdr/fit/fit.hpp"
#include "mdr/fit/plausibility.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "reference/closed_forms.hpp"
#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/prony_material.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-3;      // sphere radius [m]
constexpr double depth = 2e-5;  // held depth [m]; the peak force is ~0.04 N
constexpr double noise = 4e-6;  // force noise [N], 1e-4 of the peak

// A ramp to 1 s and a hold to 3 s, 601 rows, the force of a standard solid (G_inf 1 MPa, G1 2 MPa, tau1 0.5 s)
// by Lee-Radok quadrature plus white noise (fixed seed).
fit::Curve ramp_hold() {
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const reference::PiecewiseLinear history{{0.0, 1.0, 3.0}, {0.0, depth, depth}};
    std::mt19937_64 random(3);
    std::normal_distribution<double> gaussian(0.0, noise);
    fit::Curve curve;
    curve.name = "ramp-hold";
    for (std::size_t i = 0; i <= 600; ++i) {
        const double t = 0.005 * static_cast<double>(i);
        curve.time.push_back(t);
        curve.depth.push_back(history.value(t));
        curve.force.push_back(reference::lee_radok_force(reference::sphere_indenter(R), truth, history, t) +
                              gaussian(random));
    }
    curve.force_noise = noise;
    return curve;
}

// The standard solid on a sphere, contact point and baseline known, started 30-50 % off.
fit::FitResult fit_window(const fit::RowSelection& window) {
    fit::Curve curve = ramp_hold();
    fit::select_rows(curve, window);
    fit::FitProblem problem;
    problem.model = [](const std::vector<double>& values) {
        return drivers::ContactCase{.title = "fit model",
                                    .material = rheology::Rheology::standard(values[0], values[1], values[2]),
                                    .indenter = profile::make_sphere(R),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    problem.parameters = {{"material.G_inf", 1.5e6, 1e3, 1e9}, {"material.G1", 1.4e6, 1e3, 1e9},
                          {"material.tau1", 0.7, 1e-3, 1e3}};
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    fit::FitResult result = fit::fit(problem);
    fit::add_plausibility_flags(problem, {}, result);
    return result;
}

void expect_truth(const fit::FitResult& result, std::size_t rows_fitted) {
    ASSERT_TRUE(result.converged) << result.status;
    EXPECT_FALSE(result.misfit) << result.curves[0].rms_residual / noise;
    EXPECT_EQ(result.curves[0].time.size(), rows_fitted);
    // The record's indentation (20 um on a 1 mm sphere) is plausible: the plausibility flags see the whole record,
    // not only the rows fitted (the hold alone spans no depth: once "largest indentation 0 m").
    for (const auto& flag : result.curves[0].flags) {
        EXPECT_EQ(flag.find("largest indentation"), std::string::npos) << flag;
    }
    const std::array<double, 3> truth{1e6, 2e6, 0.5};
    for (std::size_t j = 0; j < 3; ++j) {
        EXPECT_NEAR(result.values[j], truth[j], 4.0 * result.standard_errors[j]) << result.names[j];
        EXPECT_NEAR(result.values[j], truth[j], 0.01 * truth[j]) << result.names[j];
    }
}

TEST(FitWindows, ATimeWindowOfTheHoldKeepsTheRampAsItsHistory) {
    // Only the hold from 1.5 s is fitted (301 rows). Once the window's rows were the whole record: the model started
    // at rest at 1.5 s under the full depth, a step, and the fit could not follow the relaxation.
    expect_truth(fit_window({.time = std::array<double, 2>{1.5, 3.0}}), 301);
}

TEST(FitWindows, AForceWindowThatLeavesOutThePeakKeepsItAsHistory) {
    // The rows above 60 % of the peak force (the top of the ramp and the start of the hold) are left out; the model
    // still runs through them. Once the depth was joined across the gap by a straight line.
    const fit::Curve all = ramp_hold();
    double peak = 0.0;
    for (double force : all.force) peak = std::max(peak, force);
    std::size_t below = 0;
    for (double force : all.force) below += force <= 0.6 * peak;
    ASSERT_LT(below, all.force.size() - 100);  // the window leaves out a substantial part of the record
    expect_truth(fit_window({.force = std::array<double, 2>{-1.0, 0.6 * peak}}), below);
}

}  // namespace
}  // namespace mdr
