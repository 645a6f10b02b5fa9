// A preloaded record on a layer (`[[fit.data]] start = "preloaded"` with a `[layer]`; docs/theory.md 4d, eq. L21):
// the moduli, the contact point (hence the preload depth d_0) and the thickness fitted back from a relaxation made by
// the layer driver (drivers::run_layer_indentation, the layer solved at every step; verified against a direct
// Lee-Radok quadrature and scipy's layer solution in test_layer_viscoelastic.cpp and test_layer_contact.cpp), not by
// the fit's interpolated model: the driver holds the depth d_0 for 40 relaxation times before the record starts, so
// the record begins under a relaxed preload. And for h -> inf the half-space's preloaded fit.

#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "mdr/drivers/indentation.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr {
namespace {

constexpr double thickness = 2e-6;  // m
constexpr double offset = 3e-6;     // the data's zero of depth lies 3 um above the surface: contact point -3 um

// A jump to d_0 = 0.4 um held to t = 8 s (40 tau1), then 0.4 -> 1.2 um over 1 s and a hold to 12 s, on a bonded
// layer h = 2 um under a sphere R = 10 um (its half-space contact radius at 1.2 um: 1.7 h).
std::string preloaded_case() {
    return R"(
[material]
model = "standard"
G_inf = 1.0e3
G1 = 3.0e3
tau1 = 0.2
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "displacement"
history = [[0.0, 0.0], [0.001, 0.4e-6], [8.0, 0.4e-6], [9.0, 1.2e-6], [12.0, 1.2e-6]]
[numerics]
time_step = 2.0e-3
[layer]
thickness = 2.0e-6
interface = "bonded"
)";
}

// The driver's rows from t = 7.5 s (a pause of 0.5 s at d_0, relaxed to exp(-37.5)), the depth shifted by the
// data's zero, the force as measured (the pause holds G_inf F_el(d_0): the baseline is that force, as
// `baseline = "constant"` takes it from a real record's pause).
fit::Curve preloaded_curve(const drivers::ContactCase& truth) {
    const auto result = drivers::run_case(truth);
    fit::Curve curve;
    curve.name = "preloaded relaxation";
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        if (result.time[i] < 7.5 - 1e-12) continue;
        curve.time.push_back(result.time[i]);
        curve.depth.push_back(result.depth[i] + offset);
        curve.force.push_back(result.force[i]);
    }
    curve.preloaded = true;
    curve.force_baseline = curve.force.front();
    curve.contact_depth = curve.depth.front();  // the estimate of a record that starts in contact: its first row
    return curve;
}

// values = (G_inf, G1, tau1[, h]): the truth's case with them; the thickness `fixed` when it is not free.
fit::FitProblem preloaded_problem(const drivers::ContactCase& truth, fit::Curve curve, bool thickness_free,
                                  double fixed = thickness) {
    fit::FitProblem problem;
    problem.model = [truth, fixed](const std::vector<double>& values) {
        auto model = truth;
        model.material = rheology::Rheology::standard(values[0], values[1], values[2]);
        if (values.size() > 3) {
            model.layer->thickness = values[3];
        } else {
            model.layer->thickness = fixed;
        }
        return model;
    };
    problem.parameters = {{"material.G_inf", 3e3, 1.0, 1e6}, {"material.G1", 1e3, 1.0, 1e6},
                          {"material.tau1", 1.0, 1e-3, 1e3}};
    if (thickness_free) problem.parameters.push_back({"layer.thickness", 5e-6, 1e-7, 1e-4});
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fit;
    problem.settings.baseline = fit::BaselineMode::estimate;
    return problem;
}

TEST(FitLayerPreload, ModuliPreloadAndThicknessFromAPreloadedRelaxation) {
    // The model meets the driver to its interpolation and the driver's contact solve (5.6e-9 of the peak,
    // LayerPreload.ARecedingContactFollowsTheDriverIntoThePreloadAndPastItsLoss): the values come back to 1e-5
    // (observed: h fixed 1.3e-8, the contact 3e-8 of d_0; h free 2.4e-6, h 1.0e-6, the contact 5e-7 of d_0).
    const auto truth = io::parse_case(preloaded_case());
    const auto curve = preloaded_curve(truth);
    for (const bool thickness_free : {false, true}) {
        const auto result = fit::fit(preloaded_problem(truth, curve, thickness_free));
        ASSERT_TRUE(result.converged) << thickness_free << ": " << result.status;
        std::vector<double> expected{1e3, 3e3, 0.2};
        if (thickness_free) expected.push_back(thickness);
        for (std::size_t j = 0; j < expected.size(); ++j) {
            EXPECT_NEAR(result.values[j] / expected[j], 1.0, 1e-5) << thickness_free << " " << result.names[j];
        }
        ASSERT_EQ(result.curves.size(), 1u);
        EXPECT_NEAR(result.curves[0].contact_depth, offset, 1e-5 * 0.4e-6) << thickness_free;
        EXPECT_EQ(result.element_evaluations, 0u);  // the layer model alone
    }
}

TEST(FitLayerPreload, AThickLayerIsTheHalfSpacesPreloadedFit) {
    // The half-space driver's preloaded relaxation (the same history without [layer]) fitted on the half-space
    // (tests/unit/fit/preload_test.cpp: its model against the closed form) and on a layer of 1 km: the same values
    // to 2e-6 (the kernel vanishes as h -> inf, eq. L4; the layer model's interpolation, eq. L15), the half-space's
    // the truth to 1e-4 (the half-space driver's elements).
    auto truth = io::parse_case(preloaded_case());
    truth.layer.reset();
    const auto curve = preloaded_curve(truth);
    auto with_layer = io::parse_case(preloaded_case());
    const auto on_layer = fit::fit(preloaded_problem(with_layer, curve, false, 1e3));
    auto half_space = preloaded_problem(with_layer, curve, false);
    const auto base = half_space.model;
    half_space.model = [base](const std::vector<double>& values) {
        auto model = base(values);
        model.layer.reset();
        return model;
    };
    const auto on_half_space = fit::fit(half_space);
    ASSERT_TRUE(on_layer.converged && on_half_space.converged) << on_layer.status << "; " << on_half_space.status;
    const std::vector<double> expected{1e3, 3e3, 0.2};
    for (std::size_t j = 0; j < expected.size(); ++j) {
        EXPECT_NEAR(on_layer.values[j] / on_half_space.values[j], 1.0, 2e-6) << on_layer.names[j];
        EXPECT_NEAR(on_half_space.values[j] / expected[j], 1.0, 1e-4) << on_layer.names[j];
    }
    EXPECT_NEAR(on_layer.curves[0].contact_depth, on_half_space.curves[0].contact_depth, 1e-5 * 0.4e-6);
}

}  // namespace
}  // namespace mdr
