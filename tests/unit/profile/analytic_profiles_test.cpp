#include "mdr/profile/profile.hpp"
#include "quadrature.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace {

using mdr::profile::Profile;
constexpr double pi = std::numbers::pi;
constexpr double inf = std::numeric_limits<double>::infinity();

/// Eq. (9) evaluated independently: r = x sin(phi) and phi = (pi/2) u^2 remove the end-point singularities of
/// f'(r) / sqrt(x^2 - r^2) (and of f' ~ r^(n-1) for power laws with n < 1):
/// g(x) = x int_0^1 pi u f'(x sin(pi u^2 / 2)) du.
double equivalent_by_eq9(const std::function<double(double)>& slope, double x) {
    const auto integrand = [&](double u) { return pi * u * slope(x * std::sin(0.5 * pi * u * u)); };
    // The lower limit 1e-100 instead of 0 avoids evaluating f'(0) = infinity for n < 1; the integrand is
    // bounded, so the part left out is below 1e-99 of it.
    return x * mdr::test::adaptive_simpson(integrand, 1e-100, 1.0, 1e-13);
}

/// Eq. (10) evaluated independently with x = r sin(phi): f(r) = (2/pi) int_0^{pi/2} g(r sin phi) dphi.
double gap_by_eq10(const Profile& profile, double r) {
    const auto integrand = [&](double phi) { return profile.equivalent(r * std::sin(phi)); };
    return 2.0 / pi * mdr::test::adaptive_simpson(integrand, 0.0, 0.5 * pi, 1e-13);
}

struct Shape {
    std::string name;
    std::function<std::unique_ptr<Profile>()> make;
    std::function<double(double)> gap;    // f(r) written out independently
    std::function<double(double)> slope;  // f'(r)
};

std::vector<Shape> shapes() {
    const double R = 0.01;
    const double tan20 = std::tan(20.0 * pi / 180.0);
    const double tan60 = std::tan(60.0 * pi / 180.0);
    std::vector<Shape> list = {
        {"sphere", [=] { return mdr::profile::make_sphere(R); }, [=](double r) { return r * r / (2.0 * R); },
         [=](double r) { return r / R; }},
        {"cone20", [] { return mdr::profile::make_cone(20.0); }, [=](double r) { return r * tan20; },
         [=](double) { return tan20; }},
        {"cone60", [] { return mdr::profile::make_cone(60.0); }, [=](double r) { return r * tan60; },
         [=](double) { return tan60; }},
    };
    for (const double n : {0.5, 1.5, 3.0, 4.5}) {
        const double c = 2.0;
        list.push_back({"power law n = " + std::to_string(n), [=] { return mdr::profile::make_power_law(c, n); },
                        [=](double r) { return c * std::pow(r, n); },
                        [=](double r) { return c * n * std::pow(r, n - 1.0); }});
    }
    return list;
}

TEST(AnalyticProfiles, EquivalentMatchesEq9Quadrature) {
    for (const Shape& shape : shapes()) {
        const auto profile = shape.make();
        for (const double x : {1e-5, 3e-4, 1e-3, 0.2}) {
            const double expected = equivalent_by_eq9(shape.slope, x);
            // eq. (9), quadrature tolerance 1e-13 relative: agreement to 1e-10 relative
            EXPECT_NEAR(profile->equivalent(x), expected, 1e-10 * expected) << shape.name << " x = " << x;
            // g is even (eq. 9 uses |x|)
            EXPECT_EQ(profile->equivalent(-x), profile->equivalent(x)) << shape.name;
            // the gap itself, against f written out in the test
            EXPECT_NEAR(profile->gap(x), shape.gap(x), 1e-14 * shape.gap(x)) << shape.name;
        }
        EXPECT_EQ(profile->equivalent(0.0), 0.0) << shape.name;
    }
}

TEST(AnalyticProfiles, GapRecoveredFromEquivalentByEq10) {
    const auto sphere = mdr::profile::make_sphere(0.01);
    const auto cone = mdr::profile::make_cone(30.0);
    const auto power = mdr::profile::make_power_law(5.0, 3.0);
    for (const Profile* profile : {sphere.get(), cone.get(), power.get()}) {
        for (const double r : {1e-4, 1e-3, 0.05}) {
            // eq. (10) inverts eq. (9): f recovered to 1e-10 relative
            EXPECT_NEAR(gap_by_eq10(*profile, r), profile->gap(r), 1e-10 * profile->gap(r)) << profile->describe();
        }
    }
}

TEST(AnalyticProfiles, PowerLawReducesToSphereAndCone) {
    const double R = 0.02;
    const auto sphere = mdr::profile::make_sphere(R);
    const auto parabola = mdr::profile::make_power_law(1.0 / (2.0 * R), 2.0);
    const auto cone = mdr::profile::make_cone(25.0);
    const auto linear = mdr::profile::make_power_law(std::tan(25.0 * pi / 180.0), 1.0);
    for (const double x : {1e-4, 2e-3, 0.3}) {
        // kappa_2 = 2: f = r^2/(2R) gives g = x^2/R (eq. 30), to rounding
        EXPECT_NEAR(parabola->equivalent(x), sphere->equivalent(x), 1e-14 * sphere->equivalent(x));
        // kappa_1 = pi/2: f = r tan(theta) gives g = (pi/2) x tan(theta) (eq. 25), to rounding
        EXPECT_NEAR(linear->equivalent(x), cone->equivalent(x), 1e-14 * cone->equivalent(x));
    }
    // A large exponent stays finite: kappa_n = sqrt(pi) Gamma(z + 1) / Gamma(z + 1/2), z = n/2, against the
    // asymptotic series sqrt(pi z) (1 + 1/(8z) + 1/(128 z^2)), whose next term is below 1e-9 at z = 200.
    const auto steep = mdr::profile::make_power_law(1.0, 400.0);
    const double z = 200.0;
    const double kappa = std::sqrt(pi * z) * (1.0 + 1.0 / (8.0 * z) + 1.0 / (128.0 * z * z));
    EXPECT_NEAR(steep->equivalent(1.0), kappa, 1e-9 * kappa);
}

TEST(AnalyticProfiles, ContactRadiusInvertsEquivalent) {
    for (const Shape& shape : shapes()) {
        const auto profile = shape.make();
        for (const double depth : {1e-9, 1e-6, 1e-3}) {
            const double a = profile->contact_radius(depth);
            // eq. (15): d = g(a), closed-form inverse to rounding
            EXPECT_NEAR(profile->equivalent(a), depth, 1e-13 * depth) << shape.name;
        }
        EXPECT_EQ(profile->contact_radius(0.0), 0.0) << shape.name;
        EXPECT_EQ(profile->contact_radius(-1e-6), 0.0) << shape.name;
        EXPECT_EQ(profile->max_radius(), inf) << shape.name;
        EXPECT_FALSE(profile->is_flat_punch()) << shape.name;
    }
    // Hertz: a^2 = R d (eq. 31)
    EXPECT_NEAR(mdr::profile::make_sphere(0.01)->contact_radius(1e-5), std::sqrt(1e-7), 1e-15 * std::sqrt(1e-7));
    // cone: a = 2 d / (pi tan(theta)) (eq. 26 with d = v0 t)
    EXPECT_NEAR(mdr::profile::make_cone(45.0)->contact_radius(1e-5), 2e-5 / pi, 1e-15);
}

TEST(FlatPunch, RigidWallBeyondItsRadius) {
    const double a = 1e-3;
    const auto punch = mdr::profile::make_flat_punch(a);
    EXPECT_TRUE(punch->is_flat_punch());
    EXPECT_EQ(punch->max_radius(), a);
    for (const double x : {0.0, 0.5e-3, -0.9e-3, 1e-3}) {
        EXPECT_EQ(punch->equivalent(x), 0.0);  // eq. (9) with f' = 0 inside
        EXPECT_EQ(punch->gap(x), 0.0);
    }
    EXPECT_EQ(punch->equivalent(1.000001e-3), inf);
    EXPECT_EQ(punch->equivalent(-2e-3), inf);
    EXPECT_EQ(punch->gap(2e-3), inf);
    EXPECT_EQ(punch->contact_radius(1e-9), a);
    EXPECT_EQ(punch->contact_radius(1.0), a);
    EXPECT_EQ(punch->contact_radius(0.0), 0.0);
    EXPECT_EQ(punch->contact_radius(-1.0), 0.0);
}

// The tip radius of eq. 30 (g = x^2/R): a sphere has one, its R; a cone (eq. 25, g linear in |x|) and a flat punch
// have none.
TEST(AnalyticProfiles, OnlyASphereHasATipRadius) {
    EXPECT_EQ(mdr::profile::make_sphere(0.01)->tip_radius(), 0.01);
    EXPECT_FALSE(mdr::profile::make_cone(30.0)->tip_radius().has_value());
    EXPECT_FALSE(mdr::profile::make_flat_punch(0.001)->tip_radius().has_value());
}

TEST(AnalyticProfiles, Describe) {
    EXPECT_EQ(mdr::profile::make_sphere(0.01)->describe(), "sphere R = 0.01");
    EXPECT_EQ(mdr::profile::make_cone(30.0)->describe(), "cone slope_deg = 30 (half_angle_deg = 60)");
    EXPECT_EQ(mdr::profile::make_cone_from_half_angle(70.3)->describe(), "cone slope_deg = 19.7 (half_angle_deg = 70.3)");
    EXPECT_EQ(mdr::profile::make_flat_punch(0.001)->describe(), "flat punch a = 0.001");
    EXPECT_EQ(mdr::profile::make_power_law(2.0, 1.5)->describe(), "power law c = 2, n = 1.5");
}

}  // namespace
