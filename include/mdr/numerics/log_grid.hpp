#pragma once
/// \file
/// Logarithmically spaced grids (times, angular frequencies).

#include <cstddef>
#include <vector>

namespace mdr::numerics {

/// `count` values log-spaced from `lower` to `upper` (both > 0, count >= 2): lower (upper / lower)^(i / (count - 1)).
std::vector<double> log_grid(double lower, double upper, std::size_t count);

}  // namespace mdr::numerics
