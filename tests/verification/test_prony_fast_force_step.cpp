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
// finer step is never worse than the default). A six-term series (1e-6 ... 1e3 s) likewise, with its exact creep
// function from the zeros of s G(s) (CreepFunction below).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "reference/prony_material.hpp"
#include "reference/quadrature.hpp"
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

// A series G_inf + sum G_k exp(-t/tau_k) (no dashpot, G_inf > 0) as its creep function J(t) = 1/G_inf -
// sum_j c_j exp(-t/lambda_j) (numerics-notes: creep functions of Prony series): s G(s) = G_inf + sum G_k s tau_k /
// (1 + s tau_k) has one zero z_j between each pair of its poles -1/tau_k and one in (-1/tau_max, 0) (Brent), and
// J(s) = 1 / (s sG(s)) has the residue 1 / (z_j (sG)'(z_j)) there: c_j = -1 / (z_j (sG)'(z_j)), lambda_j = -1/z_j.
struct CreepFunction {
    double long_time = 0.0;                          // 1/G_inf
    std::vector<std::pair<double, double>> terms;    // (c_j, lambda_j)

    CreepFunction(double g_inf, std::vector<std::pair<double, double>> branches) : long_time(1.0 / g_inf) {
        std::sort(branches.begin(), branches.end(), [](const auto& x, const auto& y) { return x.second < y.second; });
        const auto modulus = [&](double s) {  // s G(s)
            double sum = g_inf;
            for (const auto& [G, tau] : branches) sum += G * s * tau / (1.0 + s * tau);
            return sum;
        };
        const auto slope = [&](double s) {  // (s G)'(s)
            double sum = 0.0;
            for (const auto& [G, tau] : branches) sum += G * tau / ((1.0 + s * tau) * (1.0 + s * tau));
            return sum;
        };
        for (std::size_t k = 0; k < branches.size(); ++k) {
            const double lower = -1.0 / branches[k].second * (1.0 - 1e-13);
            const double upper = k + 1 < branches.size() ? -1.0 / branches[k + 1].second * (1.0 + 1e-13) : 0.0;
            const double zero = reference::find_root(modulus, lower, upper, 1e-15 * std::abs(lower));
            terms.emplace_back(-1.0 / (zero * slope(zero)), -1.0 / zero);
        }
    }
    // The response at t to a ramp 0 -> amplitude over [0, T] through J.
    double ramp(double amplitude, double T, double t) const {
        double sum = ramp_response(long_time, 0.0, 1.0, amplitude, T, t);
        for (const auto& [c, lambda] : terms) sum += ramp_response(0.0, -c, lambda, amplitude, T, t);
        return sum;
    }
};

// Six branches, 1e-6 ... 1e3 s, under a 1e-4 s force ramp (or spring base ramp) held 1e3 s: the default step is
// 0.2 s (a fifth of the 1 s branch), far above the four fastest times.
constexpr double six_g_inf = 1e5, six_end = 1e3;
const std::vector<std::pair<double, double>> six_terms{{1e5, 1e-6}, {1e5, 1e-4}, {1e5, 1e-2},
                                                       {1e5, 1.0},  {1e5, 1e2},  {1e5, 1e3}};

std::string six_term_case(const std::string& load) {
    std::string text = fmt::format("[material]\nmodel = \"prony\"\nG_inf = {}\nterms = [", six_g_inf);
    for (std::size_t k = 0; k < six_terms.size(); ++k) {
        text += fmt::format("{}[{}, {}]", k == 0 ? "" : ", ", six_terms[k].first, six_terms[k].second);
    }
    return text + fmt::format("]\n[indenter]\nshape = \"flat\"\na = {}\n{}\n[numerics]\nelements = 50\n", a, load);
}

TEST(PronyFastForceStep, TheSixTermCreepFunctionMeetsItsLimits) {
    // J(0+) = 1/(G_inf + sum G_k), J(infinity) = 1/G_inf (numerics-notes), and the standard solid of Table 1.
    const CreepFunction six(six_g_inf, six_terms);
    double instant = six.long_time;
    for (const auto& [c, lambda] : six.terms) instant -= c;
    EXPECT_NEAR(instant, 1.0 / (six_g_inf + 6e5), 1e-12 / six_g_inf);
    const CreepFunction standard(G_inf, {{G1, tau1}});
    for (const double t : {0.0, 1e-3, 1e-2}) {
        const double expected = reference::standard_solid_creep(G_inf, G1, tau1, t);
        EXPECT_NEAR(standard.ramp(1.0, 0.0, t), expected, 1e-12 * expected);
    }
}

TEST(PronyFastForceStep, SixTermSeriesEveryRowWithinOneThousandthOfThePeak) {
    // Force control: d = (1/8a) int J dF. Spring control: d(s) = z(s) k / (k + 8a sG(s)), i.e. d = (k/8a) int
    // J~ dz with J~ the creep function of the series with G_inf + k/8a. Before the grading of finite series:
    // 3.6e-3 and 3.2e-3 of the peak depth.
    const CreepFunction creep(six_g_inf, six_terms);
    constexpr double k = 800.0, z0 = 1e-5;
    const CreepFunction spring_creep(six_g_inf + k / punch_stiffness, six_terms);
    const auto force_run = testing::run_toml(six_term_case(
        fmt::format("[load]\ncontrol = \"force\"\nhistory = [[0.0, 0.0], [{}, {}], [{}, {}]]", ramp, F0, six_end, F0)));
    const double force_error = worst_row_error(force_run.time, force_run.depth, [&](double t) {
        return creep.ramp(F0, ramp, t) / punch_stiffness;
    });
    const auto spring_run = testing::run_toml(six_term_case(fmt::format(
        "[load]\ncontrol = \"spring\"\nspring_constant = {}\nhistory = [[0.0, 0.0], [{}, {}], [{}, {}]]", k, ramp,
        z0, six_end, z0)));
    const double spring_error = worst_row_error(spring_run.time, spring_run.depth, [&](double t) {
        return k / punch_stiffness * spring_creep.ramp(z0, ramp, t);
    });
    RecordProperty("force_error", fmt::format("{:.2e}", force_error));
    RecordProperty("spring_error", fmt::format("{:.2e}", spring_error));
    RecordProperty("steps", std::to_string(force_run.steps));
    EXPECT_LT(force_error, 1e-3);
    EXPECT_LT(spring_error, 1e-3);
}

}  // namespace
}  // namespace mdr
