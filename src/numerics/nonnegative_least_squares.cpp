#include "mdr/numerics/nonnegative_least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mdr::numerics {
namespace {

// The unconstrained least-squares solution on the columns `passive` of A, by Householder QR (rank-revealing only in
// that a vanishing pivot gives a zero coefficient).
std::vector<double> solve_passive(const ColumnMatrix& A, const std::vector<double>& b,
                                  const std::vector<std::size_t>& passive) {
    const std::size_t m = A.rows, p = passive.size();
    std::vector<double> R(m * p);
    for (std::size_t j = 0; j < p; ++j) {
        for (std::size_t i = 0; i < m; ++i) R[i + j * m] = A(i, passive[j]);
    }
    std::vector<double> y = b;
    const std::size_t steps = std::min(m, p);
    for (std::size_t k = 0; k < steps; ++k) {
        double norm = 0.0;
        for (std::size_t i = k; i < m; ++i) norm = std::hypot(norm, R[i + k * m]);
        if (norm == 0.0) continue;
        const double alpha = R[k + k * m] > 0.0 ? -norm : norm;
        // v = x - alpha e_k, stored in place below the diagonal; H = I - 2 v v^T / (v^T v).
        R[k + k * m] -= alpha;
        double vv = 0.0;
        for (std::size_t i = k; i < m; ++i) vv += R[i + k * m] * R[i + k * m];
        for (std::size_t j = k + 1; j < p; ++j) {
            double dot = 0.0;
            for (std::size_t i = k; i < m; ++i) dot += R[i + k * m] * R[i + j * m];
            const double scale = 2.0 * dot / vv;
            for (std::size_t i = k; i < m; ++i) R[i + j * m] -= scale * R[i + k * m];
        }
        double dot = 0.0;
        for (std::size_t i = k; i < m; ++i) dot += R[i + k * m] * y[i];
        const double scale = 2.0 * dot / vv;
        for (std::size_t i = k; i < m; ++i) y[i] -= scale * R[i + k * m];
        R[k + k * m] = alpha;
    }
    std::vector<double> z(p, 0.0);
    double largest = 0.0;
    for (std::size_t k = 0; k < steps; ++k) largest = std::max(largest, std::abs(R[k + k * m]));
    for (std::size_t k = steps; k-- > 0;) {
        double sum = y[k];
        for (std::size_t j = k + 1; j < steps; ++j) sum -= R[k + j * m] * z[j];
        const double pivot = R[k + k * m];
        z[k] = std::abs(pivot) > 1e-14 * largest ? sum / pivot : 0.0;
    }
    return z;
}

std::vector<double> gradient(const ColumnMatrix& A, const std::vector<double>& b, const std::vector<double>& x,
                             double& residual_norm) {
    std::vector<double> r = b;
    for (std::size_t j = 0; j < A.cols; ++j) {
        if (x[j] == 0.0) continue;
        for (std::size_t i = 0; i < A.rows; ++i) r[i] -= A(i, j) * x[j];
    }
    residual_norm = 0.0;
    for (double value : r) residual_norm = std::hypot(residual_norm, value);
    std::vector<double> w(A.cols, 0.0);
    for (std::size_t j = 0; j < A.cols; ++j) {
        for (std::size_t i = 0; i < A.rows; ++i) w[j] += A(i, j) * r[i];
    }
    return w;
}

}  // namespace

NonnegativeSolution nonnegative_least_squares(const ColumnMatrix& A, const std::vector<double>& b,
                                              std::size_t max_iterations) {
    if (A.values.size() != A.rows * A.cols || b.size() != A.rows) {
        throw std::invalid_argument("nonnegative_least_squares: sizes of A and b do not match");
    }
    const std::size_t n = A.cols;
    if (max_iterations == 0) max_iterations = 3 * n + 1;
    double norm_A = 0.0, norm_b = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        double column = 0.0;
        for (std::size_t i = 0; i < A.rows; ++i) column += std::abs(A(i, j));
        norm_A = std::max(norm_A, column);
    }
    for (double value : b) norm_b = std::max(norm_b, std::abs(value));
    const double tolerance = 10.0 * std::numeric_limits<double>::epsilon() *
                             static_cast<double>(std::max(A.rows, n)) * norm_A * norm_b;

    NonnegativeSolution solution;
    solution.x.assign(n, 0.0);
    std::vector<bool> is_passive(n, false);
    std::vector<double> w = gradient(A, b, solution.x, solution.residual_norm);
    while (solution.iterations < max_iterations) {
        std::size_t entering = n;
        double best = tolerance;
        for (std::size_t j = 0; j < n; ++j) {
            if (!is_passive[j] && w[j] > best) {
                best = w[j];
                entering = j;
            }
        }
        if (entering == n) {
            solution.converged = true;
            break;
        }
        ++solution.iterations;
        is_passive[entering] = true;
        for (;;) {  // inner loop: step towards the unconstrained solution, dropping columns that would go negative
            std::vector<std::size_t> passive;
            for (std::size_t j = 0; j < n; ++j) {
                if (is_passive[j]) passive.push_back(j);
            }
            const std::vector<double> z = solve_passive(A, b, passive);
            bool feasible = true;
            double alpha = 1.0;
            std::size_t blocking = passive.size();
            for (std::size_t k = 0; k < passive.size(); ++k) {
                if (z[k] <= 0.0) {
                    feasible = false;
                    const double x = solution.x[passive[k]];
                    const double step = x / (x - z[k]);
                    if (step < alpha || blocking == passive.size()) {
                        alpha = std::min(alpha, step);
                        blocking = k;
                    }
                }
            }
            if (feasible) {
                for (std::size_t k = 0; k < passive.size(); ++k) solution.x[passive[k]] = z[k];
                break;
            }
            for (std::size_t k = 0; k < passive.size(); ++k) {
                double& x = solution.x[passive[k]];
                x += alpha * (z[k] - x);
                if (x <= 0.0 || k == blocking) {  // the blocking column reaches 0 (exactly, but for rounding)
                    x = 0.0;
                    is_passive[passive[k]] = false;
                }
            }
            // The entering column may itself have been dropped at once (a degenerate step): stop the inner loop.
            if (std::none_of(is_passive.begin(), is_passive.end(), [](bool p) { return p; })) break;
        }
        w = gradient(A, b, solution.x, solution.residual_norm);
    }
    gradient(A, b, solution.x, solution.residual_norm);
    return solution;
}

}  // namespace mdr::numerics
