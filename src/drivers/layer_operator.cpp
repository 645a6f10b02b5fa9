#include "layer_operator.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "../numerics/cholesky.hpp"

namespace mdr::drivers {

namespace {

// What an operator depends on: equal keys give equal operators.
struct OperatorKey {
    contact::LayerInterface interface = contact::LayerInterface::bonded;
    double thickness = 0.0, poisson_ratio = 0.0, width = 0.0;
    std::size_t cells = 0;
    bool operator==(const OperatorKey&) const = default;
};

std::shared_ptr<const LayerOperator> build(const OperatorKey& key) {
    const std::size_t cells = key.cells;
    const double h = key.thickness, spacing = key.width / static_cast<double>(cells);
    const contact::LayerKernel kernel(key.interface, key.poisson_ratio, 2.0 * key.width / h);
    std::vector<double> centre(cells);
    for (std::size_t i = 0; i < cells; ++i) centre[i] = (static_cast<double>(i) + 0.5) * spacing;
    auto built = std::make_shared<LayerOperator>();
    auto& matrix = built->matrix;
    auto& factor = built->factor;
    matrix.assign(cells * cells, 0.0);
    factor.assign(cells * cells, 0.0);
    // (I - K)_ij = delta_ij - (dx/pi) [K(x_i - x_j) + K(x_i + x_j)], K(y) = k(y/h)/h (eq. L17 from L3, L4; midpoint
    // rule).
    for (std::size_t i = 0; i < cells; ++i) {
        for (std::size_t j = 0; j <= i; ++j) {
            const double coupling = spacing / std::numbers::pi *
                                    (kernel((centre[i] - centre[j]) / h) + kernel((centre[i] + centre[j]) / h)) / h;
            matrix[i * cells + j] = matrix[j * cells + i] = (i == j ? 1.0 : 0.0) - coupling;
        }
    }
    // Cholesky, I - K = L L^T with L = U^T of numerics::cholesky_factor: symmetric, and positive as its symbol
    // L(xi h) > 0 is (eq. L1).
    std::vector<double> upper = matrix;
    if (!numerics::cholesky_factor(upper, cells)) {
        throw std::runtime_error("the layer's operator I - K is not positive definite on " + std::to_string(cells) +
                                 " cells");
    }
    built->factor_transposed.assign(cells * cells, 0.0);
    built->inverse_diagonal.resize(cells);
    for (std::size_t i = 0; i < cells; ++i) {
        for (std::size_t j = i; j < cells; ++j) {
            built->factor_transposed[i * cells + j] = factor[j * cells + i] = upper[i * cells + j];
        }
        built->inverse_diagonal[i] = 1.0 / upper[i * cells + i];
    }
    return built;
}

}  // namespace

std::shared_ptr<const LayerOperator> layer_operator(const contact::Layer& layer, double poisson_ratio, double width,
                                                    std::size_t cells) {
    // One per thread (no lock; a few MiB at the most cells): a fit's runs on one layer, and the runs of its
    // Jacobian that move a modulus, reuse it.
    thread_local OperatorKey last_key;
    thread_local std::shared_ptr<const LayerOperator> last;
    const OperatorKey key{layer.interface, layer.thickness, poisson_ratio, width, cells};
    if (!last || !(key == last_key)) {
        last.reset();  // the old one's memory goes before the new one is built
        last = build(key);
        last_key = key;
    }
    return last;
}

}  // namespace mdr::drivers
