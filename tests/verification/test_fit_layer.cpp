// Fits on a layer (docs/theory.md, "Fits on a layer"): the thickness and the moduli recovered from the closed form of
// the uniform-kernel model (eq. L7) at small depth, and from curves of the layer
// driver (drivers::run_layer_indentation: the layer solved at every step, verified against a direct Lee-Radok
// quadrature and scipy's layer solution in test_layer_viscoelastic.cpp and test_layer_contact.cpp), not from the
// fit's own interpolated model; and a force-driven fit, which runs the layer's cells.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>
#include <utility>

#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr {
namespace {

constexpr double thickness = 2e-6;

std::string layer_case(const std::string& interface) {
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
history = [[0.0, 0.0], [1.0, 1.5e-6], [3.0, 1.5e-6]]
[numerics]
time_step = 1.5e-3
[layer]
thickness = 2.0e-6
interface = ")" + interface + "\"\n";
}

// A 2001-point ramp-hold on the layer from the driver.
fit::Curve driver_curve(const drivers::ContactCase& truth) {
    const auto result = drivers::run_case(truth);
    fit::Curve curve;
    curve.name = "layer ramp-hold";
    curve.time = result.time;
    curve.depth = result.depth;
    curve.force = result.force;
    return curve;
}

// values = (G_inf, G1, tau1, h): the truth's case with them.
fit::FitProblem layer_problem(const drivers::ContactCase& truth, fit::Curve curve, std::vector<double> start) {
    fit::FitProblem problem;
    problem.model = [truth](const std::vector<double>& values) {
        auto model = truth;
        model.material = rheology::Rheology::standard(values[0], values[1], values[2]);
        model.bodies.reset();  // the material replaced is no body's (drivers::validate)
        model.layer->thickness = values[3];
        return model;
    };
    problem.parameters = {{"material.G_inf", start[0], 1.0, 1e6},
                          {"material.G1", start[1], 1.0, 1e6},
                          {"material.tau1", start[2], 1e-3, 1e3},
                          {"layer.thickness", start[3], 1e-7, 1e-4}};
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    return problem;
}

TEST(FitLayer, ThicknessAndModuliFromARampHold) {
    // Half-space contact radius up to 1.9 thicknesses (the layer's: 3.0). The model's only difference to the driver
    // is its interpolation (below 1e-7 here): the values come back to 1e-6.
    for (const std::string interface : {"bonded", "sliding"}) {
        const auto truth = io::parse_case(layer_case(interface));
        auto curve = driver_curve(truth);
        ASSERT_GE(curve.time.size(), 2000u);
        const auto result = fit::fit(layer_problem(truth, std::move(curve), {3e3, 1e3, 1.0, 5e-6}));
        ASSERT_TRUE(result.converged) << interface << ": " << result.status;
        const std::vector<double> expected{1e3, 3e3, 0.2, thickness};
        for (std::size_t j = 0; j < expected.size(); ++j) {
            EXPECT_NEAR(result.values[j] / expected[j], 1.0, 1e-6) << interface << " " << result.names[j];
        }
        EXPECT_EQ(result.element_evaluations, 0u);
        RecordProperty(interface + "_wall_seconds", std::to_string(result.wall_seconds));
        std::cout << interface << ": " << result.evaluations << " runs, " << result.iterations << " iterations, "
                  << result.wall_seconds << " s\n";
    }
}

TEST(FitLayer, AFixedThicknessIsTheModelsLayer) {
    // The half-space model on the layer's data misses by the layer's effect; the layer model with the true
    // thickness fixed recovers the moduli.
    const auto truth = io::parse_case(layer_case("bonded"));
    const auto curve = driver_curve(truth);
    auto problem = layer_problem(truth, curve, {3e3, 1e3, 1.0, thickness});
    problem.parameters.pop_back();
    const auto base = problem.model;
    problem.model = [base](const std::vector<double>& values) {
        return base({values[0], values[1], values[2], thickness});
    };
    const auto result = fit::fit(problem);
    ASSERT_TRUE(result.converged) << result.status;
    EXPECT_NEAR(result.values[0] / 1e3, 1.0, 1e-6);
    EXPECT_NEAR(result.values[1] / 3e3, 1.0, 1e-6);
    problem.model = [base](const std::vector<double>& values) {
        auto model = base({values[0], values[1], values[2], thickness});
        model.layer.reset();
        return model;
    };
    const auto half_space = fit::fit(problem);
    EXPECT_GT(half_space.values[0] / 1e3, 1.5);  // the bottom effect: the half-space overestimates the modulus
}

// The relative errors of G and h fitted to a 2001-point elastic curve of eq. L7 up to chi_max: F = (16/3) G sqrt(R)
// d^(3/2) y^(3/2), y = 1 + (2/3) e y^(3/2), e = (2 k(0)/pi) sqrt(R d)/h, k(0) = 1.770216773 (scipy), a model exact to
// O(chi^2) and independent of mdr's layer solver (test_layer_contact.cpp checks the solver against it).
std::pair<double, double> uniform_kernel_recovery(double chi_max) {
    constexpr double G = 1e3, R = 1e-5, h = 1e-5, k0 = 1.770216773;
    const double largest_depth = chi_max * chi_max * h * h / R;
    fit::Curve curve;
    curve.name = "L7";
    for (std::size_t i = 0; i <= 2000; ++i) {
        const double d = largest_depth * static_cast<double>(i) / 2000.0;
        const double e = 2.0 * k0 / std::numbers::pi * std::sqrt(R * d) / h;
        double y = 1.0;
        for (int iteration = 0; iteration < 200; ++iteration) y = 1.0 + 2.0 / 3.0 * e * std::pow(y, 1.5);
        curve.time.push_back(1e-3 * static_cast<double>(i));
        curve.depth.push_back(d);
        curve.force.push_back(16.0 / 3.0 * G * std::sqrt(R) * std::pow(d, 1.5) * std::pow(y, 1.5));
    }
    fit::FitProblem problem;
    problem.model = [](const std::vector<double>& values) {
        auto model = io::parse_case(layer_case("bonded"));
        model.material = rheology::Rheology::elastic(values[0]);
        model.bodies.reset();  // the material replaced is no body's (drivers::validate)
        model.indenter = profile::make_sphere(R);
        model.layer->thickness = values[1];
        return model;
    };
    problem.parameters = {{"material.G", 3e3, 1.0, 1e6}, {"layer.thickness", 3e-6, 1e-7, 1e-3}};
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    const auto result = fit::fit(problem);
    EXPECT_TRUE(result.converged) << result.status;
    return {result.values[0] / G - 1.0, result.values[1] / h - 1.0};
}

TEST(FitLayer, ElasticLayerFromTheUniformKernelModelAtSmallDepth) {
    // The fit of G and h (from 3x and 0.3x off) is off by the data's own model error alone: O(chi^3) in the force, so
    // O(chi^3) in G and O(chi^2) in h (the bottom effect is O(chi)). Measured: G -8.2e-4, h -1.2 % at chi = 0.1 (an
    // 11 % bottom effect); -9.5e-5 and -0.30 % at 0.05: ratios 8.7 and 4.1.
    const auto [g_coarse, h_coarse] = uniform_kernel_recovery(0.1);
    const auto [g_fine, h_fine] = uniform_kernel_recovery(0.05);
    EXPECT_LT(std::abs(g_coarse), 1.5e-3);
    EXPECT_LT(std::abs(h_coarse), 2e-2);
    EXPECT_GT(g_coarse / g_fine, 6.0);
    EXPECT_LT(g_coarse / g_fine, 11.0);
    EXPECT_GT(h_coarse / h_fine, 3.0);
    EXPECT_LT(h_coarse / h_fine, 5.0);
}

bool has_thickness_flag(const fit::FitResult& result) {
    for (const auto& flag : result.curves.front().flags) {
        if (flag.find("the layer's thickness") != std::string::npos) return true;
    }
    return false;
}

TEST(FitLayer, ADepthThatReachesTheThicknessIsFlagged) {
    // The ramp-hold reaches d = 1.5 um: on a layer of 2 um no flag; fitted with a fixed thickness of 1.2 um, the
    // curve is flagged (a layer on a rigid substrate cannot be indented through).
    const auto truth = io::parse_case(layer_case("bonded"));
    const auto curve = driver_curve(truth);
    for (const double thickness_fixed : {2e-6, 1.2e-6}) {
        auto problem = layer_problem(truth, curve, {1e3, 3e3, 0.2, thickness_fixed});
        problem.parameters.resize(2);
        const auto base = problem.model;
        problem.model = [base, thickness_fixed](const std::vector<double>& values) {
            return base({values[0], values[1], 0.2, thickness_fixed});
        };
        EXPECT_EQ(has_thickness_flag(fit::fit(problem)), thickness_fixed < 1.5e-6) << thickness_fixed;
    }
}

TEST(FitLayer, CompressibleElasticLayerAndItsYoungsModulus) {
    // G free beside a fixed elastic K = 2e3: nu = (3K - 2G) / (2 (3K + G)) moves with G, and with it the kernel. The
    // data: F = E* F_1(d) of the elastic layer solved at each depth (contact::LayerContact, E* = 2G/(1 - nu), nu =
    // 4/14 at G = 1e3), not the fit's interpolated model. The reported E = 2 (1 + nu) G = 9 K G / (3K + G), with its
    // error through nu's dependence on G.
    constexpr double G = 1e3, K = 2e3, nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G)), R = 1e-5;
    const auto text = [](double shear_modulus) {
        char material[128];
        std::snprintf(material, sizeof material, "model = \"elastic\"\nG = %.17g\nK = %.17g\n", shear_modulus, K);
        return "[material]\n" + std::string(material) +
               "[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n[load]\ncontrol = \"displacement\"\n"
               "history = [[0.0, 0.0], [1.0, 1.5e-6]]\n[layer]\nthickness = 2.0e-6\ninterface = \"bonded\"\n";
    };
    const contact::LayerContact layer({thickness, contact::LayerInterface::bonded}, nu, profile::make_sphere(R), 1e-5);
    fit::Curve curve;
    curve.name = "compressible";
    double radius = 0.0;
    for (std::size_t i = 0; i <= 200; ++i) {
        const double d = 1.5e-6 * static_cast<double>(i) / 200.0;
        const auto state = layer.at_depth(d, radius);
        radius = state.contact_radius;
        curve.time.push_back(5e-3 * static_cast<double>(i));
        curve.depth.push_back(d);
        curve.force.push_back(2.0 * G / (1.0 - nu) * state.force);
    }
    fit::FitProblem problem;
    problem.model = [text](const std::vector<double>& values) { return io::parse_case(text(values[0])); };
    problem.parameters = {{"material.G", 3e3, 1.0, 1e6}};
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    const auto result = fit::fit(problem);
    ASSERT_TRUE(result.converged) << result.status;
    EXPECT_NEAR(result.values[0] / G, 1.0, 1e-6);
    ASSERT_EQ(result.young_moduli.size(), 1u);
    EXPECT_NEAR(result.young_moduli[0].value / (9.0 * K * G / (3.0 * K + G)), 1.0, 1e-6);
    // Its error through dE/dG = 27 K^2 / (3K + G)^2 (nu moves with G), not 2 (1 + nu) (nu held).
    const double slope = 27.0 * K * K / ((3.0 * K + G) * (3.0 * K + G));
    EXPECT_NEAR(result.young_moduli[0].standard_error / (slope * result.standard_errors[0]), 1.0, 1e-4);
}

TEST(FitLayer, AForceDrivenCurveFitsTheDepthOnCells) {
    // The driver's ramp-hold (Lee-Radok on the layer, exact in time and to ~1e-8 in space) fitted with the depth as
    // the fitted quantity: the fit runs the measured force through the layer's cells under force control (eq. L16 to
    // L19, second order in the cell). Before issue 28's force-driven layer fits it was refused naming fit.fitted.
    // Observed at 400 cells (the default): -1.7e-4, 3.5e-4, -4.9e-4 from starts 2x, 1.5x, 2x off (98 runs, 9 s).
    const auto truth = io::parse_case(layer_case("bonded"));
    auto problem = layer_problem(truth, driver_curve(truth), {2e3, 2e3, 0.4, thickness});
    problem.parameters.pop_back();  // the thickness fixed
    problem.model = [truth](const std::vector<double>& values) {
        auto model = truth;
        model.material = rheology::Rheology::standard(values[0], values[1], values[2]);
        model.bodies.reset();  // the material replaced is no body's (drivers::validate)
        return model;
    };
    problem.settings.fitted = fit::Fitted::depth;
    const auto result = fit::fit(problem);
    ASSERT_TRUE(result.converged) << result.status;
    EXPECT_NEAR(result.values[0] / 1e3, 1.0, 1e-3);
    EXPECT_NEAR(result.values[1] / 3e3, 1.0, 1e-3);
    EXPECT_NEAR(result.values[2] / 0.2, 1.0, 1e-3);
}

}  // namespace
}  // namespace mdr
