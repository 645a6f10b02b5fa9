// A constant-force pause after a spring approach (`[load] force_pauses`, the AFM creep segment): the feedback holds
// the force reached at the pause's start, the depth creeps as under force control and the base follows as
// z = d + F / k; afterwards the base history resumes shifted from the z reached. Elastic: nothing moves during the
// pause, and after it the algebraic Hertz-plus-spring solution with the shifted base holds. Standard solid and
// Kelvin-Voigt, sphere: against an independent solution of eq. (34) in its creep form,
// P(d(t)) = int_0^t J(t - s) dF(s) (P the unit-modulus Hertz force), with F = k (z - d) during the approach (solved
// here step by step, exact for F linear in time over each step) and F = F(t_start) during the pause (closed form).

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "convergence.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::interpolate;
using testing::run_toml;

constexpr double R = 0.01;

// Unit-modulus Hertz force (16/3) sqrt(R) d^(3/2) (eq. 35 with a^2 = R d, eq. 31) and its inverse.
double unit_hertz(double depth) { return depth > 0.0 ? 16.0 / 3.0 * std::sqrt(R) * std::pow(depth, 1.5) : 0.0; }
double hertz_depth(double unit_force) { return std::pow(3.0 * unit_force / (16.0 * std::sqrt(R)), 2.0 / 3.0); }

// The root of a rising function on [lower, upper] by bisection.
template <typename Function>
double rising_root(const Function& f, double lower, double upper) {
    for (int i = 0; i < 80; ++i) {
        const double middle = 0.5 * (lower + upper);
        (f(middle) < 0.0 ? lower : upper) = middle;
    }
    return 0.5 * (lower + upper);
}

// A creep function J(t) = J_inf - dJ exp(-t / tau_c) (Table 1).
struct Creep {
    double J_inf, dJ, tau_c;
};
// Standard solid G(t) = G_inf + G1 exp(-t / tau1): J_inf = 1 / G_inf, J(0) = 1 / (G_inf + G1),
// tau_c = tau1 (G_inf + G1) / G_inf. Kelvin-Voigt: J = (1 - exp(-t G / eta)) / G.
Creep standard_solid(double G_inf, double G1, double tau1) {
    return {1.0 / G_inf, 1.0 / G_inf - 1.0 / (G_inf + G1), tau1 * (G_inf + G1) / G_inf};
}
Creep kelvin_voigt(double G, double eta) { return {1.0 / G, 1.0 / G, eta / G}; }

// Eq. (34): P(d) = J_inf F - dJ q with q(t) = int_0^t exp(-(t - s) / tau_c) dF(s). The approach z = rate t from the
// surface (z(0) = 0) to t_start on `steps` uniform steps with F linear in time over each step:
// q_{n+1} = e q_n + beta (F_{n+1} - F_n), e = exp(-dt / tau_c), beta = (tau_c / dt)(1 - e), and F = k (z - d), so
// that each step's depth is the root of P(d) - (J_inf - dJ beta) k (z - d) + dJ (e q_n - beta F_n) (rising in d).
// The pause holds F: q decays as exp(-(t - t_start) / tau_c), and the depth follows in closed form.
struct SpringCreepReference {
    Creep creep;
    double k, rate, start;
    std::vector<double> time{0.0}, force{0.0};
    double q = 0.0;

    SpringCreepReference(Creep material, double spring, double base_rate, double t_start, int steps)
        : creep(material), k(spring), rate(base_rate), start(t_start) {
        const double dt = start / steps, e = std::exp(-dt / creep.tau_c), beta = -std::expm1(-dt / creep.tau_c) * creep.tau_c / dt;
        for (int n = 1; n <= steps; ++n) {
            const double z = rate * start * n / steps, F = force.back();
            const auto residual = [&](double d) {
                return unit_hertz(d) - (creep.J_inf - creep.dJ * beta) * k * (z - d) + creep.dJ * (e * q - beta * F);
            };
            const double d = rising_root(residual, 0.0, z);
            const double F_new = k * (z - d);
            q = e * q + beta * (F_new - F);
            time.push_back(start * n / steps);
            force.push_back(F_new);
        }
    }
    double held_force() const { return force.back(); }
    /// The depth at t >= t_start during the pause.
    double depth_in_pause(double t) const {
        return hertz_depth(creep.J_inf * held_force() - creep.dJ * q * std::exp(-(t - start) / creep.tau_c));
    }
};

// Approach to z1 at t1, pause to t2, retract by `retract` over the next second.
struct Program {
    double z1 = 1e-4, t1 = 1.0, t2 = 4.0, retract = 1.5e-4;
    std::string load(double k) const {
        return fmt::format("control = \"spring\"\nspring_constant = {}\n"
                           "history = [[0.0, 0.0], [{}, {}], [{}, {}], [{}, {}]]\nforce_pauses = [[{}, {}]]",
                           k, t1, z1, t2, z1, t2 + 1.0, z1 - retract, t1, t2);
    }
    double history(double t) const { return t <= t1 ? z1 * t / t1 : t <= t2 ? z1 : z1 - retract * (t - t2); }
};

std::string case_text(const std::string& material, const std::string& load, const std::string& numerics = "") {
    return fmt::format("[material]\n{}\n[indenter]\nshape = \"sphere\"\nR = {}\n[load]\n{}\n{}", material, R, load,
                       numerics);
}

// The row of `result` at time t (a node of the grid).
std::size_t row_at(const drivers::IndentationResult& result, double t) {
    for (std::size_t n = 0; n < result.time.size(); ++n) {
        if (result.time[n] == t) return n;
    }
    ADD_FAILURE() << "no row at t = " << t;
    return 0;
}

// The depth [m] by which k (z - d) = G P(d) (the left side falls with d, the right rises).
double spring_balance(double k, double z, double G) {
    return rising_root([&](double d) { return G * unit_hertz(d) - k * (z - d); }, std::min(z, 0.0) - 1.0, z);
}

TEST(ForcePause, ElasticNothingMovesAndTheBaseResumesShifted) {
    // The history rises by 5e-5 during the pause [1, 2] (its values there are not used): the base then resumes
    // from z(1) = 2e-4, i.e. the history shifted by -5e-5.
    const double G = 1e6, k = 1e4, shift = -5e-5;
    const auto result = run_toml(case_text(fmt::format("model = \"elastic\"\nG = {}", G),
                                           fmt::format("control = \"spring\"\nspring_constant = {}\n"
                                                       "history = [[0.0, 0.0], [1.0, 2.0e-4], [2.0, 2.5e-4], "
                                                       "[3.0, -1.0e-4]]\nforce_pauses = [[1.0, 2.0]]",
                                                       k)));
    const std::size_t start = row_at(result, 1.0), end = row_at(result, 2.0);
    const double held = result.force[start], depth = result.depth[start];
    for (std::size_t n = start; n <= end; ++n) {
        EXPECT_NEAR(result.depth[n], depth, 1e-12 * depth);
        EXPECT_NEAR(result.force[n], held, 1e-12 * held);
        EXPECT_NEAR(result.base[n], 2e-4, 1e-12 * 2e-4);
    }
    double largest = 0.0;
    for (std::size_t n = end; n < result.time.size(); ++n) {
        const double t = result.time[n];
        const double z = (t <= 2.0 ? 2.5e-4 : 2.5e-4 - 3.5e-4 * (t - 2.0)) + shift;
        EXPECT_NEAR(result.base[n], z, 1e-12 * 2e-4);
        largest = std::max(largest, std::abs(result.depth[n] - spring_balance(k, z, G)));
    }
    ::testing::Test::RecordProperty("error_after", fmt::format("{:.3g}", largest / depth));
    EXPECT_LT(largest, 1e-5 * depth);
}

// A run's errors against the reference: the force during the approach and the force held, over the force held; the
// depth during the pause, over the depth at its end.
struct PauseCheck {
    double approach_error = 0.0, pause_error = 0.0, held_error = 0.0;
};
PauseCheck check_pause(const drivers::IndentationResult& result, const SpringCreepReference& reference,
                       const Program& program) {
    PauseCheck check;
    const std::size_t start = row_at(result, program.t1), end = row_at(result, program.t2);
    const double peak = reference.held_force(), depth = reference.depth_in_pause(program.t2);
    for (std::size_t n = 0; n <= start; ++n) {
        // The reference's linear interpolation cannot follow the first instants (F ~ t^(1/2) against a dashpot).
        if (result.time[n] < 0.01 * program.t1) continue;
        const double expected = interpolate(reference.time, reference.force, result.time[n]);
        check.approach_error = std::max(check.approach_error, std::abs(result.force[n] - expected) / peak);
    }
    check.held_error = std::abs(result.force[start] - peak) / peak;
    for (std::size_t n = start; n <= end; ++n) {
        check.pause_error = std::max(check.pause_error,
                                     std::abs(result.depth[n] - reference.depth_in_pause(result.time[n])) / depth);
    }
    return check;
}

void expect_pause_matches(const std::string& material, Creep creep, double k, double approach_tolerance,
                          double tolerance) {
    const Program program;
    const auto result = run_toml(case_text(material, program.load(k)));  // the defaults
    const SpringCreepReference reference(creep, k, program.z1 / program.t1, program.t1, 40000);
    const SpringCreepReference half(creep, k, program.z1 / program.t1, program.t1, 20000);
    const double depth = reference.depth_in_pause(program.t2);
    EXPECT_NEAR(half.depth_in_pause(program.t2), depth, 1e-8 * depth);  // the reference has converged
    const PauseCheck check = check_pause(result, reference, program);
    ::testing::Test::RecordProperty("approach_error", fmt::format("{:.3g}", check.approach_error));
    ::testing::Test::RecordProperty("held_force_error", fmt::format("{:.3g}", check.held_error));
    ::testing::Test::RecordProperty("pause_error", fmt::format("{:.3g}", check.pause_error));
    EXPECT_LT(check.approach_error, approach_tolerance);
    EXPECT_LT(check.held_error, approach_tolerance);
    EXPECT_LT(check.pause_error, tolerance);
    // It crept: the depth at the pause's end is well beyond the one at its start.
    EXPECT_GT(depth, 1.2 * reference.depth_in_pause(program.t1));

    // During the pause the force stays at the one reached; the base follows as z = d + F / k.
    const std::size_t start = row_at(result, program.t1), end = row_at(result, program.t2);
    const double held = result.force[start];
    for (std::size_t n = start; n <= end; ++n) {
        EXPECT_NEAR(result.force[n], held, 1e-12 * held);
        EXPECT_NEAR(result.base[n], result.depth[n] + held / k, 1e-12 * program.z1);
    }
    // Afterwards the base history resumes from the z reached, with its own slope; F = k (z - d) again.
    const double z_end = result.base[end];
    EXPECT_NEAR(z_end, reference.depth_in_pause(program.t2) + reference.held_force() / k, tolerance * program.z1);
    for (std::size_t n = end + 1; n < result.time.size(); ++n) {
        const double t = result.time[n];
        EXPECT_NEAR(result.base[n], z_end + program.history(t) - program.history(program.t2), 1e-12 * program.z1);
        EXPECT_NEAR(result.force[n], std::max(0.0, k * (result.base[n] - result.depth[n])), 1e-9 * held);
    }
    EXPECT_GT(z_end, program.z1 + 0.1 * depth);  // the base followed the creep
}

TEST(ForcePause, StandardSolidCreepsAsEq34AfterTheSpringApproach) {
    // k of the order of the contact stiffness 8 G(0) a (~2.4e4 N/m at a = 1 mm): neither limit of the spring.
    const double G_inf = 1e6, G1 = 2e6, tau1 = 1.0;
    expect_pause_matches(fmt::format("model = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}", G_inf, G1, tau1),
                         standard_solid(G_inf, G1, tau1), 2e4, 1e-5, 1e-5);  // measured 2.4e-7 and 2.5e-7
}

TEST(ForcePause, KelvinVoigtCreepsAsEq34AfterTheSpringApproach) {
    const double G = 1e6, eta = 1e6;
    // The approach's force has a one-node spike of 6.4e-4 at t = 0.07 s (the trapezoidal dashpot rate as the contact
    // grows across the graded steps; the spring approach alone, before any pause); the creep in the pause 8.8e-6.
    expect_pause_matches(fmt::format("model = \"kelvin_voigt\"\nG = {}\neta = {}", G, eta), kelvin_voigt(G, eta), 2e4,
                         1e-3, 1e-4);
}

TEST(ForcePause, StandardSolidPauseConvergesAtSecondOrderInTheTimeStep) {
    // Steps of 1/40 of the approach and finer on a fine foundation, so that the time-stepping error dominates.
    const double G_inf = 1e6, G1 = 2e6, tau1 = 1.0, k = 2e4;
    const Program program;
    const SpringCreepReference reference(standard_solid(G_inf, G1, tau1), k, program.z1 / program.t1, program.t1,
                                         40000);
    std::vector<double> errors;
    for (const double step : {0.025, 0.0125, 0.00625}) {
        const auto result = run_toml(
            case_text(fmt::format("model = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}", G_inf, G1, tau1),
                      program.load(k),
                      fmt::format("[numerics]\nelements = 32000\nhalf_width = 1.5e-3\ntime_step = {}", step)));
        const std::size_t end = row_at(result, program.t2);
        errors.push_back(std::abs(result.depth[end] - reference.depth_in_pause(program.t2)) /
                         reference.depth_in_pause(program.t2));
    }
    testing::expect_orders_above(errors, 1.8, "force_pause_time_step");
}

}  // namespace
}  // namespace mdr
