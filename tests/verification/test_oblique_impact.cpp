// Oblique impact of a rigid sphere with spin (eq. 37-51 with m v_t' = -F_x, I omega' = R F_x): gross sliding
// against the closed form, partial slip of an elastic sphere against an independent Mindlin–Deresiewicz/Jäger
// integration, the energy balance of a viscoelastic impact, the dimensionless groups, and convergence.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "convergence.hpp"
#include "reference/oblique_hertz.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

struct ObliqueImpact {
    double mass, radius, velocity, G_inf, G1, tau1;  ///< as the normal impact (G1 = 0: elastic)
    double friction, tangential_velocity, spin;
    double inertia_factor = 0.4;                     ///< I / (m R^2)
};

std::string oblique_case(const ObliqueImpact& c, const std::string& numerics = "") {
    const std::string material = c.G1 > 0.0 ? fmt::format("model = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}",
                                                         c.G_inf, c.G1, c.tau1)
                                            : fmt::format("model = \"elastic\"\nG = {}", c.G_inf);
    return fmt::format(R"(
[material]
{}
[indenter]
shape = "sphere"
R = {}
mass = {}
moment_of_inertia = {}
[load]
control = "impact"
velocity = {}
tangential_velocity = {}
spin = {}
[tangential]
friction = {}
{})",
                       material, c.radius, c.mass, c.inertia_factor * c.mass * c.radius * c.radius, c.velocity,
                       c.tangential_velocity, c.spin, c.friction, numerics);
}

constexpr ObliqueImpact elastic{0.01, 0.01, 0.1, 1e6, 0.0, 0.0, 0.3, 0.0, 0.0};

reference::ObliqueHertzResult hertz_reference(const ObliqueImpact& c) {
    return reference::oblique_hertz_impact({c.G_inf, c.radius, c.mass, c.inertia_factor * c.mass * c.radius * c.radius,
                                            c.friction, c.velocity, c.tangential_velocity, c.spin});
}

// A standard solid (p2 = 3) and the normal speed of test_impact.cpp's reference impact.
constexpr ObliqueImpact viscoelastic{0.01, 0.01, 0.1, 1e6, 3e6, 1e-3, 0.3, 0.0, 0.0};

// The case with the contact point's initial speed v_c0 = chi mu v_n0 (the incidence parameter), from the centre's
// translation (spin = 0) or from the spin alone (v_t = 0).
ObliqueImpact at_incidence(ObliqueImpact c, double chi, bool by_spin = false) {
    const double contact_velocity = chi * c.friction * c.velocity;
    if (by_spin) {
        c.spin = -contact_velocity / c.radius;
    } else {
        c.tangential_velocity = contact_velocity;
    }
    return c;
}

double initial_energy(const ObliqueImpact& c) {
    const double inertia = c.inertia_factor * c.mass * c.radius * c.radius;
    return 0.5 * c.mass * (c.velocity * c.velocity + c.tangential_velocity * c.tangential_velocity) +
           0.5 * inertia * c.spin * c.spin;
}

TEST(ObliqueImpact, GrossSlidingThroughoutMatchesTheClosedForm) {
    // Sliding all along, F_x = mu F_N at every instant: the tangential impulse is mu m v_n0 (1 + e), so
    // v_t(T) = v_t0 - mu (1 + e) v_n0 and omega(T) = omega0 + R mu m (1 + e) v_n0 / I, with e the normal restitution.
    ObliqueImpact c = viscoelastic;
    c.tangential_velocity = 1.0;
    c.spin = 20.0;
    c.inertia_factor = 0.3;  // a hollow-ish sphere: I is read, not assumed
    const auto result = run_toml(oblique_case(c));
    const auto& oblique = *result.impact->oblique;
    ASSERT_TRUE(oblique.slid_throughout);
    const double e = result.impact->restitution;
    ASSERT_LT(e, 0.9);  // the material dissipates: the impulse is not trivially 2 m v_n0
    const double impulse = c.friction * c.mass * (1.0 + e) * c.velocity;
    const double inertia = c.inertia_factor * c.mass * c.radius * c.radius;
    EXPECT_NEAR(oblique.impulse_ratio, c.friction, 1e-6 * c.friction);
    EXPECT_NEAR(oblique.rebound_tangential_velocity, c.tangential_velocity - impulse / c.mass,
                1e-6 * impulse / c.mass);
    EXPECT_NEAR(oblique.rebound_spin, c.spin + c.radius * impulse / inertia, 1e-6 * c.radius * impulse / inertia);
    const double slip_before = c.tangential_velocity - c.radius * c.spin;
    const double slip_after = oblique.rebound_tangential_velocity - c.radius * oblique.rebound_spin;
    EXPECT_NEAR(oblique.tangential_restitution, -slip_after / slip_before, 1e-12);
}

TEST(ObliqueImpact, ElasticPartialSlipMatchesMindlinDeresiewicz) {
    // From sticking (small chi; the compliance of the contact makes the contact point rebound, e_t > 0) through
    // partial slip to sliding throughout (chi >= 7 (1 + e)/2 for a solid sphere, e = 1 here), against the
    // independent Hertz / Mindlin–Deresiewicz–Jäger integration; default numerics.
    for (const double chi : {0.25, 1.0, 2.0, 3.0, 4.0, 5.0, 6.5, 8.0}) {
        for (const bool by_spin : {false, true}) {
            if (by_spin && chi != 2.0) continue;
            const ObliqueImpact c = at_incidence(elastic, chi, by_spin);
            const auto result = run_toml(oblique_case(c));
            const auto reference = hertz_reference(c);
            const auto& oblique = *result.impact->oblique;
            SCOPED_TRACE(fmt::format("chi = {}, by spin: {}", chi, by_spin));
            EXPECT_NEAR(oblique.tangential_restitution, reference.tangential_restitution, 1e-4);
            EXPECT_NEAR(oblique.impulse_ratio, reference.impulse_ratio, 1e-4 * c.friction);
            EXPECT_NEAR(oblique.rebound_spin, reference.spin, 1e-4 * c.velocity / c.radius);
            RecordProperty(fmt::format("tangential_restitution_error_chi_{}", chi),
                           fmt::format("{:.2e}", oblique.tangential_restitution - reference.tangential_restitution));
        }
    }
}

TEST(ObliqueImpact, ViscoelasticEnergyBalance) {
    // Kinetic energy lost (translation, rotation) = work on the material (stored and dissipated by the elements,
    // exact per step) + work of friction on the slip, each summed independently of the motion's integration.
    for (const double chi : {1.0, 3.0, 12.0}) {
        const ObliqueImpact c = at_incidence(viscoelastic, chi);
        const auto result = run_toml(oblique_case(c));
        const auto& oblique = *result.impact->oblique;
        SCOPED_TRACE(fmt::format("chi = {}", chi));
        const double balance =
            result.impact->dissipated_energy - oblique.material_dissipation - oblique.friction_dissipation;
        EXPECT_LT(std::abs(balance), 1e-6 * initial_energy(c));
        EXPECT_GT(oblique.friction_dissipation, 1e-3 * initial_energy(c));  // both parts are there
        EXPECT_GT(oblique.material_dissipation, 1e-2 * initial_energy(c));
        RecordProperty(fmt::format("energy_balance_chi_{}", chi), fmt::format("{:.2e}", balance / initial_energy(c)));
    }
}

TEST(ObliqueImpact, ResultsDependOnlyOnTheDimensionlessGroups) {
    // Eq. (40)'s p1 and p2 with the incidence parameter chi = v_c0 / (mu v_n0), mu and I / (m R^2) fixed: change
    // m, R, v0, G_inf, tau1 as in test_impact.cpp (and v_t with v0).
    const auto p1 = [](const ObliqueImpact& c) {
        const double rho = 3.0 * c.mass / (4.0 * std::numbers::pi * std::pow(c.radius, 3));
        return c.tau1 * std::pow(c.velocity, 0.2) * std::pow(c.G_inf / rho, 0.4) / c.radius;
    };
    const ObliqueImpact first = at_incidence(viscoelastic, 2.0);
    ObliqueImpact scaled{0.01 * 27.0, 0.03, 0.4, 2.5e6, 7.5e6, 1.0, 0.3, 0.0, 0.0};
    scaled.tau1 = p1(first) / p1(scaled);
    scaled = at_incidence(scaled, 2.0);
    const auto a = run_toml(oblique_case(first));
    const auto b = run_toml(oblique_case(scaled));
    const auto& x = *a.impact->oblique;
    const auto& y = *b.impact->oblique;
    EXPECT_NEAR(x.tangential_restitution, y.tangential_restitution, 1e-6);
    EXPECT_NEAR(x.impulse_ratio, y.impulse_ratio, 1e-6);
    EXPECT_NEAR(x.rebound_angle, y.rebound_angle, 1e-6 * 90.0);
    EXPECT_NEAR(x.rebound_spin * first.radius / first.velocity, y.rebound_spin * scaled.radius / scaled.velocity, 1e-6);
    EXPECT_NEAR(x.friction_dissipation / initial_energy(first), y.friction_dissipation / initial_energy(scaled), 1e-6);
    EXPECT_GT(x.tangential_restitution, 0.1);  // partial slip, not a trivial case
    EXPECT_FALSE(x.slid_throughout);
}

TEST(ObliqueImpact, ConvergenceOrders) {
    // Viscoelastic partial slip. Time: differences of successive halvings of the step (default elements) fall as
    // dt^2. Elements (step fixed): the error against 3200 elements falls at least as (dx)^1.5 over three halvings
    // (the contact edge cuts the elements, so single halvings vary).
    const ObliqueImpact c = at_incidence(viscoelastic, 2.0);
    const auto by_default = run_toml(oblique_case(c));
    const double contact_time = by_default.impact->contact_time;
    const auto with = [&](const std::string& numerics) {
        return run_toml(oblique_case(c, "[numerics]\n" + numerics)).impact->oblique->tangential_restitution;
    };
    std::vector<double> in_time;
    for (const double steps : {250.0, 500.0, 1000.0, 2000.0}) {
        in_time.push_back(with(fmt::format("time_step = {}", contact_time / steps)));
    }
    for (std::size_t i = 2; i < in_time.size(); ++i) {
        const double order = testing::observed_order(std::abs(in_time[i - 2] - in_time[i - 1]),
                                                     std::abs(in_time[i - 1] - in_time[i]));
        RecordProperty(fmt::format("order_time_{}", i), fmt::format("{:.2f}", order));
        EXPECT_GT(order, 1.7);
    }
    const std::string step = fmt::format("time_step = {}", contact_time / 500.0);
    const double converged = with("elements = 3200\n" + step);
    std::vector<double> errors;
    for (const int elements : {25, 50, 100, 200}) {
        errors.push_back(std::abs(with(fmt::format("elements = {}\n", elements) + step) - converged));
    }
    const double order = std::log2(errors.front() / errors.back()) / 3.0;
    RecordProperty("order_elements", fmt::format("{:.2f}", order));
    EXPECT_GT(order, 1.5);
    // The default numerics are on the converged side of 1e-4.
    EXPECT_NEAR(by_default.impact->oblique->tangential_restitution, in_time.back(), 1e-4);
}

TEST(ObliqueImpact, ALightContactPointIsResolvedByDefault) {
    // I = 0.05 m R^2: m_t = m/21, the contact point oscillates 2.4x faster than a solid sphere's; the default step
    // shrinks with sqrt(m_t) and stays within 1e-4 of a twice finer step.
    ObliqueImpact c = at_incidence(viscoelastic, 1.0);
    c.inertia_factor = 0.05;
    const auto by_default = run_toml(oblique_case(c));
    const auto finer = run_toml(oblique_case(c, fmt::format("[numerics]\ntime_step = {}",
                                                            by_default.numerics.time_step / 2.0)));
    EXPECT_NEAR(by_default.impact->oblique->tangential_restitution, finer.impact->oblique->tangential_restitution,
                1e-4);
}

}  // namespace
}  // namespace mdr
