// numerics::make_gauss_rule: the closed forms of the 2- and 3-point rules, and for rules up to a layer's widest
// contact (600 nodes) the defining property, exactness for polynomials of degree 2n - 1 on [0, 1], checked on
// Legendre's shifted polynomials (their integrals 1 for degree 0, else 0; monomials of high degree would cancel).

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "mdr/numerics/gauss_rule.hpp"

namespace {

using mdr::numerics::make_gauss_rule;

TEST(GaussRule, TwoAndThreePointsAreTheClosedForms) {
    const auto two = make_gauss_rule(2);
    EXPECT_NEAR(two.nodes[0], 0.5 - 0.5 / std::sqrt(3.0), 1e-16);
    EXPECT_NEAR(two.nodes[1], 0.5 + 0.5 / std::sqrt(3.0), 1e-16);
    EXPECT_NEAR(two.weights[0], 0.5, 1e-15);
    const auto three = make_gauss_rule(3);
    EXPECT_NEAR(three.nodes[0], 0.5 - 0.5 * std::sqrt(0.6), 1e-16);
    EXPECT_EQ(three.nodes[1], 0.5);
    EXPECT_NEAR(three.weights[0], 5.0 / 18.0, 1e-15);
    EXPECT_NEAR(three.weights[1], 8.0 / 18.0, 1e-15);
}

TEST(GaussRule, IntegratesLegendrePolynomialsOfDegreeBelowTwiceItsNodes) {
    for (std::size_t n = 1; n <= 600; n += (n < 20 ? 1 : 37)) {
        const auto rule = make_gauss_rule(n);
        ASSERT_EQ(rule.nodes.size(), n);
        for (std::size_t i = 0; i + 1 < n; ++i) EXPECT_LT(rule.nodes[i], rule.nodes[i + 1]) << n;
        // sum_i w_i P_k(2 x_i - 1) for every k < 2n by the recurrence at each node: 1 for k = 0, else 0.
        std::vector<double> sums(2 * n, 0.0);
        for (std::size_t i = 0; i < n; ++i) {
            const double x = 2.0 * rule.nodes[i] - 1.0;
            double previous = 1.0, current = x;
            sums[0] += rule.weights[i];
            sums[1] += rule.weights[i] * x;
            for (std::size_t k = 2; k < 2 * n; ++k) {
                const auto kk = static_cast<double>(k);
                const double next = ((2.0 * kk - 1.0) * x * current - (kk - 1.0) * previous) / kk;
                previous = current;
                current = next;
                sums[k] += rule.weights[i] * current;
            }
        }
        EXPECT_NEAR(sums[0], 1.0, 1e-14) << n;
        for (std::size_t k = 1; k < 2 * n; ++k) EXPECT_NEAR(sums[k], 0.0, 1e-13) << n << " degree " << k;
    }
}

}  // namespace
