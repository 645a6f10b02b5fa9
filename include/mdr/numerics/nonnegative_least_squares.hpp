#pragma once
/// \file
/// Bounded linear least squares: min ||A x - b||_2 subject to x >= 0 (Lawson and Hanson, "Solving Least Squares
/// Problems", 1974, ch. 23), for fitting non-negative spectra on a logarithmic grid of times (material tables,
/// `mdr fit` spectrum mode).

#include <cstddef>
#include <vector>

namespace mdr::numerics {

/// A dense matrix stored column by column: entry (i, j) at values[i + j * rows].
struct ColumnMatrix {
    std::size_t rows = 0;
    std::size_t cols = 0;
    std::vector<double> values{};

    double& operator()(std::size_t i, std::size_t j) { return values[i + j * rows]; }
    double operator()(std::size_t i, std::size_t j) const { return values[i + j * rows]; }
};

/// What the solver found.
struct NonnegativeSolution {
    std::vector<double> x{};      ///< the minimiser, every entry >= 0 (exactly 0 off the passive set)
    double residual_norm = 0.0;   ///< ||A x - b||_2
    std::size_t iterations = 0;   ///< outer iterations (columns entered)
    bool converged = false;       ///< the Kuhn-Tucker conditions hold to the solver's tolerance
};

/// Lawson-Hanson active-set method. The unconstrained subproblems are solved by Householder QR of the passive
/// columns (stable for the nearly dependent columns of exponential bases); a column is entered while its
/// gradient component A^T (b - A x) exceeds 10 eps max(rows, cols) ||A||_1 ||b||_inf. At most `max_iterations`
/// columns are entered (0: three times the number of columns). Throws std::invalid_argument for mismatched sizes.
NonnegativeSolution nonnegative_least_squares(const ColumnMatrix& A, const std::vector<double>& b,
                                              std::size_t max_iterations = 0);

}  // namespace mdr::numerics
