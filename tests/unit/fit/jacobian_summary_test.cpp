// src/fit/jacobian_summary.cpp against the dense quantities it replaces (issue 23, memory of a large fit): the
// singular values of J from a JacobiSVD of J itself, J^T P J (and the last curve's part of it) with
// P_ij = phi^|i - j| written out as a matrix, |r| from
// Eigen's norm; and no overflow of the squares of large residuals.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "fit/jacobian_summary.hpp"

namespace mdr::fit {
namespace {

// Rows of a column-scaled random matrix, with one nearly dependent column (as a fit's correlated parameters).
Eigen::MatrixXd tall_matrix(Eigen::Index rows, Eigen::Index columns, unsigned seed) {
    std::mt19937 random(seed);
    std::normal_distribution<double> normal;
    Eigen::MatrixXd matrix(rows, columns);
    for (Eigen::Index i = 0; i < rows; ++i) {
        for (Eigen::Index j = 0; j < columns; ++j) {
            matrix(i, j) = normal(random) * std::pow(10.0, static_cast<double>(j));
        }
    }
    const double last_scale = std::pow(10.0, static_cast<double>(columns - 1));
    matrix.col(columns - 1) = matrix.col(0) + 1e-6 * matrix.col(columns - 1) / last_scale;
    return matrix;
}

// P_ij = phi^|i - j| on the diagonal block of each curve, 0 across curves.
Eigen::MatrixXd correlation_matrix(const std::vector<Eigen::Index>& sizes, const std::vector<double>& phis) {
    Eigen::Index total = 0;
    for (const auto size : sizes) total += size;
    Eigen::MatrixXd p = Eigen::MatrixXd::Zero(total, total);
    Eigen::Index begin = 0;
    for (std::size_t c = 0; c < sizes.size(); ++c) {
        for (Eigen::Index i = 0; i < sizes[c]; ++i) {
            for (Eigen::Index j = 0; j < sizes[c]; ++j) {
                p(begin + i, begin + j) = std::pow(phis[c], static_cast<double>(std::abs(i - j)));
            }
        }
        begin += sizes[c];
    }
    return p;
}

TEST(JacobianSummary, AgreesWithTheDenseSvdSandwichAndNorm) {
    const std::vector<Eigen::Index> sizes{700, 3, 611};  // several blocks of 256 rows, a short curve between
    const std::vector<double> phis{0.93, 0.0, 0.4};
    const Eigen::Index columns = 4;
    Eigen::Index total = 0;
    for (const auto size : sizes) total += size;
    const Eigen::MatrixXd jacobian = tall_matrix(total, columns, 11);
    const Eigen::VectorXd residuals = tall_matrix(total, 1, 12).col(0);

    JacobianSummary summary(columns);
    Eigen::Index begin = 0;
    for (std::size_t c = 0; c < sizes.size(); ++c) {
        summary.start_curve(phis[c]);
        for (Eigen::Index done = 0; done < sizes[c];) {  // in pieces of 100 rows, as a fit's row blocks
            const Eigen::Index count = std::min<Eigen::Index>(100, sizes[c] - done);
            summary.add_rows(count, [&](Eigen::Index i, Eigen::Ref<Eigen::RowVectorXd> row) {
                row = jacobian.row(begin + done + i);
            });
            done += count;
        }
        summary.add_residuals(residuals.segment(begin, sizes[c]));
        begin += sizes[c];
    }
    EXPECT_EQ(summary.rows(), total);

    const Eigen::VectorXd expected = Eigen::JacobiSVD<Eigen::MatrixXd>(jacobian).singularValues();
    const Eigen::VectorXd singular = Eigen::JacobiSVD<Eigen::MatrixXd>(summary.triangular()).singularValues();
    for (Eigen::Index s = 0; s < columns; ++s) {
        // backward stable both: each singular value to a few units of roundoff of the largest
        EXPECT_NEAR(singular[s], expected[s], 1e-13 * expected[0]) << s;
    }
    EXPECT_LT(expected[columns - 1], 1e-5 * expected[0]);  // the case covers a nearly dependent column

    const Eigen::MatrixXd sandwich = jacobian.transpose() * correlation_matrix(sizes, phis) * jacobian;
    EXPECT_LT((summary.correlated_gram() - sandwich).norm(), 1e-12 * sandwich.norm());
    // The last curve's part: its rows alone, written out.
    const Eigen::MatrixXd last_rows = jacobian.bottomRows(sizes.back());
    const Eigen::MatrixXd last = last_rows.transpose() * correlation_matrix({sizes.back()}, {phis.back()}) * last_rows;
    EXPECT_LT((summary.curve_correlated_gram() - last).norm(), 1e-12 * last.norm());
    EXPECT_NEAR(summary.residual_norm(), residuals.norm(), 1e-14 * residuals.norm());
}

TEST(JacobianSummary, ResidualNormOfLargeValuesDoesNotOverflow) {
    JacobianSummary summary(1);
    const Eigen::Vector3d residuals(3e200, -4e200, 0.0);  // squares beyond the largest double
    summary.add_residuals(residuals.head(1));
    summary.add_residuals(residuals.tail(2));
    EXPECT_NEAR(summary.residual_norm(), 5e200, 1e-15 * 5e200);
}

}  // namespace
}  // namespace mdr::fit
