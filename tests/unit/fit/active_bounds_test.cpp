// The active set of src/fit/active_bounds.cpp on linear least-squares problems whose bounded minima are known in
// closed form (the normal equations with the bounded coordinate fixed, and the Karush-Kuhn-Tucker sign), for a
// coordinate of a block that is the second of one cost (a curve's contact point) and for one of a block that many
// costs share (a material's parameter).

#include <gtest/gtest.h>

#include <ceres/loss_function.h>
#include <ceres/sized_cost_function.h>

#include <memory>
#include <vector>

#include "fit/active_bounds.hpp"
#include "fit/statistical_convergence.hpp"

namespace mdr::fit {
namespace {

// r0 = x - target, r1 = weight (y - x): blocks {y} and {x}, with their Jacobians.
class Chain : public ceres::SizedCostFunction<2, 1, 1> {
public:
    Chain(double target, double weight) : target_(target), weight_(weight) {}

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
        const double y = parameters[0][0];
        const double x = parameters[1][0];
        residuals[0] = x - target_;
        residuals[1] = weight_ * (y - x);
        if (jacobians != nullptr && jacobians[0] != nullptr) {
            jacobians[0][0] = 0.0;
            jacobians[0][1] = weight_;
        }
        if (jacobians != nullptr && jacobians[1] != nullptr) {
            jacobians[1][0] = 1.0;
            jacobians[1][1] = -weight_;
        }
        return true;
    }

private:
    double target_;
    double weight_;
};

struct ChainProblem {
    double y = 0.0;
    double x = 0.0;
    ceres::Problem problem;
    ceres::CostFunction* cost = nullptr;

    ChainProblem(double target, double weight, double x_start, double y_start) : y(y_start), x(x_start) {
        cost = new Chain(target, weight);
        problem.AddResidualBlock(cost, nullptr, &y, &x);
        problem.SetParameterLowerBound(&x, 0, 0.0);
        problem.SetParameterUpperBound(&x, 0, 5.0);
    }

    ActiveBoundsSolve solve(std::vector<BoundedCoordinate>& bounded) {
        ceres::Solver::Options options;
        options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
        options.line_search_interpolation_type = ceres::QUADRATIC;
        options.function_tolerance = options.parameter_tolerance = 1e-14;
        options.max_num_iterations = 100;
        options.logging_type = ceres::SILENT;
        return solve_with_active_bounds(options, problem, bounded,
                                        [] { return std::make_unique<StatisticalConvergence>(); });
    }
};

// d (1/2 |r|^2) / dx = r0 - weight r1, by hand.
TEST(ActiveBounds, CoordinateGradientOfASecondBlockIsTheCostsSlope) {
    ChainProblem chain(2.0, 3.0, 0.5, 1.5);
    const BoundedCoordinate coordinate{&chain.x, 1, 0, 0.0, 5.0};
    const double r0 = 0.5 - 2.0;
    const double r1 = 3.0 * (1.5 - 0.5);
    EXPECT_NEAR(coordinate_gradient(chain.problem, coordinate), r0 - 3.0 * r1, 1e-12);
}

// A coordinate held on its lower bound where the cost pulls it inside (slope -2 at x = 0, y = 0) is released: the
// minimum is the unbounded x = y = 2, reached in a second solve.
TEST(ActiveBounds, AHeldCoordinateTheCostPullsInsideIsReleased) {
    ChainProblem chain(2.0, 1.0, 0.0, 1.0);
    std::vector<BoundedCoordinate> bounded{{&chain.x, 1, 0, 0.0, 5.0, true}};
    const ActiveBoundsSolve solved = chain.solve(bounded);
    EXPECT_FALSE(bounded[0].held);
    EXPECT_EQ(solved.solves, 2u);
    EXPECT_NEAR(chain.x, 2.0, 1e-8);
    EXPECT_NEAR(chain.y, 2.0, 1e-8);
}

// The minimum beyond the lower bound (target -1): held at x = 0 exactly, y = 0 (the normal equations with x fixed),
// and the slope there pushes outward (1 > 0), so it stays held. Ceres alone (no coordinate in `bounded`) ends at
// y = -1.0e-3 after 36 iterations: its projected steps crawl and its function tolerance stops them short.
TEST(ActiveBounds, ACoordinateTheCostPushesOutwardEndsHeldOnItsBound) {
    ChainProblem chain(-1.0, 10.0, 3.0, 3.0);
    std::vector<BoundedCoordinate> bounded{{&chain.x, 1, 0, 0.0, 5.0}};
    const ActiveBoundsSolve solved = chain.solve(bounded);
    EXPECT_EQ(chain.x, 0.0);
    EXPECT_NEAR(chain.y, 0.0, 1e-8);
    EXPECT_GT(coordinate_gradient(chain.problem, bounded[0]), 0.0);
    EXPECT_EQ(solved.solves, 2u);
    EXPECT_TRUE(bounded[0].held);
}

// The same minimum beyond the bound for a coordinate held only where a solve ends on its bound (a material's
// parameter): Ceres' projected solve ends first, the coordinate is held there, and a second solve reaches y = 0.
TEST(ActiveBounds, ACoordinateHeldAtTheEndEndsHeldOnItsBoundAtTheBoundedMinimum) {
    ChainProblem chain(-1.0, 10.0, 3.0, 3.0);
    std::vector<BoundedCoordinate> bounded{{&chain.x, 1, 0, 0.0, 5.0, false, Hold::at_the_end}};
    const ActiveBoundsSolve solved = chain.solve(bounded);
    EXPECT_EQ(chain.x, 0.0);
    EXPECT_NEAR(chain.y, 0.0, 1e-8);
    EXPECT_EQ(solved.solves, 2u);
    EXPECT_TRUE(bounded[0].held);
}

// One residual r = sum_b coefficients[b] . p_b - target over blocks of the coefficients' sizes, with its Jacobian.
class Plane : public ceres::CostFunction {
public:
    Plane(std::vector<std::vector<double>> coefficients, double target)
        : coefficients_(std::move(coefficients)), target_(target) {
        set_num_residuals(1);
        for (const auto& block : coefficients_) {
            mutable_parameter_block_sizes()->push_back(static_cast<int>(block.size()));
        }
    }

    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
        residuals[0] = -target_;
        for (std::size_t b = 0; b < coefficients_.size(); ++b) {
            for (std::size_t i = 0; i < coefficients_[b].size(); ++i) {
                residuals[0] += coefficients_[b][i] * parameters[b][i];
                if (jacobians != nullptr && jacobians[b] != nullptr) jacobians[b][i] = coefficients_[b][i];
            }
        }
        return true;
    }

private:
    std::vector<std::vector<double>> coefficients_;
    double target_;
};

// A block y = (y0, y1) that four costs share, two of them with a block of their own (x1, x2), as a material's
// parameters and two curves' contact points: y0 - 1, y1 + x1 - 3, y1 - x2 - 1 and 2 y1 - 4, all 0 at the one
// minimum y = (1, 2), x1 = x2 = 1. y1 is bounded to [0, 5].
struct SharedProblem {
    std::vector<double> y{0.0, 0.0};
    double x1 = 0.0;
    double x2 = 0.0;
    ceres::Problem problem;

    explicit SharedProblem(ceres::LossFunction* last_loss = nullptr) {
        problem.AddResidualBlock(new Plane({{1.0, 0.0}, {0.0}}, 1.0), nullptr, y.data(), &x1);
        problem.AddResidualBlock(new Plane({{0.0, 1.0}, {1.0}}, 3.0), nullptr, y.data(), &x1);
        problem.AddResidualBlock(new Plane({{0.0, 1.0}, {-1.0}}, 1.0), nullptr, y.data(), &x2);
        problem.AddResidualBlock(new Plane({{0.0, 2.0}}, 4.0), last_loss, y.data());
        problem.SetParameterLowerBound(y.data(), 1, 0.0);
        problem.SetParameterUpperBound(y.data(), 1, 5.0);
    }
};

// d cost / d y1 at the start (all 0), by hand: r . dr/dy1 over the costs that have y (0, -3, -1 and -4 * 2), the
// last weighted by a Cauchy loss's rho'(s) = 1 / (1 + s) at s = 16 (Ceres' cost is 1/2 sum rho(|r|^2)).
TEST(ActiveBounds, CoordinateGradientSumsEveryCostOfASharedBlock) {
    SharedProblem plain;
    const BoundedCoordinate y1{plain.y.data(), 2, 1, 0.0, 5.0};
    EXPECT_NEAR(coordinate_gradient(plain.problem, y1), -3.0 - 1.0 - 8.0, 1e-12);
    SharedProblem robust(new ceres::CauchyLoss(1.0));
    const BoundedCoordinate robust_y1{robust.y.data(), 2, 1, 0.0, 5.0};
    EXPECT_NEAR(coordinate_gradient(robust.problem, robust_y1), -3.0 - 1.0 - 8.0 / 17.0, 1e-12);
    const BoundedCoordinate x1{&plain.x1, 1, 0, -1.0, 1.0};
    EXPECT_NEAR(coordinate_gradient(plain.problem, x1), -3.0, 1e-12);  // the one cost with x1 and a slope
}

// The shared coordinate held on its lower bound, where the cost pulls it inside (slope -12): released, and the
// second solve reaches the one minimum inside.
TEST(ActiveBounds, AHeldSharedCoordinateTheCostPullsInsideIsReleased) {
    SharedProblem shared;
    std::vector<BoundedCoordinate> bounded{{shared.y.data(), 2, 1, 0.0, 5.0, true},
                                           {&shared.x1, 1, 0, -10.0, 10.0},
                                           {&shared.x2, 1, 0, -10.0, 10.0}};
    shared.problem.SetParameterLowerBound(&shared.x1, 0, -10.0);
    shared.problem.SetParameterUpperBound(&shared.x1, 0, 10.0);
    shared.problem.SetParameterLowerBound(&shared.x2, 0, -10.0);
    shared.problem.SetParameterUpperBound(&shared.x2, 0, 10.0);
    ceres::Solver::Options options;
    options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
    options.function_tolerance = options.parameter_tolerance = 1e-14;
    options.max_num_iterations = 100;
    options.logging_type = ceres::SILENT;
    const ActiveBoundsSolve solved = solve_with_active_bounds(
        options, shared.problem, bounded, [] { return std::make_unique<StatisticalConvergence>(); });
    EXPECT_FALSE(bounded[0].held);
    EXPECT_EQ(solved.solves, 2u);
    EXPECT_NEAR(shared.y[0], 1.0, 1e-8);
    EXPECT_NEAR(shared.y[1], 2.0, 1e-8);
    EXPECT_NEAR(shared.x1, 1.0, 1e-8);
    EXPECT_NEAR(shared.x2, 1.0, 1e-8);
}

}  // namespace
}  // namespace mdr::fit
