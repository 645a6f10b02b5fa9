// The Mittag-Leffler oracle of the springpot tests checked itself: its two methods agree where both hold, and
// alpha = 1/2 has the closed form E_1/2(-x) = exp(x^2) erfc(x).

#include <gtest/gtest.h>

#include <cmath>

#include "reference/mittag_leffler.hpp"

namespace mdr::reference {
namespace {

TEST(MittagLefflerReference, SeriesAndTalbotAgree) {
    for (double alpha : {0.05, 0.2, 0.5, 0.8, 0.95}) {
        for (double x : {0.05, 0.1, 0.2, 0.35, 0.5}) {
            EXPECT_NEAR(mittag_leffler_talbot(alpha, x) / mittag_leffler_series(alpha, x), 1.0, 1e-9) << alpha << " " << x;
        }
    }
}

TEST(MittagLefflerReference, HalfOrderIsTheScaledComplementaryErrorFunction) {
    for (double x : {0.01, 0.3, 1.0, 2.0, 4.0, 8.0}) {
        EXPECT_NEAR(mittag_leffler(0.5, x) / (std::exp(x * x) * std::erfc(x)), 1.0, 1e-9) << x;
    }
}

TEST(MittagLefflerReference, LargeArgumentsFollowTheAsymptoticSeries) {
    // E_alpha(-x) = x^-1 / Gamma(1 - alpha) - x^-2 / Gamma(1 - 2 alpha) + O(x^-3).
    for (double alpha : {0.1, 0.3, 0.7}) {
        const double x = 1e4;
        const double asymptotic = 1.0 / (x * std::tgamma(1.0 - alpha)) - 1.0 / (x * x * std::tgamma(1.0 - 2.0 * alpha));
        EXPECT_NEAR(mittag_leffler(alpha, x) / asymptotic, 1.0, 1e-7) << alpha;
    }
}

}  // namespace
}  // namespace mdr::reference
