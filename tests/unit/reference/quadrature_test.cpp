#include "reference/quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mdr::reference {
namespace {

TEST(ReferenceQuadrature, IntegratesSmoothFunctionsToRoundOff) {
    // ∫_0^1 e^x dx = e − 1 and ∫_0^π sin = 2, exact values; tolerance 1e-14 relative.
    EXPECT_NEAR(integrate([](double x) { return std::exp(x); }, 0.0, 1.0), std::numbers::e - 1.0, 1e-14);
    EXPECT_NEAR(integrate([](double x) { return std::sin(x); }, 0.0, std::numbers::pi), 2.0, 2e-14);
}

TEST(ReferenceQuadrature, HandlesSquareRootEndpointAndSharpExponential) {
    // ∫_0^1 sqrt(x) dx = 2/3; ∫_0^10 exp(−(10 − x)/0.001) dx = 0.001 (1 − e^{−10000}); 1e-12 relative.
    EXPECT_NEAR(integrate([](double x) { return std::sqrt(x); }, 0.0, 1.0), 2.0 / 3.0, 1e-12);
    EXPECT_NEAR(integrate([](double x) { return std::exp(-(10.0 - x) / 1e-3); }, 0.0, 10.0), 1e-3, 1e-15);
}

TEST(ReferenceQuadrature, FindsBracketedRootAndRejectsUnbracketed) {
    // cos x = x has the root 0.7390851332151607 (Dottie number); requested 1e-14.
    const double root = find_root([](double x) { return std::cos(x) - x; }, 0.0, 1.0, 1e-14);
    EXPECT_NEAR(root, 0.7390851332151607, 2e-15);
    EXPECT_THROW(find_root([](double x) { return x * x + 1.0; }, -1.0, 1.0, 1e-12), std::invalid_argument);
}

}  // namespace
}  // namespace mdr::reference
