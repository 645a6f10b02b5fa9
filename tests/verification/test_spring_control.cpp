// control = "spring": a base displacement z(t) acting through a linear spring k on the massless rigid indenter,
// F = k (z - d). Against the algebraic Hertz-plus-spring solution (elastic), the limits of a very stiff spring
// (displacement control, error O(k_contact / k)) and a very soft one (force control, error O(k / k_contact)), and the
// force relaxation during a constant-height pause on a standard solid against an independent integration of the
// Lee-Radok hereditary integral with the spring.

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "run_case.hpp"

namespace mdr {
namespace {

using testing::interpolate;
using testing::run_toml;

constexpr double R = 0.01;
constexpr double G_inf = 1.0e6;
constexpr double G1 = 2.0e6;
constexpr double tau1 = 1.0;
// Same grid for the runs compared in the limits: their difference is then the spring's alone.
constexpr const char* fixed_numerics = "[numerics]\nelements = 2000\nhalf_width = 1.2e-3\ntime_step = 1.0e-3\n";

std::string standard_case(const std::string& load, const std::string& numerics) {
    return fmt::format(R"(
[material]
model = "standard"
G_inf = {}
G1 = {}
tau1 = {}
[indenter]
shape = "sphere"
R = {}
[load]
{}
{})",
                       G_inf, G1, tau1, R, load, numerics);
}

// Unit-modulus Hertz force (16/3) sqrt(R) d^(3/2) (E* = 4G).
double unit_hertz(double depth) { return depth > 0.0 ? 16.0 / 3.0 * std::sqrt(R) * std::pow(depth, 1.5) : 0.0; }

// The depth d with k (z - d) = G P(d) + offset (P the unit Hertz force), by bisection: the left side falls, the right
// rises with d.
double spring_balance(double k, double z, double modulus, double offset) {
    double lower = std::min(z, 0.0) - 1.0, upper = z;
    for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (lower + upper);
        (k * (z - middle) > modulus * unit_hertz(middle) + offset ? lower : upper) = middle;
    }
    return 0.5 * (lower + upper);
}

TEST(SpringControl, ElasticHertzWithSpringMatchesTheAlgebraicSolution) {
    // Elastic G, base from 0.5 um above the surface down to z = 2e-4 and back: F = k (z - d) = (16/3) G sqrt(R) d^1.5.
    const double G = 1e6, k = 1e4;
    const auto result = run_toml(fmt::format(R"(
[material]
model = "elastic"
G = {}
[indenter]
shape = "sphere"
R = {}
[load]
control = "spring"
spring_constant = {}
history = [[0.0, -5.0e-7], [1.0, 2.0e-4], [2.0, -5.0e-7]]
)",
                                             G, R, k));
    double peak = 0.0;
    for (double f : result.force) peak = std::max(peak, f);
    ASSERT_EQ(result.base.size(), result.time.size());
    double largest = 0.0;
    for (std::size_t n = 0; n < result.time.size(); ++n) {
        const double depth = spring_balance(k, result.base[n], G, 0.0);
        largest = std::max(largest, std::abs(result.force[n] - k * (result.base[n] - depth)));
        EXPECT_NEAR(result.force[n], k * (result.base[n] - result.depth[n]), 1e-9 * peak);  // F = k (z - d)
    }
    RecordProperty("error", fmt::format("{:.3g}", largest / peak));
    EXPECT_LT(largest, 1e-5 * peak);
    EXPECT_DOUBLE_EQ(result.depth.front(), -5e-7);  // off the surface the indenter rides on the unloaded spring
}

TEST(SpringControl, StiffSpringTendsToDisplacementControlAtFirstOrder) {
    // Base z = 1e-4 reached in tau1 / 2 and held: with k = c k_c (k_c = 8 G(0) a = 2.4e4 N/m at the peak) the force
    // differs from the displacement-controlled one by about F k_c / k.
    const std::string history = "history = [[0.0, 0.0], [0.5, 1.0e-4], [3.0, 1.0e-4]]";
    const auto exact = run_toml(standard_case("control = \"displacement\"\n" + history, fixed_numerics));
    double peak = 0.0;
    for (double f : exact.force) peak = std::max(peak, f);
    std::vector<double> errors;
    for (const double ratio : {1e2, 1e3, 1e4}) {
        const double k = ratio * 8.0 * (G_inf + G1) * 1e-3;
        const auto result = run_toml(
            standard_case(fmt::format("control = \"spring\"\nspring_constant = {}\n{}", k, history), fixed_numerics));
        ASSERT_EQ(result.time.size(), exact.time.size());
        double largest = 0.0;
        for (std::size_t n = 0; n < result.time.size(); ++n) largest = std::max(largest, std::abs(result.force[n] - exact.force[n]));
        errors.push_back(largest / peak);
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = std::log10(errors[i - 1] / errors[i]);  // per decade of k
        RecordProperty(fmt::format("order_stiff_{}", i), fmt::format("{:.3f}", order));
        EXPECT_NEAR(order, 1.0, 0.05);
    }
    EXPECT_LT(errors.back(), 2e-4);
}

TEST(SpringControl, SoftSpringTendsToForceControlAtFirstOrder) {
    // Force F1 = 1 N reached in tau1 / 2 and held; the spring run has z = F / k: its force is F - k d, so its depth
    // differs from the force-controlled one by about d k / k_c.
    const double F1 = 1.0;
    const auto exact = run_toml(
        standard_case(fmt::format("control = \"force\"\nhistory = [[0.0, 0.0], [0.5, {}], [3.0, {}]]", F1, F1),
                      fixed_numerics));
    double peak = 0.0;
    for (double d : exact.depth) peak = std::max(peak, d);
    std::vector<double> errors;
    for (const double ratio : {1e-2, 1e-3, 1e-4}) {
        const double k = ratio * 8.0 * (G_inf + G1) * 1e-3;
        const auto result = run_toml(standard_case(
            fmt::format("control = \"spring\"\nspring_constant = {}\nhistory = [[0.0, 0.0], [0.5, {}], [3.0, {}]]", k,
                        F1 / k, F1 / k),
            fixed_numerics));
        double largest = 0.0;
        for (std::size_t n = 0; n < exact.time.size(); ++n) {
            largest = std::max(largest, std::abs(interpolate(result.time, result.depth, exact.time[n]) - exact.depth[n]));
        }
        errors.push_back(largest / peak);
    }
    for (std::size_t i = 1; i < errors.size(); ++i) {
        const double order = std::log10(errors[i - 1] / errors[i]);
        RecordProperty(fmt::format("order_soft_{}", i), fmt::format("{:.3f}", order));
        EXPECT_NEAR(order, 1.0, 0.05);
    }
    EXPECT_LT(errors.back(), 2e-4);
}

// Independent solution of k (z - d) = int_0^t G(t - s) dP(d(s)) (Lee-Radok: the contact only grows), P the unit
// Hertz force, on uniform steps with P linear in time over each: F = G_inf P + G1 h, h_{n+1} = e h_n + beta dP with
// e = exp(-dt / tau1), beta = (tau1 / dt)(1 - e) (exact for the linear P); the depth of each step by bisection.
struct LeeRadokSpring {
    double k;
    std::vector<double> time, force;
    LeeRadokSpring(double spring, double ramp, double z1, double end, int steps) : k(spring) {
        const double dt = end / steps, e = std::exp(-dt / tau1), beta = tau1 / dt * (1.0 - e);
        double h = 0.0, P = 0.0;
        time.push_back(0.0);
        force.push_back(0.0);
        for (int n = 1; n <= steps; ++n) {
            const double t = n * dt, z = z1 * std::min(t / ramp, 1.0);
            // k (z - d) = G_inf P(d) + G1 (e h + beta (P(d) - P)) = (G_inf + G1 beta) P(d) + G1 (e h - beta P)
            const double offset = G1 * (e * h - beta * P);
            const double d = spring_balance(k, z, G_inf + G1 * beta, offset);
            const double P_new = unit_hertz(d);
            h = e * h + beta * (P_new - P);
            P = P_new;
            time.push_back(t);
            force.push_back(k * (z - d));
        }
    }
};

TEST(SpringControl, ConstantHeightPauseRelaxesAsLeeRadokWithTheSpring) {
    // z rises to 1e-4 in tau1 / 10 and is held to 3 tau1 with k of the order of the contact stiffness: the force
    // relaxes while the indenter creeps in (the contact grows throughout, so Lee-Radok holds).
    const double k = 2e4, ramp = 0.1, z1 = 1e-4, end = 3.0;
    const auto result = run_toml(standard_case(
        fmt::format("control = \"spring\"\nspring_constant = {}\nhistory = [[0.0, 0.0], [{}, {}], [{}, {}]]", k, ramp,
                    z1, end, z1),
        ""));
    const LeeRadokSpring reference(k, ramp, z1, end, 30000);
    double peak = 0.0;
    for (double f : reference.force) peak = std::max(peak, f);
    double largest = 0.0;
    for (std::size_t n = 0; n < result.time.size(); ++n) {
        largest = std::max(largest, std::abs(result.force[n] - interpolate(reference.time, reference.force, result.time[n])));
    }
    RecordProperty("error", fmt::format("{:.3g}", largest / peak));
    EXPECT_LT(largest, 1e-4 * peak);
    EXPECT_LT(result.force.back(), 0.8 * peak);  // it did relax
}

}  // namespace
}  // namespace mdr
