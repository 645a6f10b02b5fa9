#include "mdr/numerics/chi_squared.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace mdr::numerics {
namespace {

// Two and four degrees of freedom have closed forms: 1 - e^(-x/2) and 1 - e^(-x/2) (1 + x/2); one degree is
// erf(sqrt(x/2)). The points cover both branches (the series below a + 1, the continued fraction above).
TEST(ChiSquared, DistributionMeetsItsClosedForms) {
    for (const double x : {1e-6, 0.3, 1.0, 2.5, 7.0, 20.0, 60.0}) {
        EXPECT_NEAR(chi_squared_cdf(2.0, x), 1.0 - std::exp(-0.5 * x), 1e-14) << x;
        EXPECT_NEAR(chi_squared_cdf(4.0, x), 1.0 - std::exp(-0.5 * x) * (1.0 + 0.5 * x), 1e-14) << x;
        EXPECT_NEAR(chi_squared_cdf(1.0, x), std::erf(std::sqrt(0.5 * x)), 1e-14) << x;
    }
    EXPECT_EQ(chi_squared_cdf(3.0, 0.0), 0.0);
    EXPECT_EQ(chi_squared_cdf(3.0, -1.0), 0.0);
}

TEST(ChiSquared, QuantilesMeetClosedFormsAndTables) {
    for (const double p : {0.001, 0.025, 0.5, 0.975, 0.999}) {
        EXPECT_NEAR(chi_squared_quantile(2.0, p), -2.0 * std::log1p(-p), 1e-12 * (1.0 - 2.0 * std::log1p(-p))) << p;
    }
    // Abramowitz & Stegun, Table 26.8 (percentage points of the chi-squared distribution), to their 5-6 digits.
    EXPECT_NEAR(chi_squared_quantile(9.0, 0.975), 19.0228, 5e-4);
    EXPECT_NEAR(chi_squared_quantile(9.0, 0.025), 2.70039, 5e-5);
    EXPECT_NEAR(chi_squared_quantile(30.0, 0.975), 46.9792, 5e-4);
    EXPECT_NEAR(chi_squared_quantile(30.0, 0.025), 16.7908, 5e-4);
    EXPECT_NEAR(chi_squared_quantile(1.0, 0.95), 3.84146, 5e-5);
}

TEST(ChiSquared, RefusesWhatHasNoDistribution) {
    EXPECT_THROW(chi_squared_cdf(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(chi_squared_cdf(NAN, 1.0), std::invalid_argument);
    EXPECT_THROW(chi_squared_quantile(2.0, 0.0), std::invalid_argument);
    EXPECT_THROW(chi_squared_quantile(2.0, 1.0), std::invalid_argument);
    EXPECT_THROW(chi_squared_quantile(-1.0, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace mdr::numerics
