#pragma once
// The dot product of two arrays of doubles (internal to mdr_core): the dense kernels of the layer's cells
// (drivers::LayerCells: the Cholesky factor, its triangular solves and the free surface's matrix-vector product).

#include <cstddef>

namespace mdr::numerics {

/// sum_j a[j] b[j] for j < size, summed as eight partial sums (j mod 8; the last size mod 8 products in the first)
/// added pairwise at the end: the products vectorise and the additions overlap, where a single running sum is a
/// serial chain. No fused multiply-add, so the result is the same with and without AVX2.
double dot_product(const double* a, const double* b, std::size_t size);

}  // namespace mdr::numerics
