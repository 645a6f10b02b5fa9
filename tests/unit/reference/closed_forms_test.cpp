#include "reference/closed_forms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "reference/quadrature.hpp"

namespace mdr::reference {
namespace {

using std::numbers::pi;

constexpr double radius = 1e-2;      // sphere radius [m]
constexpr double modulus = 1e6;      // shear modulus [Pa]
constexpr double cone_angle = 0.2;   // flank angle [rad]

// F = 2 ∫_0^a 4G (d − g(x)) dx by quadrature: the MDR force of eqs. 11, 13, 21 for an elastic material.
double mdr_quadrature_force(const PowerLawIndenter& indenter, double depth) {
    const double a = indenter.radius_at_depth(depth);
    return 8.0 * modulus * integrate([&](double x) { return depth - indenter.mdr_profile(x); }, 0.0, a);
}

TEST(ReferenceClosedForms, IndenterProfilesMatchHandbook) {
    // Section 3 of equations.md: sphere g = x²/R (κ_2 = 2), cone g = (π/2) tanθ |x| (κ_1 = π/2); 1e-15.
    EXPECT_NEAR(sphere_indenter(radius).mdr_profile(3e-4), 9e-8 / radius, 1e-20);
    EXPECT_NEAR(cone_indenter(cone_angle).mdr_profile(3e-4), 0.5 * pi * std::tan(cone_angle) * 3e-4, 1e-18);
    EXPECT_NEAR(sphere_indenter(radius).kappa(), 2.0, 1e-15);
    EXPECT_NEAR(cone_indenter(cone_angle).kappa(), 0.5 * pi, 1e-15);
}

TEST(ReferenceClosedForms, HertzForceEqualsIntegratedPressureAndMdrIntegral) {
    // Hertz force vs 2π ∫ p r dr of the Hertz pressure and vs the MDR integral; 1e-12 relative.
    const double d = 1e-4;
    const double force = hertz_force(radius, modulus, d);
    const double a = hertz_contact_radius(radius, d);
    const double from_pressure =
        integrate([&](double r) { return 2.0 * pi * r * hertz_pressure(radius, modulus, d, r); }, 0.0, a);
    EXPECT_NEAR(from_pressure / force, 1.0, 1e-12);
    EXPECT_NEAR(mdr_quadrature_force(sphere_indenter(radius), d) / force, 1.0, 1e-12);
    EXPECT_NEAR(sphere_indenter(radius).radius_at_depth(d), a, 1e-15);
}

TEST(ReferenceClosedForms, ConeAndPowerLawForcesMatchMdrIntegral) {
    // Sneddon cone and the power law (n = 1, 2, 1.5) against the MDR quadrature; 1e-12 relative.
    const double d = 2e-5;
    const PowerLawIndenter cone = cone_indenter(cone_angle);
    EXPECT_NEAR(cone_force(cone_angle, modulus, d) / mdr_quadrature_force(cone, d), 1.0, 1e-12);
    EXPECT_NEAR(cone_contact_radius(cone_angle, d) / cone.radius_at_depth(d), 1.0, 1e-14);
    for (const PowerLawIndenter& indenter : {cone, sphere_indenter(radius), PowerLawIndenter{3e3, 1.5}}) {
        const double a = indenter.radius_at_depth(d);
        EXPECT_NEAR(indenter.depth_at_radius(a) / d, 1.0, 1e-14);
        EXPECT_NEAR(power_law_force(indenter, modulus, a) / mdr_quadrature_force(indenter, d), 1.0, 1e-12);
    }
}

TEST(ReferenceClosedForms, FlatPunchIsStiffnessTimesDepth) {
    // Boussinesq: contact stiffness 2 E* a = 8 G a, so F = 8 G a d; exact arithmetic, 1e-15.
    EXPECT_NEAR(flat_punch_force(1e-3, modulus, 1e-5) / (8.0 * modulus * 1e-3 * 1e-5), 1.0, 1e-15);
}

TEST(ReferenceClosedForms, Equation28EqualsDoubleIntegralAndLeeRadok) {
    // Eq. 28 derived independently: F = 8 v0 ∫_0^{a(t)} Φ(t − t_c(x)) dx (double quadrature of G, eq. 16, 21)
    // and the Lee–Radok quadrature; 1e-11 relative. Elastic limit G1 = 0 gives Sneddon, 1e-14.
    const double v0 = 1e-5;
    const double G_inf = 1e6;
    const double G1 = 3e6;
    const double tau1 = 0.7;
    const PronyMaterial material{G_inf, 0.0, {{G1, tau1}}};
    const PowerLawIndenter cone = cone_indenter(cone_angle);
    const PiecewiseLinear ramp{{0.0, 5.0}, {0.0, 5.0 * v0}};
    for (double t : {0.1, 0.7, 2.0, 5.0}) {
        const double closed = cone_ramp_force_standard_solid(cone_angle, v0, G_inf, G1, tau1, t);
        const double a = cone_contact_radius(cone_angle, v0 * t);
        const double double_integral = 8.0 * v0 * integrate([&](double x) {
            const double t_c = cone.mdr_profile(x) / v0;
            return integrate([&](double s) { return material.relaxation(s); }, 0.0, t - t_c);
        }, 0.0, a);
        EXPECT_NEAR(closed / double_integral, 1.0, 1e-11) << "t = " << t;
        EXPECT_NEAR(closed / lee_radok_force(cone, material, ramp, t), 1.0, 1e-11) << "t = " << t;
        EXPECT_NEAR(cone_ramp_force_standard_solid(cone_angle, v0, G_inf, 0.0, tau1, t) /
                        cone_force(cone_angle, G_inf, v0 * t), 1.0, 1e-14);
    }
}

TEST(ReferenceClosedForms, Equation33SolvesKelvinVoigtCreepEquation) {
    // Eq. 32: F0 = (16/(3R)) [G a³ + η d(a³)/dt], checked with a central difference (relative 1e-7);
    // a(∞) is the Hertz radius at F0 (1e-12).
    const double eta = 2e5;
    const double force = 0.5;
    for (double t : {0.02, 0.1, 0.5}) {
        const auto cube = [&](double s) { return std::pow(kelvin_voigt_sphere_creep_radius(radius, modulus, eta, force, s), 3); };
        const double h = 1e-5;
        const double rate = (cube(t + h) - cube(t - h)) / (2.0 * h);
        EXPECT_NEAR(16.0 / (3.0 * radius) * (modulus * cube(t) + eta * rate) / force, 1.0, 1e-7) << "t = " << t;
    }
    const double a_final = kelvin_voigt_sphere_creep_radius(radius, modulus, eta, force, 100.0);
    EXPECT_NEAR(hertz_force(radius, modulus, a_final * a_final / radius) / force, 1.0, 1e-12);
}

TEST(ReferenceClosedForms, LeeRadokMatchesHertzAndTimeDomainQuadrature) {
    // Elastic: Hertz at d(t), 1e-12. Maxwell sphere on a ramp–hold–ramp history vs ∫ G(t − t') Ḟ1(t') dt' in
    // time with t' = u² near t' = 0 (a different variable and integrand), 1e-10. Dashpot adds η·8a·ḋ, 1e-12.
    const PowerLawIndenter sphere = sphere_indenter(radius);
    const PiecewiseLinear history{{0.0, 1.0, 1.5, 2.5}, {0.0, 1e-4, 1e-4, 1.6e-4}};
    for (double t : {0.5, 1.0, 1.2, 2.0, 2.5})
        EXPECT_NEAR(lee_radok_force(sphere, PronyMaterial{modulus, 0.0, {}}, history, t) /
                        hertz_force(radius, modulus, history.value(t)), 1.0, 1e-12);
    const PronyMaterial maxwell{0.0, 0.0, {{modulus, 0.4}}};
    const auto elastic_rate = [&](double s) {  // dF1/dt = 8 a ḋ at unit modulus
        return 8.0 * sphere.radius_at_depth(history.value(s)) * history.slope(s);
    };
    for (double t : {0.6, 1.3, 2.2}) {
        double expected = integrate([&](double u) { return 2.0 * u * maxwell.relaxation(t - u * u) * elastic_rate(u * u); },
                                    0.0, std::sqrt(std::min(t, 1.0)));
        if (t > 1.5) expected += integrate([&](double s) { return maxwell.relaxation(t - s) * elastic_rate(s); }, 1.5, t);
        EXPECT_NEAR(lee_radok_force(sphere, maxwell, history, t) / expected, 1.0, 1e-10) << "t = " << t;
    }
    const PronyMaterial kelvin_voigt{modulus, 3e5, {}};
    const double t = 2.0;
    const double expected = hertz_force(radius, modulus, history.value(t)) +
                            3e5 * 8.0 * sphere.radius_at_depth(history.value(t)) * history.slope(t);
    EXPECT_NEAR(lee_radok_force(sphere, kelvin_voigt, history, t) / expected, 1.0, 1e-12);
    EXPECT_THROW(lee_radok_force(sphere, maxwell, PiecewiseLinear{{0.0, 1.0, 2.0}, {0.0, 1e-4, 0.0}}, 1.5),
                 std::invalid_argument);
}

}  // namespace
}  // namespace mdr::reference
