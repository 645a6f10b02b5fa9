// The AFM creep segment on a layer (`[load] force_pauses` under spring control with a `[layer]`, docs/theory.md eq.
// L22): the feedback holds the force reached at the pause's start, the depth creeps, the base follows as
// z = d + F / k, and afterwards the base history resumes shifted from the z reached. An elastic layer: nothing moves
// during the pause. A very thick layer: the half-space driver's pause (standard solid, Prony 2), its elements
// converging at second order. A thin layer: the correspondence principle in creep form, F_el(d(t)) =
// int_0^t J(t - s) dF(s) (F_el the elastic layer's force at unit shear modulus, contact::LayerContact), exact while
// the contact grows: a force step from rest (d = F_el^-1(F0 J(t))) and a spring approach solved by a time-stepping
// of its own here, then the pause in closed form. A pause after a partial retract regrows the contact: LayerCells,
// against the half-space driver on a very thick layer.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "convergence.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "run_case.hpp"

namespace mdr {
namespace {

using testing::interpolate;
using testing::run_toml;

constexpr double R = 1e-5, k = 0.05, thin = 2e-6;
// Standard solid G(t) = G_inf + G1 exp(-t / tau1): J(t) = J_inf - dJ exp(-t / tau_c), J_inf = 1 / G_inf,
// J(0) = 1 / (G_inf + G1), tau_c = tau1 (G_inf + G1) / G_inf (Table 1).
constexpr double G_inf = 1e3, G1 = 3e3, tau1 = 0.2;
constexpr double J_inf = 1.0 / G_inf, dJ = 1.0 / G_inf - 1.0 / (G_inf + G1), tau_c = tau1 * (G_inf + G1) / G_inf;
const std::string standard = fmt::format("model = \"standard\"\nG_inf = {}\nG1 = {}\ntau1 = {}", G_inf, G1, tau1);
const std::string prony2 = "model = \"prony\"\nG_inf = 1.0e3\nterms = [[2.0e3, 0.05], [1.5e3, 0.6]]";

// Approach to z = 2 um at t = 1 s, the pause [1, 2] (the history's hold there unused), retract to -0.5 um at 3 s.
const std::string program = "history = [[0.0, 0.0], [1.0, 2.0e-6], [2.0, 2.0e-6], [3.0, -0.5e-6]]\n"
                            "force_pauses = [[1.0, 2.0]]";
constexpr double t1 = 1.0, t2 = 2.0;

std::string case_text(const std::string& material, const std::string& load, const std::string& layer,
                      const std::string& numerics = "") {
    return fmt::format("[material]\n{}\n[indenter]\nshape = \"sphere\"\nR = {}\n[load]\ncontrol = \"spring\"\n"
                       "spring_constant = {}\n{}\n{}\n{}",
                       material, R, k, load, layer, numerics);
}
std::string layer(double thickness) {
    return fmt::format("[layer]\nthickness = {}\ninterface = \"bonded\"", thickness);
}

std::size_t row_at(const drivers::IndentationResult& result, double t) {
    for (std::size_t n = 0; n < result.time.size(); ++n) {
        if (result.time[n] == t) return n;
    }
    ADD_FAILURE() << "no row at t = " << t;
    return 0;
}

// The depth solves' force tolerance on a layer: 5e-8 of k max z (layer_indentation.cpp).
constexpr double solve_tolerance = 5e-8 * k * 2e-6;

// The pause's rules on every row: the force held at its start's, z = d + F / k inside (both to the solves' tolerance:
// F(t1) = k (z - d) is solved); after it z resumes from the z reached with the history's slope (-2.5e-6 m/s) and
// F = k (z - d).
void expect_pause_rules(const drivers::IndentationResult& result) {
    const std::size_t start = row_at(result, t1), end = row_at(result, t2);
    const double held = result.force[start];
    ASSERT_GT(held, 0.0);
    for (std::size_t n = start; n <= end; ++n) {
        EXPECT_NEAR(result.force[n], held, solve_tolerance) << "t " << result.time[n];
        EXPECT_NEAR(result.base[n], result.depth[n] + held / k, solve_tolerance / k);
    }
    for (std::size_t n = end + 1; n < result.time.size(); ++n) {
        EXPECT_NEAR(result.base[n], result.base[end] - 2.5e-6 * (result.time[n] - t2), 1e-12 * 2e-6);
        EXPECT_NEAR(result.force[n], std::max(0.0, k * (result.base[n] - result.depth[n])), 1e-6 * held);
    }
}

TEST(LayerForcePause, ElasticLayerDepthStaysPutAndTheBaseResumesShifted) {
    const auto result = run_toml(case_text("model = \"elastic\"\nG = 4.0e3", program, layer(thin)));
    const std::size_t start = row_at(result, t1), end = row_at(result, t2);
    for (std::size_t n = start; n <= end; ++n) {
        // F(d) = F held has one root, the depth at the start, found to the solve's force tolerance: the depth to
        // that over dF/dd >= F/d (a growing contact's force rises faster than the depth), and the base with it.
        const double depth_tolerance = solve_tolerance / result.force[start] * result.depth[start];
        EXPECT_NEAR(result.depth[n], result.depth[start], depth_tolerance) << "t " << result.time[n];
        EXPECT_NEAR(result.base[n], 2e-6, depth_tolerance);
    }
    expect_pause_rules(result);
}

// The half-space driver at `elements` (empty: its default) and the very thick layer's run, the largest differences
// of depth (over the deepest) and of force (over the peak).
struct Difference {
    double depth = 0.0, force = 0.0;
};
Difference against_half_space(const std::string& material, const drivers::IndentationResult& thick,
                              const std::string& elements = "") {
    const auto half_space = run_toml(case_text(material, program, "", elements));
    EXPECT_EQ(half_space.time.size(), thick.time.size());
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    const double peak = *std::max_element(half_space.force.begin(), half_space.force.end());
    Difference difference;
    for (std::size_t i = 0; i < std::min(half_space.time.size(), thick.time.size()); ++i) {
        EXPECT_EQ(half_space.time[i], thick.time[i]);
        difference.depth = std::max(difference.depth, std::abs(half_space.depth[i] - thick.depth[i]) / deepest);
        difference.force = std::max(difference.force, std::abs(half_space.force[i] - thick.force[i]) / peak);
    }
    return difference;
}

void expect_thick_layer_is_the_half_space(const std::string& material, const std::string& name) {
    const auto thick = run_toml(case_text(material, program, layer(1e3)));
    expect_pause_rules(thick);
    const std::size_t start = row_at(thick, t1), end = row_at(thick, t2);
    EXPECT_GT(thick.depth[end], 1.1 * thick.depth[start]);  // it crept
    const Difference at_default = against_half_space(material, thick);
    ::testing::Test::RecordProperty("depth_difference", fmt::format("{:.3g}", at_default.depth));
    ::testing::Test::RecordProperty("force_difference", fmt::format("{:.3g}", at_default.force));
    EXPECT_LT(at_default.depth, 2e-6);
    EXPECT_LT(at_default.force, 2e-6);
    // The difference is the half-space driver's elements' (the layer's is O(a/h) = 1e-8): second order in them.
    std::vector<double> errors;
    for (const int elements : {250, 500, 1000}) {
        errors.push_back(
            against_half_space(material, thick, fmt::format("[numerics]\nelements = {}", elements)).depth);
    }
    testing::expect_orders_above(errors, 1.7, name);
}

TEST(LayerForcePause, VeryThickLayerIsTheHalfSpaceDriverStandardSolid) {
    expect_thick_layer_is_the_half_space(standard, "thick_layer_pause_standard");
}

TEST(LayerForcePause, VeryThickLayerIsTheHalfSpaceDriverProny2) {
    expect_thick_layer_is_the_half_space(prony2, "thick_layer_pause_prony2");
}

TEST(LayerForcePause, VeryThickLayerWithAParallelDashpotIsTheHalfSpaceDriver) {
    // Kelvin-Voigt: the dashpot sees the trapezoidal rate of the solved depth through the pause's ends (the force
    // continuous, so is the rate). The approach differs by the half-space's own early spike (its elements on the
    // small contact with the graded steps, test_force_pause.cpp: 6.4e-4 of its own), observed 8.3e-5; from the
    // pause on by 1.2e-6.
    const std::string kelvin_voigt = "model = \"kelvin_voigt\"\nG = 1.0e3\neta = 100.0";
    const auto thick = run_toml(case_text(kelvin_voigt, program, layer(1e3)));
    const auto half_space = run_toml(case_text(kelvin_voigt, program, ""));
    expect_pause_rules(thick);
    ASSERT_EQ(thick.time.size(), half_space.time.size());
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    const double peak = *std::max_element(half_space.force.begin(), half_space.force.end());
    double approach = 0.0, later = 0.0;
    for (std::size_t n = 0; n < thick.time.size(); ++n) {
        const double difference = std::max(std::abs(thick.depth[n] - half_space.depth[n]) / deepest,
                                           std::abs(thick.force[n] - half_space.force[n]) / peak);
        (thick.time[n] < t1 ? approach : later) = std::max(thick.time[n] < t1 ? approach : later, difference);
    }
    ::testing::Test::RecordProperty("approach_difference", fmt::format("{:.3g}", approach));
    ::testing::Test::RecordProperty("pause_and_after_difference", fmt::format("{:.3g}", later));
    EXPECT_LT(approach, 3e-4);
    EXPECT_LT(later, 5e-6);
}

// The elastic layer at unit shear modulus: P(d) = 4 F_unit (E* = 4 G, incompressible), and the depth at which
// P = `force` solved over the contact radius by the secant method from `radius` (both rise with the radius).
struct ElasticLayer {
    contact::LayerContact layer;
    explicit ElasticLayer(const drivers::ContactCase& thin_case)
        : layer(*thin_case.layer, 0.5, thin_case.indenter, 2e-5) {}
    // The radius at which residual(state) = 0, residual rising with the radius.
    template <typename Residual>
    contact::LayerContactState solve(const Residual& residual, double radius) const {
        double a0 = radius, a1 = 1.01 * radius;
        auto s0 = layer.at_radius(a0), s1 = layer.at_radius(a1);
        double r0 = residual(s0), r1 = residual(s1);
        for (int i = 0; i < 60 && r1 != 0.0 && std::abs(a1 - a0) > 1e-15 * a1; ++i) {
            const double a2 = std::clamp(a1 - r1 * (a1 - a0) / (r1 - r0), 0.5 * a1, 2.0 * a1);
            a0 = a1, r0 = r1;
            a1 = a2, s1 = layer.at_radius(a1), r1 = residual(s1);
        }
        return s1;
    }
    contact::LayerContactState at_force(double force, double radius) const {
        return solve([&](const contact::LayerContactState& s) { return 4.0 * s.force - force; }, radius);
    }
};

drivers::ContactCase thin_case() { return io::parse_case(case_text(standard, program, layer(thin))); }

TEST(LayerForcePause, ForceStepFromRestCreepsAsTheCorrespondencePrinciple) {
    // F = F0 from t = 0 (force control, the pause's equation with no approach): P(d(t)) = F0 J(t) exactly.
    const double F0 = 5e-8;
    const auto result = run_toml(fmt::format(
        "[material]\n{}\n[indenter]\nshape = \"sphere\"\nR = {}\n[load]\ncontrol = \"force\"\n"
        "history = [[0.0, 0.0], [0.0, {}], [2.0, {}]]\n{}",
        standard, R, F0, F0, layer(thin)));
    const ElasticLayer elastic(thin_case());
    double largest = 0.0, radius = 1e-6;
    for (std::size_t n = 1; n < result.time.size(); ++n) {
        const double t = result.time[n];
        const auto state = elastic.at_force(F0 * (J_inf - dJ * std::exp(-t / tau_c)), radius);
        radius = state.contact_radius;
        largest = std::max(largest, std::abs(result.depth[n] - state.depth) / state.depth);
    }
    ::testing::Test::RecordProperty("depth_error", fmt::format("{:.3g}", largest));
    // The solves' tolerances (the force to 5e-8, the contact's depth to 1e-8) and the time-stepping's (F_el linear over
    // each step, O(dt^2)): observed 7.1e-8.
    EXPECT_LT(largest, 2e-7);
}

// The spring approach z = rate t in creep form: P(d) = J_inf F - dJ q, q(t) = int_0^t exp(-(t - s) / tau_c) dF(s),
// on `steps` uniform steps with F linear in time over each: q_{n+1} = e q_n + beta (F_{n+1} - F_n),
// e = exp(-dt / tau_c), beta = (tau_c / dt)(1 - e), F = k (z - d); each step's depth the root of
// P(d) - (J_inf - dJ beta) k (z - d) + dJ (e q_n - beta F_n) (rising in d). The pause holds F: q decays as
// exp(-(t - t1) / tau_c) and P(d(t)) = J_inf F(t1) - dJ q(t1) exp(-(t - t1) / tau_c).
struct SpringCreepReference {
    const ElasticLayer& elastic;
    std::vector<double> time{0.0}, force{0.0};
    double q = 0.0;

    SpringCreepReference(const ElasticLayer& layer, int steps) : elastic(layer) {
        const double dt = t1 / steps, e = std::exp(-dt / tau_c), beta = -std::expm1(-dt / tau_c) * tau_c / dt;
        double radius = 1e-7;
        for (int n = 1; n <= steps; ++n) {
            const double z = 2e-6 * t1 * n / steps, F = force.back();
            const auto state = elastic.solve(
                [&](const contact::LayerContactState& s) {
                    return 4.0 * s.force - (J_inf - dJ * beta) * k * (z - s.depth) + dJ * (e * q - beta * F);
                },
                radius);
            radius = state.contact_radius;
            const double F_new = k * (z - state.depth);
            q = e * q + beta * (F_new - F);
            time.push_back(t1 * n / steps);
            force.push_back(F_new);
        }
    }
    double depth_in_pause(double t, double radius) const {
        return elastic.at_force(J_inf * force.back() - dJ * q * std::exp(-(t - t1) / tau_c), radius).depth;
    }
};

TEST(LayerForcePause, ThinLayerCreepsAsTheCorrespondencePrincipleAfterTheSpringApproach) {
    const auto result = run_toml(case_text(standard, program, layer(thin)));
    expect_pause_rules(result);
    const ElasticLayer elastic(thin_case());
    const SpringCreepReference reference(elastic, 2000), half(elastic, 1000);
    const std::size_t start = row_at(result, t1), end = row_at(result, t2);
    const double radius = result.radius[end];
    const double depth = reference.depth_in_pause(t2, radius);
    EXPECT_NEAR(half.depth_in_pause(t2, radius), depth, 1e-7 * depth);  // the reference has converged
    const double peak = reference.force.back();
    double approach = 0.0, pause = 0.0;
    for (std::size_t n = 1; n <= start; ++n) {
        const double expected = interpolate(reference.time, reference.force, result.time[n]);
        approach = std::max(approach, std::abs(result.force[n] - expected) / peak);
    }
    for (std::size_t n = start; n <= end; ++n) {
        pause = std::max(pause, std::abs(result.depth[n] - reference.depth_in_pause(result.time[n], radius)) / depth);
    }
    ::testing::Test::RecordProperty("approach_error", fmt::format("{:.3g}", approach));
    ::testing::Test::RecordProperty("pause_error", fmt::format("{:.3g}", pause));
    EXPECT_LT(approach, 1e-5);
    EXPECT_LT(pause, 1e-5);
    EXPECT_GT(result.depth[end], 1.05 * result.depth[start]);  // it crept
}

TEST(LayerForcePause, APauseAfterAPartialRetractRegrowsOnCellsAsTheHalfSpace) {
    // The base falls from 2 to 1.6 um before the pause: the contact recedes, and under the held force it grows
    // again (outside Ting's class): LayerCells, on a very thick layer against the half-space driver.
    const std::string regrowing = "history = [[0.0, 0.0], [1.0, 2.0e-6], [1.2, 1.6e-6], [2.2, 1.6e-6], "
                                  "[3.0, -0.5e-6]]\nforce_pauses = [[1.2, 2.2]]";
    const auto thick = run_toml(case_text(standard, regrowing, layer(1e3)));
    const auto half_space = run_toml(case_text(standard, regrowing, ""));
    ASSERT_EQ(thick.time.size(), half_space.time.size());
    EXPECT_EQ(thick.numerics.elements, 400U);  // the cells' default: it ran on LayerCells
    const std::size_t start = row_at(thick, 1.2), end = row_at(thick, 2.2);
    const double held = thick.force[start];
    double grown = 0.0;
    for (std::size_t n = start; n <= end; ++n) {
        EXPECT_NEAR(thick.force[n], held, 1e-9 * held);
        EXPECT_NEAR(thick.base[n], thick.depth[n] + held / k, 1e-12 * 2e-6);
        grown = std::max(grown, thick.radius[n] - thick.radius[start]);
    }
    EXPECT_GT(grown, 0.01 * thick.radius[start]);  // the contact grew again in the pause
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    const double peak = *std::max_element(half_space.force.begin(), half_space.force.end());
    double depth = 0.0, force = 0.0;
    for (std::size_t n = 0; n < thick.time.size(); ++n) {
        depth = std::max(depth, std::abs(thick.depth[n] - half_space.depth[n]) / deepest);
        force = std::max(force, std::abs(thick.force[n] - half_space.force[n]) / peak);
        EXPECT_NEAR(thick.base[n], half_space.base[n], 1e-3 * 2e-6);
    }
    ::testing::Test::RecordProperty("depth_difference", fmt::format("{:.3g}", depth));
    ::testing::Test::RecordProperty("force_difference", fmt::format("{:.3g}", force));
    EXPECT_LT(depth, 1e-3);  // the cells' error, second order in the cell (default_layer_cells: ~1e-4 of the peak)
    EXPECT_LT(force, 1e-3);
}

TEST(LayerForcePause, APauseWithoutContactIsRefusedNamingIt) {
    const std::string early = "history = [[0.0, -1.0e-6], [1.0, 2.0e-6], [2.0, 2.0e-6], [3.0, -0.5e-6]]\n"
                              "force_pauses = [[0.2, 2.0]]";
    try {
        run_toml(case_text(standard, early, layer(thin)));
        FAIL() << "ran";
    } catch (const InvalidInput& error) {
        EXPECT_NE(std::string(error.what()).find("load.force_pauses[0]"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("no contact"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace mdr
