// control = "spring" on a Kelvin-Voigt body (a parallel dashpot): the massless indenter hangs at the base, d = z,
// until it touches; from the touch on F = k (z - d) is continuous, so the dashpots in contact stop the indenter at
// once. Every row must keep the spring's balance, and the depth must follow the touch's own solution: the closed form
// of the flat punch and an independent Runge-Kutta integration for the sphere. (Before the step that touches was split
// at the touch, the approach's rate went into the dashpots: a force out of balance with the spring at the touch.)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

constexpr double G = 1.0e3;     // [Pa]
constexpr double eta = 50.0;    // [Pa s]
constexpr double k = 1.0e-3;    // [N/m]
constexpr double z_top = 2.0e-6;  // the base rises linearly from z0 at t = 0 to z_top at t = 1 s, then holds to 2 s

std::string spring_case(const std::string& indenter, double z0, const std::string& numerics) {
    return fmt::format(R"(
[material]
model = "kelvin_voigt"
G = {}
eta = {}
[indenter]
{}
[load]
control = "spring"
spring_constant = {}
history = [[0.0, {}], [1.0, {}], [2.0, {}]]
[numerics]
time_step = 0.005
{})",
                       G, eta, indenter, k, z0, z_top, z_top, numerics);
}

double base(double z0, double t) { return z0 + (z_top - z0) * std::min(t, 1.0); }

double largest(const std::vector<double>& values) { return *std::max_element(values.begin(), values.end()); }

// Flat punch of radius a, E* = 4G: F = 8 a (G d + eta d') (eq. 21 with w = d over the contact), so from the touch
// at t0 (z(t0) = 0, d(t0) = 0) c d' + K d = k z with c = 8 a eta, K = 8 a G + k. For z = v (t - t0):
// d = (k v / K) (s - tau (1 - exp(-s / tau))), s = t - t0, tau = c / K; after t = 1 (z held) d relaxes to k z / K
// with the same tau.
double flat_punch_depth(double a, double z0, double t) {
    const double v = z_top - z0, t0 = -z0 / v;
    if (t <= t0) return base(z0, t);
    const double K = 8.0 * a * G + k, tau = 8.0 * a * eta / K;
    const auto ramp = [&](double s) { return k * v / K * (s - tau * (1.0 - std::exp(-s / tau))); };
    if (t <= 1.0) return ramp(t - t0);
    const double held = k * z_top / K;
    return held + (ramp(1.0 - t0) - held) * std::exp(-(t - 1.0) / tau);
}

TEST(SpringDashpotTouch, FlatPunchKeepsTheSpringBalanceAndFollowsTheClosedForm) {
    const double a = 2e-6;
    for (const double z0 : {0.0, -1e-6}) {
        SCOPED_TRACE(fmt::format("base from z0 = {}", z0));
        const auto result = run_toml(
            spring_case(fmt::format("shape = \"flat\"\na = {}", a), z0, "elements = 8000"));
        const double peak_force = largest(result.force), peak_depth = largest(result.depth);
        double balance = 0.0, depth_error = 0.0;
        for (std::size_t n = 0; n < result.time.size(); ++n) {
            const double t = result.time[n];
            ASSERT_DOUBLE_EQ(result.base[n], base(z0, t));
            balance = std::max(balance, std::abs(result.force[n] - k * (result.base[n] - result.depth[n])));
            depth_error = std::max(depth_error, std::abs(result.depth[n] - flat_punch_depth(a, z0, t)));
        }
        RecordProperty(fmt::format("balance_{}", z0), fmt::format("{:.3g}", balance / peak_force));
        RecordProperty(fmt::format("depth_error_{}", z0), fmt::format("{:.3g}", depth_error / peak_depth));
        EXPECT_LT(balance, 1e-9 * peak_force);      // F = k (z - d) at every row (the depth solve's tolerance)
        EXPECT_LT(depth_error, 2e-4 * peak_depth);  // measured 1.6e-5 (z0 = 0) and 2.4e-5 (z0 = -1e-6)
    }
}

// The sphere, E* = 4G: F = (16/3) sqrt(R) (G d^1.5 + eta d(d^1.5)/dt) (eq. 21 with w = d - x^2 / R over a = sqrt(R d);
// the contact only grows). With u = d^1.5 the balance k (z - d) = F is the smooth ODE
// u' = (3 k (z - u^(2/3)) / (16 sqrt(R)) - G u) / eta from u(t0) = 0, integrated here by classical Runge-Kutta.
struct SphereReference {
    double R, z0, t0, step;
    std::vector<double> u;
    SphereReference(double radius, double z_start, int steps) : R(radius), z0(z_start) {
        t0 = -z0 / (z_top - z0);
        step = (2.0 - t0) / steps;
        const auto rate = [&](double t, double value) {
            const double d = std::cbrt(std::max(value, 0.0) * std::max(value, 0.0));
            return (3.0 * k * (base(z0, t) - d) / (16.0 * std::sqrt(R)) - G * value) / eta;
        };
        u.push_back(0.0);
        for (int n = 0; n < steps; ++n) {
            const double t = t0 + n * step, h = step, value = u.back();
            const double k1 = rate(t, value), k2 = rate(t + h / 2, value + h / 2 * k1);
            const double k3 = rate(t + h / 2, value + h / 2 * k2), k4 = rate(t + h, value + h * k3);
            u.push_back(value + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4));
        }
    }
    double depth(double t) const {
        if (t <= t0) return base(z0, t);
        const double position = (t - t0) / step;
        const auto n = std::min(static_cast<std::size_t>(position), u.size() - 2);
        const double w = position - static_cast<double>(n);
        return std::pow((1.0 - w) * u[n] + w * u[n + 1], 2.0 / 3.0);
    }
};

TEST(SpringDashpotTouch, SphereKeepsTheSpringBalanceAndFollowsAnIndependentIntegration) {
    const double R = 1e-5, z0 = -1e-6, half_width = 2e-6;
    const std::size_t elements = 4000;
    const auto result = run_toml(spring_case(fmt::format("shape = \"sphere\"\nR = {}", R), z0,
                                             fmt::format("elements = {}\nhalf_width = {}", elements, half_width)));
    const SphereReference reference(R, z0, 200000);
    const double peak_force = largest(result.force), peak_depth = largest(result.depth);
    double depth_error = 0.0, balance = 0.0;
    for (std::size_t n = 1; n < result.time.size(); ++n) {
        depth_error = std::max(depth_error, std::abs(result.depth[n] - reference.depth(result.time[n])));
        balance = std::max(balance, std::abs(result.force[n] - k * (result.base[n] - result.depth[n])));
    }
    // F = k (z - d) at every row to the depth solve's tolerance: an element entering contact at the edge takes its
    // dashpot's force as it enters, continuously in the depth (before, it carried 8 dx eta d' at once, and the rows
    // where the balance fell inside that step missed it: 1.1e-5 of the peak force here).
    RecordProperty("balance", fmt::format("{:.3g}", balance / peak_force));
    EXPECT_LT(balance, 1e-9 * peak_force);
    RecordProperty("depth_error", fmt::format("{:.3g}", depth_error / peak_depth));
    // Measured 6.6e-5 (2.3e-4 before: the entering elements' dashpots at the indenter's secant rate in the touch's
    // step, the contact growing from nothing; now from rest, each at its own trapezoidal rate, docs/theory.md
    // section 3).
    EXPECT_LT(depth_error, 1.5e-4 * peak_depth);
}

}  // namespace
}  // namespace mdr
