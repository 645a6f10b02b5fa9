// numerics::dot_product (src/numerics/dot_product.hpp): the eight partial sums and the tail beyond the last eight.

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "numerics/dot_product.hpp"

namespace {

TEST(DotProduct, EveryProductCountsWhateverTheSize) {
    // a_j = j + 1, b_j = 2: the sum is n (n + 1), exact in doubles; sizes below, at and beyond multiples of eight.
    for (std::size_t size = 0; size <= 41; ++size) {
        std::vector<double> a(size), b(size, 2.0);
        for (std::size_t j = 0; j < size; ++j) a[j] = static_cast<double>(j + 1);
        const double n = static_cast<double>(size);
        EXPECT_EQ(mdr::numerics::dot_product(a.data(), b.data(), size), n * (n + 1.0)) << size;
    }
}

}  // namespace
