#pragma once
// The Cholesky factorisation of a dense symmetric positive definite matrix and its solve (internal to mdr_core):
// contact::LayerContact's Nystroem system of eq. L3 (docs/theory.md, "Layers"), symmetric after a scaling by the
// square roots of the quadrature weights.

#include <cstddef>
#include <vector>

namespace mdr::numerics {

/// Factors the symmetric n x n row-major `matrix` = U^T U in place, reading only its upper triangle (j >= i): U takes
/// the upper triangle, the lower one is left as it was (Golub & Van Loan, Matrix Computations, the outer-product
/// form of algorithm 4.2.2: each row of U updates the rows below it by contiguous multiply-adds, which vectorise; four
/// rows of U at a time, each entry's updates in the order of the unblocked form, with the same results bit for bit).
/// Returns false where a pivot is not > 0 (the matrix is not positive definite to working precision); `matrix` is
/// then part-factored.
bool cholesky_factor(std::vector<double>& matrix, std::size_t n);

/// Solves U^T U x = b in place (`b` becomes x) with the factor that cholesky_factor left in `factor`.
void cholesky_solve(const std::vector<double>& factor, std::size_t n, std::vector<double>& b);
/// As above for two right-hand sides at once (`b` and `c` become their x; each the same as solved alone, bit for
/// bit): the factor is read once, and the back substitution's sums, each a chain of dependent subtractions, overlap.
void cholesky_solve(const std::vector<double>& factor, std::size_t n, std::vector<double>& b, std::vector<double>& c);

}  // namespace mdr::numerics
