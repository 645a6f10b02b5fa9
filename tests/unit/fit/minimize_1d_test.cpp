// minimize_1d (Brent's method): the minimum of smooth, kinked and bound-limited functions to the tolerance asked,
// in few evaluations on a parabola.

#include "fit/minimize_1d.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mdr::fit {
namespace {

TEST(Minimize1d, SmoothMinimumToTolerance) {
    int calls = 0;
    const auto f = [&](double x) {
        ++calls;
        return std::cosh(x - 0.3) + 0.1 * (x - 0.3) * (x - 0.3);
    };
    const Minimum1d minimum = minimize_1d(f, -2.0, 5.0, 1e-9, 100);
    EXPECT_NEAR(minimum.x, 0.3, 1e-8);
    EXPECT_NEAR(minimum.value, 1.0, 1e-15);
    EXPECT_LT(calls, 40);  // golden sections alone would need ~45 for 7 / 1e-9
}

TEST(Minimize1d, ParabolaInAFewSteps) {
    int calls = 0;
    const Minimum1d minimum = minimize_1d([&](double x) { return ++calls, (x - 1.25) * (x - 1.25); }, 0.0, 4.0, 1e-10);
    EXPECT_NEAR(minimum.x, 1.25, 1e-9);
    EXPECT_LT(calls, 15);
}

TEST(Minimize1d, KinkAndBounds) {
    EXPECT_NEAR(minimize_1d([](double x) { return std::abs(x - 0.7); }, 0.0, 1.0, 1e-9).x, 0.7, 1e-8);
    // Minimum at a bound: the bound to within the tolerance.
    EXPECT_NEAR(minimize_1d([](double x) { return x; }, 2.0, 3.0, 1e-9).x, 2.0, 1e-8);
    EXPECT_NEAR(minimize_1d([](double x) { return -x; }, 2.0, 3.0, 1e-9).x, 3.0, 1e-8);
}

TEST(Minimize1d, StopsAtTheCallLimit) {
    int calls = 0;
    minimize_1d([&](double x) { return ++calls, std::sin(50.0 * x); }, 0.0, 10.0, 1e-14, 12);
    EXPECT_LE(calls, 12);
}

}  // namespace
}  // namespace mdr::fit
