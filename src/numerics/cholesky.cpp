#include "cholesky.hpp"

#include <cmath>

namespace mdr::numerics {

// An AVX2 clone for the row updates (no FMA: the same results with and without it).
__attribute__((target_clones("avx2", "default"))) bool cholesky_factor(std::vector<double>& matrix, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        double* row_k = &matrix[k * n];
        if (!(row_k[k] > 0.0)) return false;
        // U_kk = sqrt(A_kk), U_kj = A_kj / U_kk; then A_ij -= U_ki U_kj for k < i <= j (the Schur complement).
        row_k[k] = std::sqrt(row_k[k]);
        const double inverse = 1.0 / row_k[k];
        for (std::size_t j = k + 1; j < n; ++j) row_k[j] *= inverse;
        for (std::size_t i = k + 1; i < n; ++i) {
            const double factor = row_k[i];
            double* row_i = &matrix[i * n];
            for (std::size_t j = i; j < n; ++j) row_i[j] -= factor * row_k[j];
        }
    }
    return true;
}

void cholesky_solve(const std::vector<double>& factor, std::size_t n, std::vector<double>& b) {
    for (std::size_t k = 0; k < n; ++k) {  // U^T y = b, by rows of U: once y_k is known, it leaves the rows below
        const double* row_k = &factor[k * n];
        b[k] /= row_k[k];
        for (std::size_t j = k + 1; j < n; ++j) b[j] -= row_k[j] * b[k];
    }
    for (std::size_t i = n; i-- > 0;) {  // U x = y
        const double* row_i = &factor[i * n];
        double sum = b[i];
        for (std::size_t j = i + 1; j < n; ++j) sum -= row_i[j] * b[j];
        b[i] = sum / row_i[i];
    }
}

}  // namespace mdr::numerics
