// drivers::layer_operator (src/drivers/layer_operator.hpp): I - K of a layer's cells (docs/theory.md eq. L17) and its
// Cholesky factor, kept for the thread's next run on the same layer and cells.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>

#include "drivers/layer_operator.hpp"
#include "mdr/contact/layer.hpp"

namespace {

TEST(LayerOperator, TheFactorReproducesIMinusKFromTheKernel) {
    // (I - K)_ij = delta_ij - (dx/pi) [k((x_i - x_j)/h) + k((x_i + x_j)/h)] / h at the centres x_i = (i + 1/2) dx
    // (eq. L17), from the kernel itself, against L L^T.
    const mdr::contact::Layer layer{.thickness = 1.0e-6, .interface = mdr::contact::LayerInterface::sliding};
    const double width = 3.0e-6, h = layer.thickness;
    const std::size_t cells = 37;
    const double dx = width / static_cast<double>(cells);
    const auto factored = mdr::drivers::layer_operator(layer, 0.3, width, cells);
    const mdr::contact::LayerKernel kernel(layer.interface, 0.3, 2.0 * width / h);
    for (std::size_t i = 0; i < cells; ++i) {
        const double x_i = (static_cast<double>(i) + 0.5) * dx;
        EXPECT_DOUBLE_EQ(factored->inverse_diagonal[i], 1.0 / factored->factor[i * cells + i]);
        for (std::size_t j = 0; j < cells; ++j) {
            const double x_j = (static_cast<double>(j) + 0.5) * dx;
            const double expected = (i == j ? 1.0 : 0.0) - dx / std::numbers::pi *
                                                               (kernel((x_i - x_j) / h) + kernel((x_i + x_j) / h)) / h;
            double product = 0.0;
            for (std::size_t k = 0; k < cells; ++k) {
                product += factored->factor[i * cells + k] * factored->factor[j * cells + k];
            }
            EXPECT_NEAR(factored->matrix[i * cells + j], expected, 1e-15) << i << ", " << j;
            EXPECT_NEAR(product, expected, 1e-13) << i << ", " << j;
            EXPECT_EQ(factored->factor_transposed[j * cells + i], factored->factor[i * cells + j]);
            if (j > i) {
                EXPECT_EQ(factored->factor[i * cells + j], 0.0);
            }
        }
    }
}

TEST(LayerOperator, AThreadKeepsItsLastOperatorForTheSameLayerAndCells) {
    const mdr::contact::Layer layer{.thickness = 2.0e-6};
    const auto first = mdr::drivers::layer_operator(layer, 0.5, 4.0e-6, 20);
    EXPECT_EQ(mdr::drivers::layer_operator(layer, 0.5, 4.0e-6, 20).get(), first.get());
    // Any argument changed: another operator (a thickness freed in a fit, the range of a force-controlled run).
    const auto thicker = mdr::drivers::layer_operator({.thickness = 2.5e-6}, 0.5, 4.0e-6, 20);
    EXPECT_NE(thicker.get(), first.get());
    EXPECT_NE(thicker->matrix[1], first->matrix[1]);
    const auto wider = mdr::drivers::layer_operator(layer, 0.5, 4.5e-6, 20);
    EXPECT_NE(wider->matrix[1], first->matrix[1]);
    EXPECT_EQ(mdr::drivers::layer_operator(layer, 0.5, 4.5e-6, 20).get(), wider.get());
}

}  // namespace
