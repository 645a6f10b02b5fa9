// Convergence orders: the error against closed forms falls as O(dx^2) in the elements (midpoint rule over the
// foundation, numerics notes "Space") and as O(dt^2) in the time step when the contact shrinks (entry and exit
// located inside the step; without that the order would fall to 1). The orders are stated in docs/theory.md.

#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "reference/closed_forms.hpp"
#include "reference/ting.hpp"
#include "convergence.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::expect_orders_above;
using testing::run_toml;

// Root-mean-square force error over the written rows with t >= from, relative to the peak exact force.
template <typename Exact>
double rms_force_error(const drivers::IndentationResult& result, Exact exact, double from) {
    double sum = 0.0, peak = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        const double reference = exact(result.time[i]);
        peak = std::max(peak, std::abs(reference));
        if (result.time[i] < from) continue;
        sum += std::pow(result.force[i] - reference, 2);
        ++count;
    }
    return std::sqrt(sum / static_cast<double>(count)) / peak;
}

TEST(Convergence, ElementsSecondOrderOnTheLoadingBranch) {
    // Standard solid under a sphere, d = v t: Lee-Radok/Ting loading, time-exact in the foundation, so only the
    // element size matters.
    const reference::TingSolution ting(reference::sphere_indenter(0.01), {1e6, 0.0, {{3e6, 0.5}}}, 1e-4, 1.0);
    std::vector<double> errors;
    for (int elements : {100, 200, 400, 800}) {
        const auto result = run_toml(fmt::format(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.5
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4]]
[numerics]
elements = {}
time_step = 1e-3
)",
                                                 elements));
        errors.push_back(rms_force_error(result, [&](double t) { return ting.force(t); }, 0.3));
    }
    expect_orders_above(errors, 1.7, "elements");
}

TEST(Convergence, TimeStepSecondOrderUnderForceControl) {
    // Force control: the depth is not linear inside a step, so here the time step matters. Standard solid under a
    // sphere with a force ramp and hold; the depth follows eq. (34) with the Table 1 creep function.
    const double G_inf = 1e6, G1 = 3e6, tau1 = 0.2, R = 0.01, F0 = 0.5, ramp = 0.5;
    const auto creep = [&](double t) { return reference::standard_solid_creep(G_inf, G1, tau1, t); };
    const auto exact_depth = [&](double t) { return reference::sphere_creep_depth(creep, R, F0, ramp, t); };
    std::vector<double> errors;
    for (double step : {0.02, 0.01, 0.005, 0.0025}) {
        const auto result = run_toml(fmt::format(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.2
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "force"
history = [[0.0, 0.0], [0.5, 0.5], [1.5, 0.5]]
[numerics]
elements = 4000
time_step = {}
)",
                                                 step));
        double worst = 0.0;
        for (std::size_t i = 0; i < result.time.size(); ++i) {
            if (result.time[i] < 0.1) continue;
            worst = std::max(worst, std::abs(result.depth[i] - exact_depth(result.time[i])) / exact_depth(1.5));
        }
        errors.push_back(worst);
    }
    expect_orders_above(errors, 1.7, "time");
}

TEST(Convergence, UserTimeStepWithAParallelDashpotIsGraded) {
    // Force control on a Kelvin-Voigt body: the dashpot sees the trapezoidal rate of the indenter, and a user's
    // time_step is graded after the start as the default is (issue 23; the second order of the trapezoidal rate is
    // checked on uniform steps by KelvinVoigtHarmonic.ForceControlFlatPunchErrorFallsAsTheSquareOfTheStep). Sphere
    // under a force ramp and hold; eq. (34) with the Table 1 creep function. The contact starts from nothing
    // (d ~ t^(4/3)): rows from t = 0.1 s.
    const double G = 1e6, eta = 1e5, R = 0.01, F0 = 0.5, ramp = 0.5;
    const auto creep = [&](double t) { return -std::expm1(-t * G / eta) / G; };
    const auto exact_depth = [&](double t) { return reference::sphere_creep_depth(creep, R, F0, ramp, t); };
    std::vector<double> errors;
    for (double step : {0.02, 0.01, 0.005, 0.0025}) {
        const auto result = run_toml(fmt::format(R"(
[material]
model = "kelvin_voigt"
G = 1.0e6
eta = 1.0e5
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "force"
history = [[0.0, 0.0], [0.5, 0.5], [1.5, 0.5]]
[numerics]
elements = 4000
time_step = {}
)",
                                                 step));
        double worst = 0.0;
        for (std::size_t i = 0; i < result.time.size(); ++i) {
            if (result.time[i] < 0.1) continue;
            worst = std::max(worst, std::abs(result.depth[i] - exact_depth(result.time[i])) / exact_depth(1.5));
        }
        errors.push_back(worst);
    }
    for (std::size_t i = 0; i < errors.size(); ++i) {
        RecordProperty(fmt::format("error_{}", i), fmt::format("{:.2e}", errors[i]));
        EXPECT_LT(errors[i], 1e-4) << "step " << i;
    }
}

TEST(Convergence, UnloadingIsNotLimitedByTheTimeStep) {
    // Ting's triangle: elements leave contact inside steps and the exit is located there, so even 50 steps per
    // branch reproduce Ting to 1e-8 of the peak force (it would be O(dt) without the location).
    const reference::TingSolution ting(reference::sphere_indenter(0.01), {1e6, 0.0, {{3e6, 0.5}}}, 1e-4, 1.0);
    const auto result = run_toml(R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.5
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4], [2.0, 0.0]]
[numerics]
elements = 20000
time_step = 0.02
)");
    EXPECT_LT(rms_force_error(result, [&](double t) { return ting.force(t); }, 1.0), 1e-8);
}

}  // namespace
}  // namespace mdr
