// The Jacobian of a curve's residuals: columns of moduli parameters from the continuum model's own derivatives
// (dF/dG_b with the parameter-to-moduli map), the others by forward differences, against central differences of
// the residuals themselves, on a load-hold-unload of a standard solid (the edge moves with the moduli on unloading);
// and that a point evaluated twice (Ceres' candidate, then its Jacobian there) runs the model once; and that the curve
// given to the solver in row blocks (CurveRowsCost) gives the whole curve's residuals and Jacobian with its runs.

#include "fit/curve_cost.hpp"
#include "fit/curve_rows_cost.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>

#include "mdr/profile/profile.hpp"

namespace mdr::fit {
namespace {

// A standard solid pressed by a sphere along the depth of a load-hold-unload (0.01 s per point), `dip` below the
// loading's line at t = 0.5 (a dip takes the history out of Ting's class: the element model runs it).
FitProblem load_hold_unload(double dip) {
    FitProblem problem;
    problem.model = [](const std::vector<double>& v) {
        return drivers::ContactCase{.title = "standard solid",
                                    .material = rheology::Rheology::standard(v[0], v[1], v[2]),
                                    .indenter = profile::make_sphere(1e-3),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    problem.parameters = {{"material.G_inf", 1e6, 1e3, 1e9}, {"material.G1", 2e6, 1e3, 1e9},
                          {"material.tau1", 0.3, 1e-3, 1e3}};
    Curve curve;
    curve.name = "load-hold-unload";
    for (int i = 0; i <= 200; ++i) {
        const double t = -0.1 + 0.01 * i;
        curve.time.push_back(t);
        curve.depth.push_back((t < 1.0 ? 1e-5 * t : t < 1.3 ? 1e-5 : 1e-5 * (2.3 - t)) - (i == 60 ? dip : 0.0));
        curve.force.push_back(0.0);
    }
    curve.force_noise = 1e-4;
    problem.curves = {curve};
    problem.settings.contact_point = ContactPointMode::fixed;
    problem.settings.baseline = BaselineMode::fixed;
    return problem;
}

TEST(CurveCost, ModulusColumnsAgreeWithDifferencesOfTheResiduals) {
    const FitProblem problem = load_hold_unload(0.0);
    const ParameterScales scales = make_scales(problem);
    const CurveModel prepared = prepare_curve(problem.curves[0], Fitted::force, 0.0);
    std::atomic<std::size_t> runs{0}, element_runs{0};
    const CurveCost cost(problem, scales, prepared, 0, 500, runs, element_runs);

    std::vector<double> u;
    for (std::size_t j = 0; j < 3; ++j) u.push_back(scales.to_internal(j, problem.parameters[j].start));
    const std::size_t n = prepared.used.size();
    std::vector<double> residuals(n), jacobian(n * 3);
    const double* parameters[1] = {u.data()};
    double* blocks[1] = {jacobian.data()};
    ASSERT_TRUE(cost.Evaluate(parameters, residuals.data(), blocks));
    EXPECT_EQ(element_runs, 0u);
    EXPECT_EQ(runs, 2u);  // the point and the time's column: the two moduli's columns need no run
    for (std::size_t j = 0; j < 3; ++j) {
        const double h = 1e-5;
        std::vector<double> up = u, down = u, r_up(n), r_down(n);
        up[j] += h;
        down[j] -= h;
        const double* at_up[1] = {up.data()};
        const double* at_down[1] = {down.data()};
        ASSERT_TRUE(cost.Evaluate(at_up, r_up.data(), nullptr));
        ASSERT_TRUE(cost.Evaluate(at_down, r_down.data(), nullptr));
        double largest = 0.0;
        for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, std::abs(jacobian[i * 3 + j]));
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_NEAR(jacobian[i * 3 + j], (r_up[i] - r_down[i]) / (2.0 * h), 1e-5 * largest)
                << "column " << j << ", row " << i;
        }
    }
}

// Ceres evaluates a candidate's residuals and, once it accepts it, the Jacobian at the same point: the point's run is
// kept, so the Jacobian costs one run per difference column only; the same residuals come back.
TEST(CurveCost, APointEvaluatedTwiceRunsOnce) {
    for (const double dip : {0.0, 2e-7}) {
        const FitProblem problem = load_hold_unload(dip);
        const ParameterScales scales = make_scales(problem);
        const CurveModel prepared = prepare_curve(problem.curves[0], Fitted::force, 0.0);
        std::atomic<std::size_t> runs{0}, element_runs{0};
        const CurveCost cost(problem, scales, prepared, 0, 500, runs, element_runs);
        std::vector<double> u;
        for (std::size_t j = 0; j < 3; ++j) u.push_back(scales.to_internal(j, problem.parameters[j].start));
        const std::size_t n = prepared.used.size();
        std::vector<double> first(n), second(n), jacobian(n * 3);
        const double* parameters[1] = {u.data()};
        double* blocks[1] = {jacobian.data()};
        ASSERT_TRUE(cost.Evaluate(parameters, first.data(), nullptr));
        EXPECT_EQ(runs, 1u) << "dip " << dip;
        ASSERT_TRUE(cost.Evaluate(parameters, second.data(), blocks));
        // Continuum (no dip): the time's column only, the moduli's columns need no run. Elements (the dip): the
        // time's and one modulus's columns (the other by Euler's identity).
        EXPECT_EQ(runs, dip == 0.0 ? 2u : 3u) << "dip " << dip;
        EXPECT_EQ(element_runs, dip == 0.0 ? 0u : 3u) << "dip " << dip;
        EXPECT_EQ(first, second) << "dip " << dip;
    }
}

// A depth-driven element run (the dip): the force is homogeneous of degree 1 in the moduli, so sum_b G_b dF/dG_b = F
// gives the column of the largest modulus (G1) without a run; every column against central differences of the
// residuals. The columns of G_inf and tau1 are forward differences, 2 runs; before Euler's identity it was 3.
TEST(CurveCost, EulerColumnOfDepthDrivenElementRuns) {
    const FitProblem problem = load_hold_unload(2e-7);
    const ParameterScales scales = make_scales(problem);
    const CurveModel prepared = prepare_curve(problem.curves[0], Fitted::force, 0.0);
    std::atomic<std::size_t> runs{0}, element_runs{0};
    const CurveCost cost(problem, scales, prepared, 0, 500, runs, element_runs);
    std::vector<double> u;
    for (std::size_t j = 0; j < 3; ++j) u.push_back(scales.to_internal(j, problem.parameters[j].start));
    const std::size_t n = prepared.used.size();
    std::vector<double> residuals(n), jacobian(n * 3);
    const double* parameters[1] = {u.data()};
    double* blocks[1] = {jacobian.data()};
    ASSERT_TRUE(cost.Evaluate(parameters, residuals.data(), blocks));
    EXPECT_EQ(element_runs, 3u);
    for (std::size_t j = 0; j < 3; ++j) {
        const double h = 1e-5;
        std::vector<double> up = u, down = u, r_up(n), r_down(n);
        up[j] += h;
        down[j] -= h;
        const double* at_up[1] = {up.data()};
        const double* at_down[1] = {down.data()};
        ASSERT_TRUE(cost.Evaluate(at_up, r_up.data(), nullptr));
        ASSERT_TRUE(cost.Evaluate(at_down, r_down.data(), nullptr));
        double largest = 0.0;
        for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, std::abs(jacobian[i * 3 + j]));
        ASSERT_GT(largest, 0.0);
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_NEAR(jacobian[i * 3 + j], (r_up[i] - r_down[i]) / (2.0 * h), 1e-5 * largest)
                << "column " << j << ", row " << i;
        }
    }
}

// A long curve goes to Ceres in row blocks (issue 23, memory of a large fit): the blocks' residuals and Jacobian rows
// are the whole curve's, bit for bit, and the Jacobian costs the runs of the whole curve's (not one set per block).
TEST(CurveRowsCost, BlocksGiveTheWholeCurvesRowsWithItsRuns) {
    for (const double dip : {0.0, 2e-7}) {  // the continuum model's derivative columns; the elements' Euler column
        const FitProblem problem = load_hold_unload(dip);
        const ParameterScales scales = make_scales(problem);
        const CurveModel prepared = prepare_curve(problem.curves[0], Fitted::force, 0.0);
        std::vector<double> u;
        for (std::size_t j = 0; j < 3; ++j) u.push_back(scales.to_internal(j, problem.parameters[j].start));
        const double* parameters[1] = {u.data()};
        const std::size_t n = prepared.used.size();

        std::atomic<std::size_t> whole_runs{0}, whole_element_runs{0};
        const CurveCost whole(problem, scales, prepared, 0, 500, whole_runs, whole_element_runs);
        std::vector<double> residuals(n), jacobian(n * 3);
        double* whole_blocks[1] = {jacobian.data()};
        ASSERT_TRUE(whole.Evaluate(parameters, residuals.data(), whole_blocks));

        std::atomic<std::size_t> runs{0}, element_runs{0};
        const CurveCost curve(problem, scales, prepared, 0, 500, runs, element_runs);
        const std::size_t rows = 64;  // blocks of 64 rows and a shorter last one
        ASSERT_GT(n, 2 * rows);
        std::vector<std::unique_ptr<CurveRowsCost>> blocks;
        for (std::size_t begin = 0; begin < n; begin += rows) {
            blocks.push_back(std::make_unique<CurveRowsCost>(curve, begin, std::min(begin + rows, n)));
        }
        std::vector<double> block_residuals(n), block_jacobian(n * 3);
        for (std::size_t b = 0; b < blocks.size(); ++b) {  // a candidate's residuals, then the Jacobian there
            ASSERT_TRUE(blocks[b]->Evaluate(parameters, block_residuals.data() + b * rows, nullptr));
        }
        for (std::size_t b = 0; b < blocks.size(); ++b) {
            double* rows_jacobian[1] = {block_jacobian.data() + b * rows * 3};
            ASSERT_TRUE(blocks[b]->Evaluate(parameters, block_residuals.data() + b * rows, rows_jacobian));
        }
        EXPECT_EQ(block_residuals, residuals) << "dip " << dip;
        EXPECT_EQ(block_jacobian, jacobian) << "dip " << dip;
        EXPECT_EQ(runs, whole_runs) << "dip " << dip;
        EXPECT_EQ(element_runs, whole_element_runs) << "dip " << dip;
    }
}

}  // namespace
}  // namespace mdr::fit
