#pragma once
// The operator I - K of a layer on uniform cells and its Cholesky factor (docs/theory.md, "Layers", eq. L17), which
// drivers::LayerCells solves with at every step. It depends on the layer, its Poisson ratio and the cells alone, not
// on the moduli or the load: the last one a thread built is kept for the next run on the same layer and cells (the
// model runs of a fit, issue 28).

#include <cstddef>
#include <memory>
#include <vector>

#include "mdr/contact/layer.hpp"

namespace mdr::drivers {

/// I - K on n uniform cells of [0, width] (centres x_i = (i + 1/2) width / n) and its Cholesky factor, n x n
/// row-major.
struct LayerOperator {
    std::vector<double> matrix;             ///< (I - K)_ij (eq. L17, midpoint rule)
    std::vector<double> factor;             ///< L of I - K = L L^T (zero above the diagonal)
    std::vector<double> factor_transposed;  ///< L^T (the back substitution reads its rows)
    std::vector<double> inverse_diagonal;   ///< 1 / L_ii
};

/// The operator of `cells` (>= 2) uniform cells of [0, `width`] [m] on `layer` of Poisson ratio `poisson_ratio`
/// (the kernel tabulated on [0, 2 width / h]), built and factored (O(cells^3)), or the one this thread built last
/// when every argument is the same (the same numbers bit for bit). Throws std::runtime_error where I - K is not
/// positive definite.
std::shared_ptr<const LayerOperator> layer_operator(const contact::Layer& layer, double poisson_ratio, double width,
                                                    std::size_t cells);

}  // namespace mdr::drivers
