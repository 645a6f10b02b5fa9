#include "mdr/contact/stress.hpp"
#include "mdr/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using mdr::contact::stress_from_line_load;
constexpr double pi = std::numbers::pi;

// Incompressible half-space: E* = 4 G (eq. 11).
constexpr double G = 1e6;
constexpr double E_star = 4.0 * G;
constexpr double R = 0.01;
constexpr double depth = 1e-5;
const double a = std::sqrt(R * depth);        // eq. (31)
const double p0 = 2.0 * E_star * a / (pi * R);  // Hertz: p0 = 2 E* a / (pi R) = 8 G a / (pi R)

/// The line load q_i = 4 G w1D(x_i) at n element centres x_i = (i + 1/2) a / n (eq. 16, 22 for an elastic body).
std::vector<double> line_load(int n, const std::function<double(double)>& w1d) {
    std::vector<double> q(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = 4.0 * G * w1d((static_cast<double>(i) + 0.5) * a / n);
    return q;
}

std::vector<double> hertz_pressure(int n, const std::vector<double>& radii) {
    const auto q = line_load(n, [](double x) { return depth - x * x / R; });  // eq. (13) with g = x^2/R
    return stress_from_line_load(a / n, q, a, 0.0, radii);
}

double hertz_exact(double r) { return p0 * std::sqrt(1.0 - r * r / (a * a)); }

TEST(Pressure, HertzAt1000Elements) {
    std::vector<double> radii;
    for (int k = 1; k <= 18; ++k) radii.push_back(0.05 * k * a);
    const auto p = hertz_pressure(1000, radii);
    for (std::size_t j = 0; j < radii.size(); ++j) {
        // eq. (23) against Hertz p = p0 sqrt(1 - r^2/a^2): 1e-4 p0 for 0.05 a <= r <= 0.9 a (measured <= 1.3e-5)
        EXPECT_NEAR(p[j], hertz_exact(radii[j]), 1e-4 * p0) << "r/a = " << radii[j] / a;
    }
    // At r = 0 (inside the first element, where q is taken flat) the error is first order, about 0.35 p0 / n.
    EXPECT_NEAR(hertz_pressure(1000, {0.0})[0], p0, 1e-3 * p0);
}

TEST(Pressure, HertzConvergenceOrder) {
    // The edges of the elements sit at r = k a / 10 for every n below, so the error constant is the same.
    const std::vector<double> radii = {0.1 * a, 0.3 * a, 0.5 * a, 0.7 * a, 0.9 * a};
    const std::vector<int> sizes = {100, 200, 400, 800};
    std::vector<std::vector<double>> errors;
    for (const int n : sizes) {
        const auto p = hertz_pressure(n, radii);
        std::vector<double> e;
        for (std::size_t j = 0; j < radii.size(); ++j) e.push_back(std::abs(p[j] - hertz_exact(radii[j])));
        errors.push_back(e);
    }
    for (std::size_t k = 0; k + 1 < sizes.size(); ++k) {
        for (std::size_t j = 0; j < radii.size(); ++j) {
            // Measured order 1.50-1.58, not 2: q' is piecewise constant, and its O(dx) error on the element
            // next to x = r meets the kernel 1/sqrt(x^2 - r^2) of eq. (23), giving dx^1.5 / sqrt(r).
            const double order = std::log2(errors[k][j] / errors[k + 1][j]);
            EXPECT_GT(order, 1.4) << "n = " << sizes[k] << ", r/a = " << radii[j] / a;
            EXPECT_LT(order, 1.65) << "n = " << sizes[k] << ", r/a = " << radii[j] / a;
        }
    }
}

TEST(Pressure, SneddonCone) {
    const double theta = 0.3;
    const double slope = 0.5 * pi * std::tan(theta);  // g = (pi/2) x tan(theta) (eq. 25)
    const auto q = line_load(200, [&](double x) { return slope * (a - x); });  // d = g(a) (eq. 15)
    const std::vector<double> radii = {0.01 * a, 0.2 * a, 0.5 * a, 0.8 * a, 0.999 * a};
    const auto p = stress_from_line_load(a / 200, q, a, 0.0, radii);
    const double scale = E_star * std::tan(theta) / 2.0;
    for (std::size_t j = 0; j < radii.size(); ++j) {
        // Sneddon: p = (E* tan(theta) / 2) arccosh(a/r); q is linear, so the closed form is exact (1e-12)
        EXPECT_NEAR(p[j], scale * std::acosh(a / radii[j]), 1e-12 * scale) << "r/a = " << radii[j] / a;
    }
}

TEST(Pressure, BoussinesqFlatPunch) {
    const int n = 50;
    const std::vector<double> q(n, 4.0 * G * depth);
    const std::vector<double> radii = {0.0, 0.3 * a, 0.9 * a, 0.999999 * a, a, 2.0 * a};
    const auto p = stress_from_line_load(a / n, q, a, 4.0 * G * depth, radii);
    for (std::size_t j = 0; j + 2 < radii.size(); ++j) {
        // Boussinesq: p = E* d / (pi sqrt(a^2 - r^2)), from the edge jump alone (exact, 1e-13 relative)
        const double exact = E_star * depth / (pi * std::sqrt((a - radii[j]) * (a + radii[j])));
        EXPECT_NEAR(p[j], exact, 1e-13 * exact) << "r/a = " << radii[j] / a;
    }
    EXPECT_EQ(p[4], 0.0);  // r >= a: outside the contact
    EXPECT_EQ(p[5], 0.0);
}

TEST(Pressure, EdgeOnTheLastCentre) {
    // contact_radius = last centre: the last segment is empty and q jumps from q_last to 0 at a.
    const int n = 10;
    const double spacing = a / (n - 0.5);
    const std::vector<double> q(n, 3.0);
    const auto p = stress_from_line_load(spacing, q, a, 7.0, std::vector<double>{0.5 * a});
    EXPECT_NEAR(p[0], 3.0 / (pi * std::sqrt(0.75) * a), 1e-13 * p[0]);
}

TEST(Pressure, NoElementsNoStress) {
    const auto p = stress_from_line_load(1e-6, {}, 0.0, 0.0, std::vector<double>{0.0, 1e-6});
    EXPECT_EQ(p, (std::vector<double>{0.0, 0.0}));
}

TEST(Pressure, Validation) {
    const std::vector<double> q = {1.0, 1.0};
    const std::vector<double> r = {0.0};
    EXPECT_THROW(stress_from_line_load(0.0, q, 1.0, 0.0, r), mdr::InvalidInput);
    EXPECT_THROW(stress_from_line_load(1.0, std::vector<double>{1.0, NAN}, 2.0, 0.0, r), mdr::InvalidInput);
    EXPECT_THROW(stress_from_line_load(1.0, q, 2.0, 0.0, std::vector<double>{-1.0}), mdr::InvalidInput);
    EXPECT_THROW(stress_from_line_load(1.0, q, 2.0, INFINITY, r), mdr::InvalidInput);
    try {
        stress_from_line_load(1.0, q, 1.2, 0.0, r);
        FAIL() << "no InvalidInput thrown";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_STREQ(error.what(), "contact_radius = 1.2: must be >= the last element centre 1.5");
    }
    try {
        stress_from_line_load(1.0, std::vector<double>{1.0, NAN}, 2.0, 0.0, r);
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(error.key(), "q[1]");
    }
}

}  // namespace
