#include "mdr/fit/repeat_spread.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace mdr::fit {
namespace {

FitResult fit_of(double value, double error, bool converged = true) {
    FitResult fit;
    fit.names = {"material.G"};
    fit.values = {value};
    fit.standard_errors = {error};
    fit.converged = converged;
    return fit;
}

// Three values 1, 2, 3 with errors 1: mean 2, sample standard deviation 1; for 3 values the 95 % range of
// sigma / s is sqrt(2 / chi^2_2(0.975)) to sqrt(2 / chi^2_2(0.025)), chi^2_2(p) = -2 ln(1 - p).
TEST(RepeatSpread, MeanSpreadAndRangeOfThreeValues) {
    const auto spread = spread_of_repeats({fit_of(1.0, 1.0), fit_of(2.0, 1.0), fit_of(3.0, 1.0)});
    ASSERT_EQ(spread.keys.size(), 1U);
    const auto& key = spread.keys.front();
    EXPECT_EQ(key.count, 3U);
    EXPECT_DOUBLE_EQ(key.mean, 2.0);
    EXPECT_DOUBLE_EQ(key.standard_deviation, 1.0);
    EXPECT_DOUBLE_EQ(key.standard_error_of_mean, 1.0 / std::sqrt(3.0));
    EXPECT_DOUBLE_EQ(key.error_to_spread, 1.0);
    EXPECT_NEAR(key.consistent_low, std::sqrt(1.0 / -std::log(0.025)), 1e-12);
    EXPECT_NEAR(key.consistent_high, std::sqrt(1.0 / -std::log(0.975)), 1e-10);
    EXPECT_TRUE(spread.flags.empty());
}

TEST(RepeatSpread, ErrorsFarAboveOrBelowTheSpreadAreFlagged) {
    const auto large = spread_of_repeats({fit_of(1.0, 10.0), fit_of(2.0, 10.0), fit_of(3.0, 10.0)});
    ASSERT_EQ(large.flags.size(), 1U);
    EXPECT_NE(large.flags.front().find("model misfit"), std::string::npos) << large.flags.front();
    const auto small = spread_of_repeats({fit_of(1.0, 0.1), fit_of(2.0, 0.1), fit_of(3.0, 0.1)});
    ASSERT_EQ(small.flags.size(), 1U);
    EXPECT_NE(small.flags.front().find("differ by more than their noise"), std::string::npos) << small.flags.front();
}

TEST(RepeatSpread, LeavesOutFitsThatDidNotConvergeAndUndeterminedErrors) {
    const auto spread = spread_of_repeats({fit_of(1.0, 1.0), fit_of(100.0, 1.0, false), fit_of(3.0, NAN)});
    const auto& key = spread.keys.front();
    EXPECT_EQ(key.count, 2U);
    EXPECT_DOUBLE_EQ(key.mean, 2.0);
    EXPECT_TRUE(std::isnan(key.typical_error));
    EXPECT_TRUE(spread.flags.empty());
    const auto alone = spread_of_repeats({fit_of(1.0, 1.0), fit_of(2.0, 1.0, false)});
    EXPECT_EQ(alone.keys.front().count, 1U);
    EXPECT_TRUE(std::isnan(alone.keys.front().standard_deviation));
    FitResult other = fit_of(1.0, 1.0);
    other.names = {"material.G_inf"};
    EXPECT_THROW(spread_of_repeats({fit_of(1.0, 1.0), other}), std::invalid_argument);
}

// Batches of n values drawn from a normal distribution whose standard deviation is the fits' error: the flag fires
// in 5 % of them (binomial standard deviation 0.15 % over 20 000 batches; asserted within 0.6 %).
TEST(RepeatSpread, FlagsFivePercentOfBatchesWhoseValuesScatterByTheirErrors) {
    std::mt19937_64 generator(20261127);
    for (const int n : {3, 8}) {
        std::normal_distribution<double> draw(5.0, 0.7);
        constexpr int batches = 20000;
        int flagged = 0;
        for (int b = 0; b < batches; ++b) {
            std::vector<FitResult> fits;
            for (int i = 0; i < n; ++i) fits.push_back(fit_of(draw(generator), 0.7));
            flagged += spread_of_repeats(fits).flags.empty() ? 0 : 1;
        }
        EXPECT_NEAR(static_cast<double>(flagged) / batches, 0.05, 0.006) << n << " values a batch";
    }
}

}  // namespace
}  // namespace mdr::fit
