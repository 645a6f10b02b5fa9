// The DEM contact law (include/mdr/dem/contact_law.hpp) against `mdr run`: a collision of two viscoelastic spheres
// with spin, integrated sphere by sphere the way a time-stepping code would, with the law's state in the test's
// memory, gives the impact driver's restitution, tangential restitution and forces to round-off when both use the
// same elements and steps (sphere-sphere contact through the equivalent radius and the combined creep function,
// eq. 8). Plus: the law allocates nothing once built.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "mdr/dem/contact_law.hpp"
#include "mdr/rheology/rheology.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

// Two spheres: 1 above, moving down onto 2; tangential velocities along x, spins about the axis that makes
// R1 omega1 a backward velocity of sphere 1's contact point (as in the case file) and R2 omega2 a forward one of
// sphere 2's.
struct Sphere {
    double radius, mass, inertia, normal_velocity, tangential_velocity, spin;
};

const rheology::Rheology first_material = rheology::Rheology::standard(1e6, 3e6, 1e-3);
const rheology::Rheology second_material = rheology::Rheology::prony(2e6, {{4e6, 3e-4}, {1e6, 1e-2}});
constexpr double friction = 0.3;
constexpr std::size_t elements = 400;

// The root of a continuous non-decreasing f from `guess`: bracket in doubling steps, then Illinois regula falsi.
template <typename F>
double monotone_solve(const F& f, double guess, double step) {
    double lower = guess, upper = guess, f_lower = f(guess), f_upper = f_lower;
    if (f_lower == 0.0) return guess;
    while (f_lower > 0.0) { upper = lower; f_upper = f_lower; lower -= step; step *= 2.0; f_lower = f(lower); }
    while (f_upper < 0.0) { lower = upper; f_lower = f_upper; upper += step; step *= 2.0; f_upper = f(upper); }
    int side = 0;
    for (int i = 0; i < 200 && upper - lower > 1e-16 * std::max(std::abs(lower), std::abs(upper)); ++i) {
        const double x = (lower * f_upper - upper * f_lower) / (f_upper - f_lower);
        const double fx = f(x);
        if (fx == 0.0) return x;
        if (fx < 0.0) {
            lower = x; f_lower = fx;
            if (side == -1) f_upper *= 0.5;
            side = -1;
        } else {
            upper = x; f_upper = fx;
            if (side == 1) f_lower *= 0.5;
            side = 1;
        }
    }
    return 0.5 * (lower + upper);
}

struct Outcome {
    double restitution, tangential_restitution, max_force, max_tangential_force;
};

// The collision stepped with the contact law, each sphere moved by the trapezoidal rule (implicit in the overlap
// and the tangential displacement, as a DEM code with an implicit contact would).
Outcome collide(Sphere a, Sphere b, double half_width, double time_step) {
    dem::ContactLaw law(rheology::in_series(first_material, second_material),
                        a.radius * b.radius / (a.radius + b.radius), friction, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    const double normal_mass = 1.0 / (1.0 / a.mass + 1.0 / b.mass);
    const double tangential_mass =
        1.0 / (1.0 / a.mass + 1.0 / b.mass + a.radius * a.radius / a.inertia + b.radius * b.radius / b.inertia);
    const auto approach = [&] { return a.normal_velocity - b.normal_velocity; };
    const auto slip = [&] {
        return (a.tangential_velocity - a.radius * a.spin) - (b.tangential_velocity + b.radius * b.spin);
    };
    const double approach0 = approach(), slip0 = slip();
    double overlap = 0.0, displacement = 0.0, force = 0.0, tangential = 0.0;
    Outcome outcome{0.0, 0.0, 0.0, 0.0};
    const auto kick = [&](double normal_impulse, double tangential_impulse) {
        a.normal_velocity -= normal_impulse / a.mass;
        b.normal_velocity += normal_impulse / b.mass;
        a.tangential_velocity -= tangential_impulse / a.mass;
        b.tangential_velocity += tangential_impulse / b.mass;
        a.spin += a.radius * tangential_impulse / a.inertia;
        b.spin += b.radius * tangential_impulse / b.inertia;
    };
    for (int n = 0; n < 100000; ++n) {
        law.begin(state);
        const double spring = 4.0 * normal_mass / (time_step * time_step);
        const double anchor = overlap + approach() * time_step;
        const double new_overlap = monotone_solve(
            [&](double d) { return law.normal_trial(d) + spring * (d - anchor) + force; },
            anchor - force * time_step * time_step / (2.0 * normal_mass), 1e-3 * std::abs(approach0) * time_step);
        law.advance_normal(new_overlap);
        const double new_force = law.normal_force();
        if (new_force == 0.0 && force > 0.0) {
            const double part = law.latest_exit() * time_step;
            kick(0.5 * force * part, 0.5 * tangential * part);
            outcome.restitution = -approach() / approach0;
            outcome.tangential_restitution = -slip() / slip0;
            return outcome;
        }
        const double tangential_spring = 4.0 * tangential_mass / (time_step * time_step);
        const double tangential_anchor = displacement + slip() * time_step;
        const double new_displacement = monotone_solve(
            [&](double u) {
                return law.tangential_trial({u, 0.0})[0] + tangential_spring * (u - tangential_anchor) + tangential;
            },
            tangential_anchor, 1e-3 * std::abs(slip0) * time_step);
        law.advance_tangential({new_displacement, 0.0});
        law.end(state);
        const double new_tangential = law.tangential_force(state)[0];
        EXPECT_EQ(law.normal_force(state), new_force);
        kick(0.5 * (force + new_force) * time_step, 0.5 * (tangential + new_tangential) * time_step);
        overlap = new_overlap;
        displacement = new_displacement;
        force = new_force;
        tangential = new_tangential;
        outcome.max_force = std::max(outcome.max_force, force);
        outcome.max_tangential_force = std::max(outcome.max_tangential_force, std::abs(tangential));
    }
    ADD_FAILURE() << "the collision did not end";
    return outcome;
}

TEST(DemContactLaw, TwoSphereCollisionMatchesMdrRunToRoundOff) {
    const Sphere a{0.01, 0.01, 0.4 * 0.01 * 1e-4, 0.1, 0.05, 2.0};
    const Sphere b{0.02, 0.05, 0.4 * 0.05 * 4e-4, -0.02, -0.01, -1.0};
    const double radius = a.radius * b.radius / (a.radius + b.radius);
    const double mass = 1.0 / (1.0 / a.mass + 1.0 / b.mass);
    // The equivalent rigid sphere: its lever R and moment of inertia give the same contact-point dynamics,
    // R^2 / I = R1^2 / I1 + R2^2 / I2; its spin and tangential velocity the same contact-point velocity.
    const double inertia = radius * radius / (a.radius * a.radius / a.inertia + b.radius * b.radius / b.inertia);
    const double slip = (a.tangential_velocity - a.radius * a.spin) - (b.tangential_velocity + b.radius * b.spin);
    const double half_width = 1.5e-3, time_step = 2e-6;
    const auto combined = rheology::in_series(first_material, second_material);
    std::string terms;
    for (const auto& term : combined.terms()) terms += fmt::format("[{}, {}], ", term.modulus, term.relaxation_time);
    const auto result = testing::run_toml(fmt::format(R"(
[material]
model = "prony"
G_inf = {}
terms = [{}]
[indenter]
shape = "sphere"
R = {}
mass = {}
moment_of_inertia = {}
[load]
control = "impact"
velocity = {}
tangential_velocity = {}
[tangential]
friction = {}
[numerics]
elements = {}
half_width = {}
time_step = {}
)",
                                                      combined.equilibrium_modulus(), terms, radius, mass, inertia,
                                                      a.normal_velocity - b.normal_velocity, slip, friction, elements,
                                                      half_width, time_step));
    ASSERT_TRUE(result.impact && result.impact->oblique);
    EXPECT_LT(result.impact->restitution, 0.95);            // the materials dissipate
    EXPECT_FALSE(result.impact->oblique->slid_throughout);  // partial slip: the stick zone is exercised

    // Driven by the run's own overlap and contact-point displacement at every step (all but the last, where the
    // contact ends inside the step), the law gives the run's forces: the same rule on the same input, to round-off
    // of the largest force (the law composes the steps in which no element enters or leaves contact).
    dem::ContactLaw law(combined, radius, friction, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    const double largest_force = *std::max_element(result.force.begin(), result.force.end());
    for (std::size_t n = 1; n + 1 < result.time.size(); ++n) {
        law.advance(state, result.depth[n], {result.tangential_displacement[n], 0.0});
        ASSERT_NEAR(law.normal_force(state), result.force[n], 1e-13 * largest_force) << "step " << n;
        ASSERT_NEAR(law.tangential_force(state)[0], result.tangential_force[n],
                    1e-12 * result.impact->oblique->max_tangential_force) << "step " << n;
    }

    // Integrated sphere by sphere with the law, solving the overlap and the displacement of each step to 1e-16 where
    // the run's solve stops at 1e-13 of the step's force scale: the outcome agrees to that round-off.
    const Outcome dem = collide(a, b, half_width, time_step);
    EXPECT_NEAR(dem.restitution, result.impact->restitution, 1e-10);
    EXPECT_NEAR(dem.tangential_restitution, result.impact->oblique->tangential_restitution, 1e-10);
    double max_force = 0.0;
    for (double f : result.force) max_force = std::max(max_force, f);
    EXPECT_NEAR(dem.max_force, max_force, 1e-10 * max_force);
    EXPECT_NEAR(dem.max_tangential_force, result.impact->oblique->max_tangential_force,
                1e-10 * result.impact->oblique->max_tangential_force);
}

TEST(DemContactLaw, RestitutionAccuracyAtTwentyAndFiftyElements) {
    // What a DEM user gets from a coarse law: the restitution map's impact (examples/restitution_map.toml, p2 = 3)
    // at v_t0 = 2 mu v_n0 over p1 (tau1 = 1e-4 .. 1e-2 s), with 20 and 50 elements on the half-width (1.2 times the
    // elastic radius at G_inf, as by default) against 2000 (converged to 1e-6); the law is the same code
    // (TwoSphereCollisionMatchesMdrRunToRoundOff). Observed: N = 20 within 3e-4, N = 50 within 1.3e-5.
    for (const double tau : {1e-4, 1e-3, 1e-2}) {
        const auto run = [&](int count) {
            return testing::run_toml(fmt::format(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = {}
[indenter]
shape = "sphere"
R = 0.01
mass = 3.27e-2
[load]
control = "impact"
velocity = 0.1
tangential_velocity = 0.06
[tangential]
friction = 0.3
[numerics]
elements = {}
)",
                                                 tau, count));
        };
        const auto converged = run(2000);
        for (const int count : {20, 50}) {
            const auto coarse = run(count);
            const double normal = coarse.impact->restitution - converged.impact->restitution;
            const double tangential = coarse.impact->oblique->tangential_restitution -
                                      converged.impact->oblique->tangential_restitution;
            RecordProperty(fmt::format("restitution_error_N{}_tau{}", count, tau), fmt::format("{:.1e}", normal));
            RecordProperty(fmt::format("tangential_restitution_error_N{}_tau{}", count, tau),
                           fmt::format("{:.1e}", tangential));
            const double bound = count == 20 ? 5e-4 : 3e-5;
            EXPECT_LT(std::abs(normal), bound) << "N = " << count << ", tau1 = " << tau;
            EXPECT_LT(std::abs(tangential), bound) << "N = " << count << ", tau1 = " << tau;
        }
    }
}

}  // namespace
}  // namespace mdr
