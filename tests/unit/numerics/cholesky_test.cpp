// numerics::cholesky_factor and cholesky_solve (src/numerics/cholesky.hpp): a matrix made as L L^T from an integer L
// gives U = L^T back exactly, a solve gives the integer x whose A x was the right-hand side, and a matrix that is not
// positive definite is refused; two right-hand sides solved together as each alone.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "numerics/cholesky.hpp"

namespace {

// L_ii = 2, L_ij = (i + 2 j) mod 3 below the diagonal: every product and sum in A = L L^T, and every scaling by
// 1 / L_jj = 1/2 in the factorisation, is exact in doubles.
std::vector<double> integer_factor(std::size_t n) {
    std::vector<double> factor(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < i; ++j) factor[i * n + j] = static_cast<double>((i + 2 * j) % 3);
        factor[i * n + i] = 2.0;
    }
    return factor;
}

std::vector<double> product_with_transpose(const std::vector<double>& factor, std::size_t n) {
    std::vector<double> matrix(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            for (std::size_t k = 0; k < n; ++k) matrix[i * n + j] += factor[i * n + k] * factor[j * n + k];
        }
    }
    return matrix;
}

TEST(Cholesky, FactorsAnIntegerProductExactlyAndLeavesTheLowerTriangle) {
    for (const std::size_t n : {1U, 2U, 7U, 9U, 20U}) {  // whole blocks of four rows and remainders
        const std::vector<double> factor = integer_factor(n);
        std::vector<double> matrix = product_with_transpose(factor, n);
        const std::vector<double> original = matrix;
        ASSERT_TRUE(mdr::numerics::cholesky_factor(matrix, n)) << n;
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t j = 0; j < n; ++j) {
                EXPECT_EQ(matrix[i * n + j], j >= i ? factor[j * n + i] : original[i * n + j]) << n << ' ' << i << j;
            }
        }
    }
}

TEST(Cholesky, SolvesForTheVectorWhoseProductWasGiven) {
    const std::size_t n = 20;
    std::vector<double> matrix = product_with_transpose(integer_factor(n), n);
    std::vector<double> expected(n), b(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) expected[i] = static_cast<double>(i % 5) - 2.0;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) b[i] += matrix[i * n + j] * expected[j];
    }
    ASSERT_TRUE(mdr::numerics::cholesky_factor(matrix, n));
    mdr::numerics::cholesky_solve(matrix, n, b);
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(b[i], expected[i], 1e-12) << i;
}

TEST(Cholesky, SolvesTwoRightHandSidesAsEachAlone) {
    // A matrix whose factor is not exact in doubles (the Hilbert matrix plus n on the diagonal): the pair's solutions
    // are bit for bit those of the one-vector solve, and each solves its system.
    const std::size_t n = 23;
    std::vector<double> matrix(n * n);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            matrix[i * n + j] = 1.0 / static_cast<double>(i + j + 1) + (i == j ? static_cast<double>(n) : 0.0);
        }
    }
    const std::vector<double> original = matrix;
    std::vector<double> b(n), c(n);
    for (std::size_t i = 0; i < n; ++i) {
        b[i] = std::sin(static_cast<double>(i));
        c[i] = 1.0 / static_cast<double>(i + 3);
    }
    const std::vector<double> b_given = b, c_given = c;
    ASSERT_TRUE(mdr::numerics::cholesky_factor(matrix, n));
    std::vector<double> b_alone = b, c_alone = c;
    mdr::numerics::cholesky_solve(matrix, n, b_alone);
    mdr::numerics::cholesky_solve(matrix, n, c_alone);
    mdr::numerics::cholesky_solve(matrix, n, b, c);
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(b[i], b_alone[i]) << i;
        EXPECT_EQ(c[i], c_alone[i]) << i;
        double b_product = 0.0, c_product = 0.0;
        for (std::size_t j = 0; j < n; ++j) {
            b_product += original[i * n + j] * b[j];
            c_product += original[i * n + j] * c[j];
        }
        EXPECT_NEAR(b_product, b_given[i], 1e-13) << i;
        EXPECT_NEAR(c_product, c_given[i], 1e-13) << i;
    }
}

TEST(Cholesky, RefusesAMatrixThatIsNotPositiveDefinite) {
    std::vector<double> indefinite{1.0, 2.0, 2.0, 1.0};  // eigenvalues 3 and -1
    EXPECT_FALSE(mdr::numerics::cholesky_factor(indefinite, 2));
    std::vector<double> singular{1.0, 1.0, 1.0, 1.0};  // eigenvalues 2 and 0
    EXPECT_FALSE(mdr::numerics::cholesky_factor(singular, 2));
}

}  // namespace
