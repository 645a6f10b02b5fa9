#include "cholesky.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mdr::numerics {

namespace {

// Rows of U applied together to each row below them: the trailing rows are read and written once per block of rows
// instead of once per row (the factorisation of ~200 rows was bound by that traffic).
constexpr std::size_t block_rows = 4;

}  // namespace

// An AVX2 clone for the row updates (no FMA: the same results with and without it). Each entry receives its updates
// in the order of k, as in the unblocked form: the same results, bit for bit.
__attribute__((target_clones("avx2", "default"))) bool cholesky_factor(std::vector<double>& matrix, std::size_t n) {
    for (std::size_t first = 0; first < n; first += block_rows) {
        const std::size_t end = std::min(first + block_rows, n);
        // The block's rows: U_kk = sqrt(A_kk), U_kj = A_kj / U_kk; then A_ij -= U_ki U_kj for k < i <= j within it.
        for (std::size_t k = first; k < end; ++k) {
            double* row_k = &matrix[k * n];
            if (!(row_k[k] > 0.0)) return false;
            row_k[k] = std::sqrt(row_k[k]);
            const double inverse = 1.0 / row_k[k];
            for (std::size_t j = k + 1; j < n; ++j) row_k[j] *= inverse;
            for (std::size_t i = k + 1; i < end; ++i) {
                const double factor = row_k[i];
                double* row_i = &matrix[i * n];
                for (std::size_t j = i; j < n; ++j) row_i[j] -= factor * row_k[j];
            }
        }
        // The rows below the block (the Schur complement): A_ij -= U_ki U_kj for the block's k, in order.
        if (end - first == block_rows) {
            const double* row_0 = &matrix[first * n];
            const double* row_1 = row_0 + n;
            const double* row_2 = row_1 + n;
            const double* row_3 = row_2 + n;
            for (std::size_t i = end; i < n; ++i) {
                double* row_i = &matrix[i * n];
                const double f0 = row_0[i], f1 = row_1[i], f2 = row_2[i], f3 = row_3[i];
                for (std::size_t j = i; j < n; ++j) {
                    double value = row_i[j];
                    value -= f0 * row_0[j];
                    value -= f1 * row_1[j];
                    value -= f2 * row_2[j];
                    value -= f3 * row_3[j];
                    row_i[j] = value;
                }
            }
        } else {
            for (std::size_t k = first; k < end; ++k) {
                const double* row_k = &matrix[k * n];
                for (std::size_t i = end; i < n; ++i) {
                    const double factor = row_k[i];
                    double* row_i = &matrix[i * n];
                    for (std::size_t j = i; j < n; ++j) row_i[j] -= factor * row_k[j];
                }
            }
        }
    }
    return true;
}

namespace {

// U^T U x = b for `count` right-hand sides together: each b's operations in the same order as alone, the factor read
// once for all, and the back substitution's dependent sums of the right-hand sides interleaved.
template <std::size_t count>
void solve_together(const std::vector<double>& factor, std::size_t n, const std::array<double*, count>& b) {
    for (std::size_t k = 0; k < n; ++k) {  // U^T y = b, by rows of U: once y_k is known, it leaves the rows below
        const double* row_k = &factor[k * n];
        for (double* x : b) x[k] /= row_k[k];
        for (std::size_t j = k + 1; j < n; ++j) {
            for (double* x : b) x[j] -= row_k[j] * x[k];
        }
    }
    for (std::size_t i = n; i-- > 0;) {  // U x = y
        const double* row_i = &factor[i * n];
        std::array<double, count> sum;
        for (std::size_t r = 0; r < count; ++r) sum[r] = b[r][i];
        for (std::size_t j = i + 1; j < n; ++j) {
            for (std::size_t r = 0; r < count; ++r) sum[r] -= row_i[j] * b[r][j];
        }
        for (std::size_t r = 0; r < count; ++r) b[r][i] = sum[r] / row_i[i];
    }
}

}  // namespace

void cholesky_solve(const std::vector<double>& factor, std::size_t n, std::vector<double>& b) {
    solve_together<1>(factor, n, {b.data()});
}

void cholesky_solve(const std::vector<double>& factor, std::size_t n, std::vector<double>& b,
                    std::vector<double>& c) {
    solve_together<2>(factor, n, {b.data(), c.data()});
}

}  // namespace mdr::numerics
