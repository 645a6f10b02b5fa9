#pragma once
// The Cholesky factorisation of a dense symmetric positive definite matrix and its solve (internal to mdr_core):
// contact::LayerContact's Nystroem system of eq. L3 (docs/theory.md, "Layers"), symmetric after a scaling by the
// square roots of the quadrature weights.

#include <cstddef>
#include <vector>

namespace mdr::numerics {

/// Factors the symmetric n x n row-major `matrix` = L L^T in place, reading only its lower triangle: L takes the
/// lower triangle, the upper one is left as it was (Golub & Van Loan, Matrix Computations, algorithm 4.2.1, the
/// row-oriented form). Returns false where a pivot is not > 0 (the matrix is not positive definite to working
/// precision); `matrix` is then part-factored.
bool cholesky_factor(std::vector<double>& matrix, std::size_t n);

/// Solves L L^T x = b in place (`b` becomes x) with the factor that cholesky_factor left in `factor`.
void cholesky_solve(const std::vector<double>& factor, std::size_t n, std::vector<double>& b);

}  // namespace mdr::numerics
