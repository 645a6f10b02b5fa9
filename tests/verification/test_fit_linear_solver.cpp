// The linear solver of the fit's Levenberg-Marquardt steps (fit::LinearSolver). The default solves the normal
// equations J^T J, which square the condition number of the Jacobian J; a QR of J does not. On an ill-conditioned
// fit -- a three-term Prony series with close relaxation times, its parameters strongly correlated -- both must
// reach the same optimum with the same standard errors. The data come from the Lee-Radok quadrature of
// tests/support/reference (independent of mdr) with Gaussian force noise.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "mdr/fit/fit.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "reference/closed_forms.hpp"
#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-3;      // sphere radius [m]
constexpr double depth = 2e-5;  // peak depth [m]

// Load-hold of a sphere: the depth ramps to `depth` in 1 s and holds to 4 s; the force by Lee-Radok quadrature
// (handbook eq. 34 for a monotone depth) plus Gaussian noise.
fit::Curve noisy_load_hold(const reference::PronyMaterial& material, double noise, unsigned seed) {
    const reference::PiecewiseLinear history{{0.0, 1.0, 4.0}, {0.0, depth, depth}};
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gaussian(0.0, noise);
    fit::Curve curve;
    curve.name = "load-hold";
    for (std::size_t i = 0; i <= 400; ++i) {
        const double t = 0.01 * static_cast<double>(i);
        curve.time.push_back(t);
        curve.depth.push_back(history.value(t));
        curve.force.push_back(reference::lee_radok_force(reference::sphere_indenter(R), material, history, t) +
                              gaussian(random));
    }
    curve.force_noise = noise;
    return curve;
}

fit::FitProblem three_term_problem(fit::Curve curve) {
    fit::FitProblem problem;
    problem.model = [](const std::vector<double>& v) {
        return drivers::ContactCase{
            .title = "fit model",
            .material = rheology::Rheology::prony(v[0], {{v[1], v[2]}, {v[3], v[4]}, {v[5], v[6]}}),
            .indenter = profile::make_sphere(R),
            .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
            .end_time = 1.0};
    };
    problem.parameters = {{"material.G_inf", 1.1e6, 1e3, 1e9},       {"material.terms[0][0]", 0.9e6, 1e3, 1e9},
                          {"material.terms[0][1]", 0.22, 1e-3, 1e3}, {"material.terms[1][0]", 1.1e6, 1e3, 1e9},
                          {"material.terms[1][1]", 0.33, 1e-3, 1e3}, {"material.terms[2][0]", 0.9e6, 1e3, 1e9},
                          {"material.terms[2][1]", 0.65, 1e-3, 1e3}};
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    problem.settings.elements = 500;
    return problem;
}

TEST(FitLinearSolver, NormalEquationsAgreeWithQrOnAnIllConditionedPronyFit) {
    // Relaxation times within a factor 1.5 of each other: G(t) of the three branches is nearly one exponential.
    const reference::PronyMaterial truth{1e6, 0.0, {{1e6, 0.2}, {1e6, 0.3}, {1e6, 0.45}}};
    const double noise = 1e-5;  // the peak force is ~0.1 N
    auto problem = three_term_problem(noisy_load_hold(truth, noise, 11));
    problem.settings.linear_solver = fit::LinearSolver::qr;
    const auto qr = fit::fit(problem);
    problem.settings.linear_solver = fit::LinearSolver::normal_equations;
    const auto normal = fit::fit(problem);
    ASSERT_TRUE(qr.converged) << qr.status;
    ASSERT_TRUE(normal.converged) << normal.status;  // the Cholesky of J^T J did not fail

    // The problem is ill-conditioned: some pair of parameters is correlated beyond 0.99.
    double strongest = 0.0;
    for (std::size_t a = 0; a < qr.values.size(); ++a) {
        for (std::size_t b = 0; b < a; ++b) strongest = std::max(strongest, std::abs(qr.correlation[a][b]));
    }
    EXPECT_GT(strongest, 0.99);

    // The same optimum to 1e-5 of a standard error (far below what the data determine) and the same standard errors
    // to 1e-4 relative (measured: 1e-7 and 1.4e-6, with a correlation of 0.99998 and 182 iterations).
    ASSERT_EQ(normal.values.size(), qr.values.size());
    for (std::size_t j = 0; j < qr.values.size(); ++j) {
        ASSERT_TRUE(std::isfinite(qr.standard_errors[j])) << qr.names[j];
        EXPECT_NEAR(normal.values[j], qr.values[j], 1e-5 * qr.standard_errors[j]) << qr.names[j];
        EXPECT_NEAR(normal.standard_errors[j] / qr.standard_errors[j], 1.0, 1e-4) << qr.names[j];
    }
}

}  // namespace
}  // namespace mdr
