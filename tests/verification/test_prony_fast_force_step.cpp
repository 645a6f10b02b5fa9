// A standard solid whose relaxation time (1 ms) is shorter than the default step (5 ms over a 10 s record) under a
// fast force change (a step, a 1e-4 s ramp) or a fast base ramp under spring control, on a flat punch a = 1 mm. The
// contact radius is fixed, so the depth is exact in closed form (handbook eq. 34 with F_el = 8 G a d):
//   force control   d(t) = (1/8a) int J(t - s) dF(s),  J(t) = 1/G_inf - G1/(G_inf G0) exp(-t/tau_r)  (Table 1),
//                   tau_r = tau1 G0 / G_inf, G0 = G_inf + G1;
//   spring control  F = k (z - d) with the punch 8a G(t) in series with the spring k: F(t) = int R(t - s) dz(s),
//                   s R(s) = k 8a s G(s) / (k + 8a s G(s)), a standard solid again:
//                   R(t) = R_inf + (R_0 - R_inf) exp(-t/tau_c), R_x = k 8a G_x / (k + 8a G_x),
//                   tau_c = tau1 (k + 8a G0) / (k + 8a G_inf).
// A ramp of rate r over [0, T] through the kernel c0 + c1 exp(-t/tau) gives, with m = min(t, T),
//   r [c0 m + c1 tau (exp(-(t - m)/tau) - exp(-t/tau))].
// Every row must be within 1e-3 of the peak depth, at the default step and at a finer user step (the rule that a
// finer step is never worse than the default).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "reference/prony_material.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

constexpr double G_inf = 1.0e6, G1 = 2.0e6, G0 = G_inf + G1, tau1 = 1e-3;
constexpr double a = 1e-3, F0 = 1.0, ramp = 1e-4, end = 10.0;
constexpr double punch_stiffness = 8.0 * a;  // F_el = 8 a G d

// The response at t to a ramp 0 -> amplitude over [0, T] through the kernel c0 + c1 exp(-t / tau) (T = 0: a step).
double ramp_response(double c0, double c1, double tau, double amplitude, double T, double t) {
    if (T == 0.0) return amplitude * (c0 + c1 * std::exp(-t / tau));
    const double m = std::min(t, T);
    return amplitude / T * (c0 * m + c1 * tau * (std::exp(-(t - m) / tau) - std::exp(-t / tau)));
}

double force_control_depth(double T, double t) {
    const double tau_r = tau1 * G0 / G_inf;
    return ramp_response(1.0 / G_inf, -G1 / (G_inf * G0), tau_r, F0, T, t) / punch_stiffness;
}

std::string material_and_punch() {
    return fmt::format("[material]\nmodel = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}\n"
                       "[indenter]\nshape = \"flat\"\na = {}\n",
                       G_inf, G1, tau1, a);
}

// The largest deviation of a run's rows from `exact`, relative to the peak of `exact` over the rows; the first row
// is the state before the load (at a jump at t = 0 the next row has the same time).
double worst_row_error(const std::vector<double>& time, const std::vector<double>& value, const auto& exact) {
    double worst = 0.0, peak = 0.0;
    for (std::size_t i = 1; i < time.size(); ++i) {
        worst = std::max(worst, std::abs(value[i] - exact(time[i])));
        peak = std::max(peak, std::abs(exact(time[i])));
    }
    return worst / peak;
}

TEST(PronyFastForceStep, TheClosedFormCreepIsTheStandardSolidsCreepFunction) {
    // The step limit of the kernel is F0 J(t) / 8a with J of the independent reference material (Table 1).
    for (const double t : {0.0, 1e-4, 3e-3, 1.0}) {
        const double expected = F0 * reference::standard_solid_creep(G_inf, G1, tau1, t) / punch_stiffness;
        EXPECT_NEAR(force_control_depth(0.0, t), expected, 1e-12 * expected);
        EXPECT_NEAR(force_control_depth(1e-9, t + 1e-9), expected, 1e-6 * expected);
    }
}

class ForceChange : public ::testing::TestWithParam<double> {};

TEST_P(ForceChange, EveryRowWithinOneThousandthOfThePeakAtTheDefaultAndAFinerStep) {
    const double T = GetParam();
    const std::string history = T == 0.0 ? fmt::format("[[0.0, 0.0], [0.0, {}], [{}, {}]]", F0, end, F0)
                                         : fmt::format("[[0.0, 0.0], [{}, {}], [{}, {}]]", T, F0, end, F0);
    for (const std::string numerics : {"", "time_step = 2.5e-3\n"}) {
        const auto result = testing::run_toml(material_and_punch() + "[load]\ncontrol = \"force\"\nhistory = " +
                                              history + "\n[numerics]\nelements = 50\n" + numerics);
        const double error =
            worst_row_error(result.time, result.depth, [&](double t) { return force_control_depth(T, t); });
        RecordProperty(numerics.empty() ? "default_error" : "user_step_error", fmt::format("{:.2e}", error));
        RecordProperty(numerics.empty() ? "default_steps" : "user_steps", std::to_string(result.steps));
        // Before the grading of finite series the ramp was off by 6.6e-2 at the default step, 2.4e-2 at the user step.
        EXPECT_LT(error, 1e-3) << "ramp " << T << " " << numerics;
    }
}

INSTANTIATE_TEST_SUITE_P(StepAndRamp, ForceChange, ::testing::Values(0.0, ramp));

TEST(PronyFastForceStep, SpringControlEveryRowWithinOneThousandthOfThePeak) {
    constexpr double k = 8000.0, z0 = 1e-4;
    const auto relaxed = [&](double G) { return k * punch_stiffness * G / (k + punch_stiffness * G); };
    const double tau_c = tau1 * (k + punch_stiffness * G0) / (k + punch_stiffness * G_inf);
    const auto exact_depth = [&](double t) {
        const double force = ramp_response(relaxed(G_inf), relaxed(G0) - relaxed(G_inf), tau_c, z0, ramp, t);
        return z0 * std::min(t / ramp, 1.0) - force / k;
    };
    for (const std::string numerics : {"", "time_step = 2.5e-3\n"}) {
        const auto result = testing::run_toml(
            material_and_punch() +
            fmt::format("[load]\ncontrol = \"spring\"\nspring_constant = {}\nhistory = [[0.0, 0.0], [{}, {}], "
                        "[{}, {}]]\n[numerics]\nelements = 50\n{}",
                        k, ramp, z0, end, z0, numerics));
        const double error = worst_row_error(result.time, result.depth, exact_depth);
        RecordProperty(numerics.empty() ? "default_error" : "user_step_error", fmt::format("{:.2e}", error));
        EXPECT_LT(error, 1e-3) << numerics;
    }
}

}  // namespace
}  // namespace mdr
