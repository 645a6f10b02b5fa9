#include "mdr/profile/profile.hpp"
#include "quadrature.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

namespace {

using mdr::profile::Profile;
constexpr double pi = std::numbers::pi;
constexpr double inf = std::numeric_limits<double>::infinity();

/// A table of f sampled at n points r_i = r_max (i / (n-1))^grading.
std::unique_ptr<Profile> sampled(const std::function<double(double)>& f, double r_max, int n, double grading = 1.0) {
    std::vector<double> r(static_cast<std::size_t>(n));
    std::vector<double> values(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
        r[i] = r_max * std::pow(static_cast<double>(i) / static_cast<double>(n - 1), grading);
        values[i] = f(r[i]);
    }
    r.back() = r_max;
    values.back() = f(r_max);
    return mdr::profile::make_table(r, values);
}

/// Eq. (9) integrated by parts so that only f (the profile's own gap()) is needed, not f':
/// g(x) = f(x) + int_0^{pi/2} (f(x) - f(x sin phi)) sin(phi) / cos^2(phi) dphi.
/// The integrand tends to x f'(x) / 2 at phi = pi/2, where the difference cancels; the last delta of the range
/// is taken as x f'(x) delta / 2 (error O(delta^3)), f'(x) by a central difference.
double equivalent_by_parts(const Profile& profile, double x) {
    const double fx = profile.gap(x);
    const auto integrand = [&](double phi) {
        return (fx - profile.gap(x * std::sin(phi))) * std::sin(phi) / (std::cos(phi) * std::cos(phi));
    };
    const double delta = 1e-4;
    const double step = 1e-7 * x;
    const double slope = (profile.gap(x + step) - profile.gap(x - step)) / (2.0 * step);
    return fx + mdr::test::adaptive_simpson(integrand, 0.0, 0.5 * pi - delta, 1e-13) + 0.5 * x * slope * delta;
}

double max_relative_error(const Profile& table, const Profile& exact, double x_min, double x_max) {
    double error = 0.0;
    for (int k = 0; k <= 997; ++k) {
        const double x = x_min + (x_max - x_min) * k / 997.0;
        error = std::max(error, std::abs(table.equivalent(x) / exact.equivalent(x) - 1.0));
    }
    return error;
}

TEST(TableProfile, SampledSphereReproducesEq30) {
    const double R = 0.01;
    const double r_max = 1e-3;
    const auto sphere = mdr::profile::make_sphere(R);
    const auto f = [&](double r) { return sphere->gap(r); };
    // The three-point knot slopes are exact for a quadratic, so the interpolant is the sphere itself at any
    // density: 20 points already suffice; the error is rounding (measured 5e-15 at 2000 points).
    for (const int n : {20, 200, 2000}) {
        for (const double grading : {1.0, 1.5}) {
            const auto table = sampled(f, r_max, n, grading);
            // eq. (30), g = x^2 / R, 1e-10 relative from x = r_max/1000 to r_max
            EXPECT_LT(max_relative_error(*table, *sphere, 1e-6, r_max), 1e-10) << n << " points";
            EXPECT_NEAR(table->gap(0.37e-3), f(0.37e-3), 1e-14 * f(0.37e-3));
        }
    }
}

TEST(TableProfile, SampledConeReproducesEq25) {
    const auto cone = mdr::profile::make_cone(20.0);
    const auto table = sampled([&](double r) { return cone->gap(r); }, 2e-3, 50);
    // eq. (25), g = (pi/2) x tan(theta), 1e-10 relative
    EXPECT_LT(max_relative_error(*table, *cone, 1e-6, 2e-3), 1e-10);
}

TEST(TableProfile, QuadratureExactForTheCubicInterpolant) {
    // A cubic table (the interpolant's cubic terms are active) and a step-like table (the Fritsch-Carlson
    // limiter is active): eq. (9) by the closed-form pieces against eq. (9) by parts from gap(), 1e-10 relative.
    const auto cubic = sampled([](double r) { return 1e4 * r * r * r; }, 1e-3, 40);
    const auto step =
        mdr::profile::make_table({0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0}, {0.0, 0.0, 0.1, 1.0, 1.0, 1.05, 2.0});
    for (const double fraction : {0.13, 0.5, 0.77, 0.999}) {
        const double x_cubic = 1e-3 * fraction;
        const double x_step = 6.0 * fraction;
        EXPECT_NEAR(cubic->equivalent(x_cubic), equivalent_by_parts(*cubic, x_cubic),
                    1e-10 * cubic->equivalent(x_cubic));
        EXPECT_NEAR(step->equivalent(x_step), equivalent_by_parts(*step, x_step), 1e-10 * step->equivalent(x_step));
    }
}

TEST(TableProfile, SmoothTableConvergesToAnalyticEquivalent) {
    // f = c r^3 is not reproduced by the interpolant; g converges with the knot slopes' O(h^2) error and faster.
    const auto power = mdr::profile::make_power_law(1e4, 3.0);
    const auto f = [&](double r) { return power->gap(r); };
    std::vector<double> errors;
    for (const int n : {400, 800, 1600}) errors.push_back(max_relative_error(*sampled(f, 1e-3, n), *power, 1e-4, 1e-3));
    // measured on x in [0.1, 1] r_max: 1.4e-5, 2.3e-6, 3.4e-7 (orders 2.6, 2.8)
    EXPECT_LT(errors[2], 1e-6);
    for (std::size_t i = 0; i + 1 < errors.size(); ++i) EXPECT_GT(std::log2(errors[i] / errors[i + 1]), 2.3);
}

TEST(TableProfile, MonotoneInterpolation) {
    const std::vector<double> r = {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0};
    const std::vector<double> f = {0.0, 0.0, 0.1, 1.0, 1.0, 1.05, 2.0};
    const auto table = mdr::profile::make_table(r, f);
    for (std::size_t i = 0; i < r.size(); ++i) EXPECT_NEAR(table->gap(r[i]), f[i], 1e-15);  // through the knots
    double previous = 0.0;
    for (int k = 0; k <= 6000; ++k) {
        const double value = table->gap(k * 1e-3);
        EXPECT_GE(value, previous) << "r = " << k * 1e-3;  // no overshoot: non-decreasing between knots
        previous = value;
    }
    EXPECT_EQ(table->gap(0.5), 0.0);  // a flat interval stays flat
    EXPECT_LE(table->gap(3.5), 1.0);  // and no overshoot above a plateau
}

TEST(TableProfile, ContactRadiusRoundTrip) {
    const double R = 0.01;
    const double r_max = 1e-3;
    const auto sphere = mdr::profile::make_sphere(R);
    const auto table = sampled([&](double r) { return sphere->gap(r); }, r_max, 300);
    for (const double depth : {1e-10, 1e-8, 3.3e-6, 5e-5, 1e-4}) {
        // eq. (31), a = sqrt(R d), inverted to 1e-14 relative
        EXPECT_NEAR(table->contact_radius(depth), std::sqrt(R * depth), 1e-14 * std::sqrt(R * depth));
    }
    const auto power = sampled([](double r) { return 1e4 * r * r * r; }, r_max, 100);
    for (const double depth : {1e-9, 1e-7, 2e-5}) {
        // eq. (15), d = g(a), round trip
        EXPECT_NEAR(power->equivalent(power->contact_radius(depth)), depth, 1e-13 * depth);
    }
    EXPECT_EQ(table->contact_radius(0.0), 0.0);
    EXPECT_EQ(table->contact_radius(-1.0), 0.0);
    EXPECT_EQ(table->contact_radius(2e-4), r_max);  // beyond g(r_max) = 1e-4: the wall at the table's end
}

TEST(TableProfile, ContactRadiusIsTheFirstCrossing) {
    // A cone flattened to a plateau: r f'(r) drops, so g rises and then falls (g is not monotone).
    const auto table =
        mdr::profile::make_table({0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0}, {0.0, 1.0, 2.0, 2.0, 2.0, 2.0, 2.0});
    double g_max = 0.0;
    for (int k = 0; k <= 6000; ++k) g_max = std::max(g_max, table->equivalent(k * 1e-3));
    ASSERT_GT(g_max, table->equivalent(6.0));
    for (const double depth : {0.5, 1.5, 0.99 * g_max}) {
        const double a = table->contact_radius(depth);
        EXPECT_NEAR(table->equivalent(a), depth, 1e-13 * depth);
        for (int k = 0; 1e-3 * k < a * (1.0 - 1e-12); ++k) EXPECT_LT(table->equivalent(k * 1e-3), depth);
    }
}

TEST(TableProfile, RangeAndDescription) {
    const auto table = mdr::profile::make_table({0.0, 1.0, 2.0}, {0.0, 0.5, 2.0});
    EXPECT_EQ(table->max_radius(), 2.0);
    EXPECT_FALSE(table->is_flat_punch());
    EXPECT_EQ(table->equivalent(2.0 * (1.0 + 1e-12)), inf);  // beyond the last r: wall
    EXPECT_EQ(table->gap(2.5), inf);
    EXPECT_LT(table->equivalent(2.0), inf);
    EXPECT_EQ(table->equivalent(-1.3), table->equivalent(1.3));
    EXPECT_EQ(table->equivalent(0.0), 0.0);
    EXPECT_EQ(table->describe(), "table 3 points, r_max = 2");
}

}  // namespace

namespace {

TEST(TableProfile, PiecewiseLinearKeepsTheKinkOfATruncatedCone) {
    // f = 0 for r < b, (r - b) tan(theta) beyond: eq. (9) gives g = x tan(theta) acos(b/x) for x > b, 0 inside.
    const double b = 1e-3, r_max = 4e-3, slope = std::tan(0.2);
    const auto table = mdr::profile::make_table({0.0, b, r_max}, {0.0, 0.0, (r_max - b) * slope},
                                                mdr::profile::Interpolation::linear);
    for (double x : {0.0, 0.5e-3, 1e-3, 1.0001e-3, 1.3e-3, 2e-3, 3.7e-3, 4e-3}) {
        const double exact = x > b ? x * slope * std::acos(b / x) : 0.0;
        EXPECT_NEAR(table->equivalent(x), exact, 1e-14 * r_max) << "x = " << x;
        EXPECT_NEAR(table->gap(x), x > b ? (x - b) * slope : 0.0, 1e-16) << "x = " << x;
    }
    EXPECT_NEAR(table->contact_radius(2e-3 * slope * std::acos(0.5)), 2e-3, 1e-15);
    // The monotone cubic rounds the kink: its g differs by far more.
    const auto cubic = mdr::profile::make_table({0.0, b, r_max}, {0.0, 0.0, (r_max - b) * slope});
    EXPECT_GT(std::abs(cubic->equivalent(1.3e-3) - 1.3e-3 * slope * std::acos(b / 1.3e-3)), 1e-6);
}

TEST(TableProfile, PiecewiseLinearConeIsTheCone) {
    const double slope = std::tan(0.2);
    const auto cone = mdr::profile::make_cone(0.2 * 180.0 / pi);
    const std::vector<double> r{0.0, 1e-3, 2.5e-3, 4e-3};
    std::vector<double> f;
    for (double radius : r) f.push_back(radius * slope);
    const auto table = mdr::profile::make_table(r, f, mdr::profile::Interpolation::linear);
    for (double x : {0.0, 0.3e-3, 1e-3, 2e-3, 3.9e-3}) {
        EXPECT_NEAR(table->equivalent(x), cone->equivalent(x), 1e-17) << "x = " << x;
    }
}

TEST(TableProfile, KinksAreThePointsWhereALinearTablesSlopeJumps) {
    using mdr::profile::Interpolation;
    using mdr::profile::make_table;
    // A flat tip of radius 1, a flank, a steeper flank: slopes 0, 1, 3 jump at r = 1 and 2.
    const auto stepped = make_table({0.0, 1.0, 2.0, 3.0}, {0.0, 0.0, 1.0, 4.0}, Interpolation::linear);
    EXPECT_EQ(stepped->kinks(), (std::vector<double>{1.0, 2.0}));
    EXPECT_EQ(stepped->flat_radius(), 1.0);
    // Collinear points of a cone (slopes equal to rounding) are no kink; the monotone cubic has none.
    const double slope = std::tan(0.3);
    const auto cone = make_table({0.0, 0.1, 0.7, 1.3}, {0.0, 0.1 * slope, 0.7 * slope, 1.3 * slope},
                                 Interpolation::linear);
    EXPECT_TRUE(cone->kinks().empty());
    EXPECT_EQ(cone->flat_radius(), 0.0);
    const auto smooth = make_table({0.0, 1.0, 2.0, 3.0}, {0.0, 0.0, 1.0, 4.0});
    EXPECT_TRUE(smooth->kinks().empty());
    EXPECT_EQ(smooth->flat_radius(), 1.0);  // the cubic is exactly 0 on the flat interval too
    EXPECT_EQ(smooth->gap(0.999), 0.0);
    EXPECT_EQ(mdr::profile::make_flat_punch(0.5)->flat_radius(), 0.5);
    EXPECT_TRUE(mdr::profile::make_sphere(1.0)->kinks().empty());
    EXPECT_EQ(mdr::profile::make_sphere(1.0)->flat_radius(), 0.0);
}

}  // namespace
