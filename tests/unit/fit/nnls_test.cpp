// non_negative_least_squares against its optimality (Karush-Kuhn-Tucker) conditions on random problems, and a
// problem whose solution is known in closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fit/nnls.hpp"

namespace mdr::fit {
namespace {

TEST(NonNegativeLeastSquares, KnownSolutionWithAnActiveBound) {
    // min |x - b| over x >= 0 with A = I: x = max(b, 0).
    const Eigen::VectorXd b = (Eigen::VectorXd(4) << 2.0, -1.0, 0.5, -3.0).finished();
    const Eigen::VectorXd x = non_negative_least_squares(Eigen::MatrixXd::Identity(4, 4), b);
    EXPECT_NEAR(x[0], 2.0, 1e-14);
    EXPECT_EQ(x[1], 0.0);
    EXPECT_NEAR(x[2], 0.5, 1e-14);
    EXPECT_EQ(x[3], 0.0);
}

TEST(NonNegativeLeastSquares, SatisfiesTheOptimalityConditions) {
    // x >= 0, the gradient g = A^T (A x - b) vanishes on the free components and is >= 0 on the bound ones.
    std::mt19937_64 random(3);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    for (int trial = 0; trial < 50; ++trial) {
        const Eigen::Index rows = 30, columns = 8;
        Eigen::MatrixXd A(rows, columns);
        Eigen::VectorXd b(rows);
        for (Eigen::Index i = 0; i < rows; ++i) {
            b[i] = gaussian(random);
            for (Eigen::Index j = 0; j < columns; ++j) A(i, j) = gaussian(random) * std::pow(10.0, static_cast<double>(j % 4));
        }
        const Eigen::VectorXd x = non_negative_least_squares(A, b);
        const Eigen::VectorXd g = A.transpose() * (A * x - b);
        for (Eigen::Index j = 0; j < columns; ++j) {
            const double scale = A.col(j).norm() * b.norm();
            EXPECT_GE(x[j], 0.0);
            if (x[j] > 0.0) {
                EXPECT_LT(std::abs(g[j]), 1e-10 * scale) << trial << " " << j;
            } else {
                EXPECT_GT(g[j], -1e-10 * scale) << trial << " " << j;
            }
        }
    }
}

}  // namespace
}  // namespace mdr::fit
