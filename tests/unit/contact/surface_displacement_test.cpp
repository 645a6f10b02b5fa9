#include "mdr/contact/stress.hpp"
#include "mdr/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using mdr::contact::surface_displacement;
constexpr double pi = std::numbers::pi;
constexpr double R = 0.01;
constexpr double depth = 1e-5;
const double a = std::sqrt(R * depth);  // eq. (31)

/// Hertz surface displacement: d - r^2/(2R) inside the contact, and outside
/// w(r) = (1/(pi R)) [(2a^2 - r^2) asin(a/r) + a sqrt(r^2 - a^2)] (Johnson, Contact Mechanics, eq. 3.42).
double hertz_displacement(double r) {
    if (r <= a) return depth - r * r / (2.0 * R);
    return ((2.0 * a * a - r * r) * std::asin(a / r) + a * std::sqrt(r * r - a * a)) / (pi * R);
}

/// w(r) from w1D = d - x^2/R inside the contact, 0 outside, on n elements covering [0, 2a].
std::vector<double> hertz_from_elements(int n, const std::vector<double>& radii) {
    const double spacing = 2.0 * a / n;
    std::vector<double> w1d(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < w1d.size(); ++i) {
        const double x = (static_cast<double>(i) + 0.5) * spacing;
        w1d[i] = x < a ? depth - x * x / R : 0.0;  // eq. (13)
    }
    return surface_displacement(spacing, w1d, radii);
}

TEST(SurfaceDisplacement, Hertz) {
    const std::vector<double> radii = {0.0, 0.2 * a, 0.5 * a, 0.9 * a, 1.1 * a, 1.5 * a, 2.0 * a, 3.0 * a};
    const auto w = hertz_from_elements(800, radii);
    for (std::size_t j = 0; j < radii.size(); ++j) {
        // Abel transform of eq. (10) against Hertz: 5e-6 d at 800 elements (measured <= 1.6e-6 d)
        EXPECT_NEAR(w[j], hertz_displacement(radii[j]), 5e-6 * depth) << "r/a = " << radii[j] / a;
    }
    // at the contact edge the kink of w1D costs accuracy: 2.6e-5 d measured
    EXPECT_NEAR(hertz_from_elements(800, {a})[0], hertz_displacement(a), 5e-5 * depth);
}

TEST(SurfaceDisplacement, HertzConvergenceOrder) {
    const std::vector<double> radii = {0.5 * a, 0.9 * a, 1.5 * a, 3.0 * a};
    std::vector<std::vector<double>> errors;
    for (const int n : {200, 400, 800}) {
        const auto w = hertz_from_elements(n, radii);
        std::vector<double> e;
        for (std::size_t j = 0; j < radii.size(); ++j) e.push_back(std::abs(w[j] - hertz_displacement(radii[j])));
        errors.push_back(e);
    }
    for (std::size_t k = 0; k + 1 < errors.size(); ++k) {
        for (std::size_t j = 0; j < radii.size(); ++j) {
            // piecewise linear w1D, exact integration of each piece: second order away from r = a
            const double order = std::log2(errors[k][j] / errors[k + 1][j]);
            EXPECT_GT(order, 1.9) << "r/a = " << radii[j] / a;
            EXPECT_LT(order, 2.1) << "r/a = " << radii[j] / a;
        }
    }
}

TEST(SurfaceDisplacement, ConstantDisplacementIsThePunchSolution) {
    // w1D = d up to the last centre x_last: w = d inside, (2/pi) d asin(x_last / r) outside (Boussinesq).
    const int n = 40;
    const double spacing = 1e-5;
    const double x_last = (n - 0.5) * spacing;
    const std::vector<double> w1d(n, depth);
    const std::vector<double> radii = {0.0, 0.3 * x_last, x_last, 1.2 * x_last, 5.0 * x_last};
    const auto w = surface_displacement(spacing, w1d, radii);
    for (std::size_t j = 0; j < radii.size(); ++j) {
        const double exact = radii[j] <= x_last ? depth : 2.0 / pi * depth * std::asin(x_last / radii[j]);
        EXPECT_NEAR(w[j], exact, 1e-14 * depth) << "r = " << radii[j];
    }
}

TEST(SurfaceDisplacement, EmptyAndInvalid) {
    EXPECT_EQ(surface_displacement(1.0, {}, std::vector<double>{0.0, 2.0}), (std::vector<double>{0.0, 0.0}));
    EXPECT_THROW(surface_displacement(-1.0, std::vector<double>{1.0}, std::vector<double>{0.0}), mdr::InvalidInput);
    EXPECT_THROW(surface_displacement(1.0, std::vector<double>{INFINITY}, std::vector<double>{0.0}), mdr::InvalidInput);
    EXPECT_THROW(surface_displacement(1.0, std::vector<double>{1.0}, std::vector<double>{-0.5}), mdr::InvalidInput);
}

}  // namespace
