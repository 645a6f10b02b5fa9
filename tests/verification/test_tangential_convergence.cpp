// Convergence of the steady fretting loop (section 6): the energy dissipated per cycle (the area of the F_x-u
// loop over the last full cycle) falls as dt^2 in the time step and is settled in the elements.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "run_case.hpp"

namespace mdr {
namespace {

using testing::run_toml;

// examples/fretting_stick_radius.toml: a sphere at a fixed depth in a standard solid, then ten 10 Hz cycles.
std::string fretting_case(const std::string& numerics) {
    return R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-4], [2.0, 1.0e-4]]
[tangential]
friction = 0.3
amplitude = 1.5e-5
frequency = 10.0
start = 1.0
end = 2.0
)" + numerics;
}

double energy_per_cycle(const std::string& numerics) {
    return run_toml(fretting_case(numerics)).tangential->dissipated_energy_per_cycle.value();
}

TEST(TangentialConvergence, EnergyPerCycleSecondOrderInTheTimeStep) {
    std::vector<double> energies;
    for (int steps_per_period : {50, 100, 200, 400}) {
        energies.push_back(energy_per_cycle(fmt::format("[numerics]\nelements = 1000\ntime_step = {}\n",
                                                        0.1 / steps_per_period)));
    }
    // Differences of successive halvings shrink by 4 (observed 3.99, 4.0).
    for (std::size_t i = 2; i < energies.size(); ++i) {
        const double order = testing::observed_order(std::abs(energies[i - 2] - energies[i - 1]),
                                                     std::abs(energies[i - 1] - energies[i]));
        RecordProperty(fmt::format("order_energy_{}", i), fmt::format("{:.2f}", order));
        EXPECT_GT(order, 1.7);
    }
    // The default step (200 per period) is within 1e-3 of the finest.
    EXPECT_NEAR(energy_per_cycle(""), energies.back(), 1e-3 * energies.back());
}

TEST(TangentialConvergence, EnergyPerCycleSettledInTheElements) {
    // The loop energy changes by less than 1e-5 (relative) from 500 to 4000 elements (observed ~2e-6).
    const double coarse = energy_per_cycle("[numerics]\nelements = 500\n");
    const double fine = energy_per_cycle("[numerics]\nelements = 4000\n");
    EXPECT_NEAR(coarse, fine, 1e-5 * fine);
}

}  // namespace
}  // namespace mdr

namespace mdr {
namespace {

TEST(TangentialStress, CattaneoMindlinShearStressProfile) {
    // Elastic sphere at depth d, then a tangential displacement u = u_max/2 (u_max = 3 mu d / 2): the classical
    // traction tau(r) = (mu p0/a) [sqrt(a^2 - r^2) - sqrt(c^2 - r^2)] (the second term for r < c only),
    // c = a sqrt(1 - u/u_max), p0 = 8 G a/(pi R). Eq. (47) from the tangential line loads: 1e-2 of mu p0
    // (element-scale errors at the stick edge, where tau has a kink, and near the axis).
    const double G = 1e6, R = 0.01, d = 1e-4, mu = 0.3;
    const double u = 0.5 * 1.5 * mu * d;
    const auto result = testing::run_toml(fmt::format(R"(
[material]
model = "elastic"
G = {}
[indenter]
shape = "sphere"
R = {}
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {}], [2.0, {}]]
[tangential]
friction = {}
history = [[0.0, 0.0], [1.0, 0.0], [2.0, {}]]
[output]
snapshots = [2.0]
)",
                                                      G, R, d, d, mu, u));
    ASSERT_EQ(result.snapshots.size(), 1u);
    const auto& snapshot = result.snapshots.front();
    const double a = std::sqrt(R * d), c = a * std::sqrt(0.5), p0 = 8 * G * a / (std::numbers::pi * R);
    for (std::size_t j = 0; j < snapshot.radius.size(); ++j) {
        const double r = snapshot.radius[j];
        if (r >= a) continue;
        const double exact =
            mu * p0 / a * (std::sqrt(a * a - r * r) - (r < c ? std::sqrt(c * c - r * r) : 0.0));
        EXPECT_NEAR(snapshot.shear_stress[j], exact, 1e-2 * mu * p0) << "r = " << r;
    }
}

}  // namespace
}  // namespace mdr
