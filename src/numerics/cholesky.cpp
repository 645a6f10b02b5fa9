#include "cholesky.hpp"

#include <cmath>

#include "dot_product.hpp"

namespace mdr::numerics {

bool cholesky_factor(std::vector<double>& matrix, std::size_t n) {
    // Row by row: L_ij = (A_ij - sum_{k<j} L_ik L_jk) / L_jj, L_ii = sqrt(A_ii - sum_{k<i} L_ik^2); each sum is a dot
    // product of two rows already factored, contiguous in memory.
    for (std::size_t i = 0; i < n; ++i) {
        double* row_i = &matrix[i * n];
        for (std::size_t j = 0; j < i; ++j) {
            const double* row_j = &matrix[j * n];
            row_i[j] = (row_i[j] - dot_product(row_i, row_j, j)) / row_j[j];
        }
        const double pivot = row_i[i] - dot_product(row_i, row_i, i);
        if (!(pivot > 0.0)) return false;
        row_i[i] = std::sqrt(pivot);
    }
    return true;
}

void cholesky_solve(const std::vector<double>& factor, std::size_t n, std::vector<double>& b) {
    for (std::size_t i = 0; i < n; ++i) {  // L y = b
        b[i] = (b[i] - dot_product(&factor[i * n], b.data(), i)) / factor[i * n + i];
    }
    for (std::size_t i = n; i-- > 0;) {  // L^T x = y, by rows of L: once x_i is known, it leaves the rows above
        b[i] /= factor[i * n + i];
        for (std::size_t k = 0; k < i; ++k) b[k] -= factor[i * n + k] * b[i];
    }
}

}  // namespace mdr::numerics
