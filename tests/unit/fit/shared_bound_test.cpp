// A material's parameter that the data push beyond its bound is held there (src/fit/active_bounds.cpp: the shared
// parameters join the active set beside the contact points). The data are the closed-form force of a Kelvin-Voigt
// half-space (G(t) = G + eta delta(t), incompressible) under a sphere pressed at constant speed, by the Lee-Radok
// hereditary integral of Hertz's force (Johnson, Contact Mechanics, eq. 4.22 with E* = 4G; Lee & Radok 1960):
// F(t) = 16/3 sqrt(R) (G d^1.5 + eta d(d^1.5)/dt), d = v t, plus Gaussian noise of known deviation (fixed seed).

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::fit {
namespace {

constexpr double radius = 5e-6;  // R [m]
constexpr double speed = 2e-6;   // v [m/s]
constexpr double modulus = 2e3;  // G [Pa], the truth
constexpr double viscosity = 4e2;  // eta [Pa s], the truth
constexpr double sigma = 1e-11;  // force noise [N] (the peak force is 7e-8 N)
constexpr double bound = 1.5e3;  // G's upper bound, below the truth [Pa]

// The two terms of the force per unit modulus and viscosity at depth d = v t: F = G a(d) + eta b(d).
double hertz_term(double d) { return 16.0 / 3.0 * std::sqrt(radius) * std::pow(d, 1.5); }
double viscous_term(double d) { return 16.0 / 3.0 * std::sqrt(radius) * 1.5 * speed * std::sqrt(d); }

Curve ramp() {
    std::mt19937_64 random(5);
    std::normal_distribution<double> normal(0.0, sigma);
    Curve curve;
    curve.name = "ramp";
    for (std::size_t i = 0; i <= 200; ++i) {
        const double t = 0.005 * static_cast<double>(i);
        curve.time.push_back(t);
        curve.depth.push_back(speed * t);
        curve.force.push_back(modulus * hertz_term(speed * t) + viscosity * viscous_term(speed * t) + normal(random));
    }
    curve.force_noise = sigma;
    return curve;
}

// The Kelvin-Voigt sphere; `modulus_fixed` set: G is that and values = (eta), else values = (G, eta) with G in
// [10, `upper`] from `start`.
FitProblem kelvin_voigt_problem(std::optional<double> modulus_fixed, double upper = bound, double start = 1e3,
                                double viscosity_start = 1e2) {
    FitProblem problem;
    problem.model = [modulus_fixed](const std::vector<double>& values) {
        const double G = modulus_fixed ? *modulus_fixed : values[0];
        const double eta = values.back();
        return drivers::ContactCase{.title = "kelvin-voigt",
                                    .material = rheology::Rheology::kelvin_voigt(G, eta),
                                    .indenter = profile::make_sphere(radius),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    if (!modulus_fixed) problem.parameters.push_back({"material.G", start, 1e1, upper});
    problem.parameters.push_back({"material.eta", viscosity_start, 1.0, 1e5});
    problem.curves = {ramp()};
    problem.settings.contact_point = ContactPointMode::fixed;
    problem.settings.baseline = BaselineMode::fixed;
    problem.settings.elements = 400;
    return problem;
}

// The truth lies beyond G's upper bound: the fit ends on the bound exactly, at the constrained minimum, which two
// independent ways give: the fit of eta alone with G fixed at the bound (the same model: to 1e-6 of eta and 1e-9 of
// the residual), and the closed form's normal equation for eta with G fixed, eta = sum (F - G a) b / sum b^2 (to
// 1e-3: the element model's discretisation). Before the shared parameters joined the active set (main at 4d24c41),
// Ceres' projected steps crawled along the bound and the statistical convergence stopped them short, "converged":
// 61 iterations and 253 runs, eta 1.9 % below the bounded minimum's and the residual RMS 1.2 % above it. Now G is
// held where that solve ends (Hold::at_the_end) and a second solve reaches the minimum: 63 iterations, 267 runs, eta
// within 2.3e-8. (Held once it crawled, as a contact point is, the fit took 12 iterations, but that rule ended
// three of the JPK record's candidates at higher minima: docs/performance.md, "A shared parameter on its bound".)
TEST(SharedBound, ParameterPushedBeyondItsBoundEndsHeldThereAtTheBoundedMinimum) {
    const FitResult result = fit(kelvin_voigt_problem(std::nullopt));
    ASSERT_TRUE(result.converged) << result.status;
    EXPECT_NEAR(result.values[0], bound, 1e-12 * bound);
    const FitResult fixed = fit(kelvin_voigt_problem(bound));
    ASSERT_TRUE(fixed.converged) << fixed.status;
    EXPECT_NEAR(result.values[1], fixed.values[0], 1e-6 * fixed.values[0]);
    EXPECT_NEAR(result.rms_residual, fixed.rms_residual, 1e-9 * fixed.rms_residual);

    const Curve curve = ramp();
    double sfb = 0.0, sbb = 0.0;
    for (std::size_t i = 0; i < curve.depth.size(); ++i) {
        const double b = viscous_term(curve.depth[i]);
        sfb += (curve.force[i] - bound * hertz_term(curve.depth[i])) * b;
        sbb += b * b;
    }
    EXPECT_NEAR(result.values[1], sfb / sbb, 1e-3 * sfb / sbb);

    // Held on its bound, it is still reported as at its bound.
    bool at_bound = false;
    for (const auto& undetermined : result.undetermined) {
        at_bound = at_bound || (undetermined.name == "material.G" && undetermined.reason.find("at its upper bound") !=
                                                                          std::string::npos);
    }
    EXPECT_TRUE(at_bound);
}

// G starts on an upper bound 10 % above the truth (2.2e3 Pa) with eta far below its own (1 Pa s): the force falls
// short and the cost pushes G beyond the bound while eta grows, for more than `patience` steps; with eta fitted, the
// cost pulls G inward, and the fit ends inside, at the minimum of a fit whose bound lies far away (1e5 Pa), to 1e-6.
// Held once it crawled (Hold::when_crawling) and never released, G ended at 2.2e3 Pa, "converged, misfit", eta
// 311 Pa s against 400 (checked with the release taken out); with Hold::at_the_end G is held only where a solve ends
// with it on the bound pushed outward, and here the fit ends inside.
TEST(SharedBound, ParameterOnItsBoundWhileTheCostPushesItOutwardEndsInsideWhereItsMinimumIs) {
    const FitResult result = fit(kelvin_voigt_problem(std::nullopt, 2.2e3, 2.2e3, 1.0));
    ASSERT_TRUE(result.converged) << result.status;
    const FitResult wide = fit(kelvin_voigt_problem(std::nullopt, 1e5));
    ASSERT_TRUE(wide.converged) << wide.status;
    EXPECT_LT(wide.values[0], 2.1e3);
    EXPECT_NEAR(result.values[0], wide.values[0], 1e-6 * wide.values[0]);
    EXPECT_NEAR(result.values[1], wide.values[1], 1e-6 * wide.values[1]);
    EXPECT_TRUE(result.undetermined.empty()) << result.undetermined.front().reason;
}

}  // namespace
}  // namespace mdr::fit
