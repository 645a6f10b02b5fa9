// Lawson-Hanson NNLS against an independent solution: for small problems every subset of columns is tried (the
// unconstrained least squares on the subset by the normal equations, kept when all its entries are > 0); the
// best feasible subset is the constrained minimum. Plus the Kuhn-Tucker conditions on larger exponential fits.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mdr/numerics/nonnegative_least_squares.hpp"

namespace mdr::numerics {
namespace {

// Solves the normal equations of the columns in `mask` by Gaussian elimination; empty when singular.
std::vector<double> subset_solution(const ColumnMatrix& A, const std::vector<double>& b, unsigned mask) {
    std::vector<std::size_t> columns;
    for (std::size_t j = 0; j < A.cols; ++j) {
        if (mask & (1u << j)) columns.push_back(j);
    }
    const std::size_t p = columns.size();
    std::vector<double> M(p * (p + 1), 0.0);
    for (std::size_t a = 0; a < p; ++a) {
        for (std::size_t i = 0; i < A.rows; ++i) M[a * (p + 1) + p] += A(i, columns[a]) * b[i];
        for (std::size_t c = 0; c < p; ++c) {
            for (std::size_t i = 0; i < A.rows; ++i) M[a * (p + 1) + c] += A(i, columns[a]) * A(i, columns[c]);
        }
    }
    for (std::size_t k = 0; k < p; ++k) {
        if (std::abs(M[k * (p + 1) + k]) < 1e-14) return {};
        for (std::size_t i = 0; i < p; ++i) {
            if (i == k) continue;
            const double f = M[i * (p + 1) + k] / M[k * (p + 1) + k];
            for (std::size_t c = 0; c <= p; ++c) M[i * (p + 1) + c] -= f * M[k * (p + 1) + c];
        }
    }
    std::vector<double> x(A.cols, 0.0);
    for (std::size_t k = 0; k < p; ++k) x[columns[k]] = M[k * (p + 1) + p] / M[k * (p + 1) + k];
    return x;
}

double residual(const ColumnMatrix& A, const std::vector<double>& b, const std::vector<double>& x) {
    double sum = 0.0;
    for (std::size_t i = 0; i < A.rows; ++i) {
        double r = -b[i];
        for (std::size_t j = 0; j < A.cols; ++j) r += A(i, j) * x[j];
        sum += r * r;
    }
    return std::sqrt(sum);
}

TEST(NonnegativeLeastSquares, MatchesExhaustiveSearchOnRandomProblems) {
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    for (int trial = 0; trial < 200; ++trial) {
        const std::size_t rows = 4 + trial % 7, cols = 1 + trial % 6;
        ColumnMatrix A{rows, cols, std::vector<double>(rows * cols)};
        for (double& value : A.values) value = normal(random);
        std::vector<double> b(rows);
        for (double& value : b) value = normal(random);
        double best = residual(A, b, std::vector<double>(cols, 0.0));
        for (unsigned mask = 1; mask < (1u << cols); ++mask) {
            const auto x = subset_solution(A, b, mask);
            if (x.empty() || std::any_of(x.begin(), x.end(), [](double v) { return v < 0.0; })) continue;
            best = std::min(best, residual(A, b, x));
        }
        const auto solution = nonnegative_least_squares(A, b);
        EXPECT_TRUE(solution.converged);
        for (double x : solution.x) EXPECT_GE(x, 0.0);
        EXPECT_NEAR(solution.residual_norm, best, 1e-10 * (1.0 + best)) << "trial " << trial;
        EXPECT_NEAR(solution.residual_norm, residual(A, b, solution.x), 1e-12 * (1.0 + best));
    }
}

TEST(NonnegativeLeastSquares, KuhnTuckerConditionsHoldForAnExponentialBasis) {
    // Nearly dependent columns exp(-t_i / tau_k), about 10 per decade: the case the material tables meet.
    const std::size_t rows = 80, cols = 97;
    ColumnMatrix A{rows, cols, std::vector<double>(rows * cols)};
    std::vector<double> b(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        const double t = 1e-3 * std::pow(1e5, static_cast<double>(i) / static_cast<double>(rows - 1));
        b[i] = 1.0 + 2.0 * std::exp(-t / 0.0137) + std::exp(-t / 3.1);
        for (std::size_t k = 0; k < cols; ++k) {
            const double tau = 1e-4 * std::pow(1e10, static_cast<double>(k) / static_cast<double>(cols - 1));
            A(i, k) = std::exp(-t / tau);
        }
    }
    const auto solution = nonnegative_least_squares(A, b);
    ASSERT_TRUE(solution.converged);
    // w = A^T (b - A x): w_j <= 0 everywhere (no column would lower the residual), w_j = 0 where x_j > 0.
    for (std::size_t j = 0; j < cols; ++j) {
        double w = 0.0;
        for (std::size_t i = 0; i < rows; ++i) {
            double r = b[i];
            for (std::size_t k = 0; k < cols; ++k) r -= A(i, k) * solution.x[k];
            w += A(i, j) * r;
        }
        EXPECT_LE(w, 1e-9) << j;
        if (solution.x[j] > 0.0) {
            EXPECT_NEAR(w, 0.0, 1e-9) << j;
        }
    }
    EXPECT_LT(solution.residual_norm, 1e-2);
}

TEST(NonnegativeLeastSquares, RefusesMismatchedSizes) {
    ColumnMatrix A{2, 2, std::vector<double>(3)};
    EXPECT_THROW(nonnegative_least_squares(A, {1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace mdr::numerics
