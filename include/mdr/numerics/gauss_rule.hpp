#pragma once
/// \file
/// Gauss-Legendre quadrature rules.

#include <cstddef>
#include <vector>

namespace mdr::numerics {

/// The n-point Gauss-Legendre rule on [0, 1]: nodes ascending, weights summing to 1 (Newton on P_n, to round-off).
struct GaussRule {
    std::vector<double> nodes;    ///< in [0, 1], ascending
    std::vector<double> weights;  ///< summing to 1
};
/// The rule with `points` >= 1 nodes.
GaussRule make_gauss_rule(std::size_t points);

}  // namespace mdr::numerics
