// residual_autocovariance (the linearised moving-block bootstrap of a fit's errors): the block length from the first
// zero crossing, the effective points of a smooth misfit and of white residuals, and the banded Toeplitz product
// against the dense matrix.

#include "fit/residual_autocovariance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace mdr::fit {
namespace {

Eigen::VectorXd smooth_misfit(Eigen::Index n, double periods) {
    Eigen::VectorXd r(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        r[i] = std::sin(2.0 * std::numbers::pi * periods * static_cast<double>(i) / static_cast<double>(n));
    }
    return r;
}

TEST(ResidualAutocovariance, SmoothMisfitCountsOnePointPerBlock) {
    // Five periods of a sine over 1000 rows: the autocorrelation, about (1 - l/n) cos(2 pi 5 l / n), first reaches 0
    // near a quarter period, l = 50 (52 with the sum's end terms), so blocks are 4 x ~50 rows and the lag-1
    // correlation is ~1: the Bartlett window sums to ~b, n_eff ~ 1000 / b ~ 5 blocks. An AR(1) model over the whole
    // curve (before) gave n (1 - phi) / (1 + phi) -> 1: the whole record one point.
    const auto autocovariance = residual_autocovariance(smooth_misfit(1000, 5.0));
    EXPECT_GE(autocovariance.block_length, blocks_per_zero_crossing * 49);
    EXPECT_LE(autocovariance.block_length, blocks_per_zero_crossing * 53);
    // phi ~ cos(2 pi 5 / 1000) = 0.9995: phi^l falls to ~0.9 over a block, n_eff a little above n / b.
    const double blocks = 1000.0 / static_cast<double>(autocovariance.block_length);
    EXPECT_GT(autocovariance.effective_points, blocks);
    EXPECT_LT(autocovariance.effective_points, 1.2 * blocks);
    EXPECT_NEAR(autocovariance.gamma[0], 0.5, 1e-12);  // the variance of a sine over whole periods
}

TEST(ResidualAutocovariance, WhiteResidualsKeepTheirPoints) {
    std::mt19937_64 random(7);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    Eigen::VectorXd r(4000);
    for (auto& value : r) value = gaussian(random);
    const auto autocovariance = residual_autocovariance(r);
    // The first zero crossing of white residuals' autocorrelation is at lag 1 or 2 in most draws (each lag is
    // positive with probability 1/2); phi ~ 1/n: the window adds ~0.
    EXPECT_LE(autocovariance.block_length, 4 * blocks_per_zero_crossing);
    EXPECT_GT(autocovariance.effective_points, 0.95 * 4000);
}

TEST(ResidualAutocovariance, BandedProductIsTheToeplitzMatrixTimesTheColumns) {
    // Against the dense matrix C_ij = gamma(|i - j|) for |i - j| < b, which must also be positive semi-definite.
    const auto autocovariance = residual_autocovariance(smooth_misfit(120, 3.0) + 0.3 * smooth_misfit(120, 17.0));
    const Eigen::Index n = 120;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
        for (Eigen::Index j = 0; j < n; ++j) {
            const Eigen::Index lag = std::abs(i - j);
            if (lag < autocovariance.gamma.size()) dense(i, j) = autocovariance.gamma[lag];
        }
    }
    const Eigen::MatrixXd columns = Eigen::MatrixXd::Random(n, 3);
    const Eigen::MatrixXd expected = dense * columns;
    EXPECT_LT((apply_autocovariance(autocovariance, columns) - expected).norm(), 1e-12 * expected.norm());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(dense);
    EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-12 * eigen.eigenvalues().maxCoeff());
}

}  // namespace
}  // namespace mdr::fit
