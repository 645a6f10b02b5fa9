#include "dot_product.hpp"

#include <array>

namespace mdr::numerics {

__attribute__((target_clones("avx2", "default"))) double dot_product(const double* a, const double* b,
                                                                      std::size_t size) {
    std::array<double, 8> partial{};
    std::size_t j = 0;
    for (; j + 8 <= size; j += 8) {
        for (std::size_t lane = 0; lane < 8; ++lane) partial[lane] += a[j + lane] * b[j + lane];
    }
    for (; j < size; ++j) partial[0] += a[j] * b[j];
    return ((partial[0] + partial[1]) + (partial[2] + partial[3])) +
           ((partial[4] + partial[5]) + (partial[6] + partial[7]));
}

}  // namespace mdr::numerics
