// The active set of src/fit/active_bounds.cpp on linear least-squares problems whose bounded minima are known in
// closed form (the normal equations with the bounded coordinate fixed, and the Karush-Kuhn-Tucker sign).

#include <gtest/gtest.h>

#include <ceres/sized_cost_function.h>

#include <memory>

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
        const auto gradient = [&](const BoundedCoordinate& coordinate) {
            return second_block_gradient(*cost, &y, coordinate);
        };
        return solve_with_active_bounds(options, problem, bounded, gradient,
                                        [] { return std::make_unique<StatisticalConvergence>(); });
    }
};

// d (1/2 |r|^2) / dx = r0 - weight r1, by hand.
TEST(ActiveBounds, SecondBlockGradientIsTheCostsSlope) {
    ChainProblem chain(2.0, 3.0, 0.5, 1.5);
    const BoundedCoordinate coordinate{&chain.x, 1, 0, 0.0, 5.0};
    const double r0 = 0.5 - 2.0;
    const double r1 = 3.0 * (1.5 - 0.5);
    EXPECT_NEAR(second_block_gradient(*chain.cost, &chain.y, coordinate), r0 - 3.0 * r1, 1e-12);
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
    EXPECT_GT(second_block_gradient(*chain.cost, &chain.y, bounded[0]), 0.0);
    EXPECT_EQ(solved.solves, 2u);
    EXPECT_TRUE(bounded[0].held);
}

}  // namespace
}  // namespace mdr::fit
