#include "mdr/numerics/log_grid.hpp"

#include <cmath>

namespace mdr::numerics {

std::vector<double> log_grid(double lower, double upper, std::size_t count) {
    std::vector<double> grid(count);
    const double step = std::log(upper / lower) / static_cast<double>(count - 1);
    for (std::size_t i = 0; i < count; ++i) grid[i] = lower * std::exp(step * static_cast<double>(i));
    return grid;
}

}  // namespace mdr::numerics
