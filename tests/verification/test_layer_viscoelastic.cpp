// A viscoelastic layer under a growing contact (docs/theory.md, "Layers"): the driver's Prony recursion against a
// direct quadrature of the Lee-Radok convolution, and a very thick layer against the half-space driver.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lee_radok_ramp.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/profile/profile.hpp"

namespace {

std::string layer_case(const std::string& layer,
                       const std::string& history = "[[0.0, 0.0], [1.0, 1.0e-6], [3.0, 1.0e-6]]",
                       const std::string& control = "displacement") {
    return R"(
[material]
model = "standard"
G_inf = 1.0e3
G1 = 3.0e3
tau1 = 0.2
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = ")" + control + R"("
history = )" + history + "\n" + layer;
}

TEST(LayerViscoelastic, DriverMatchesTheDirectLeeRadokConvolution) {
    // Bonded and sliding: the separation of eq. L11 does not depend on the kernel, the kernel on the interface.
    for (const std::string interface : {"bonded", "sliding"}) {
        const auto contact_case = mdr::io::parse_case(
            layer_case("[layer]\nthickness = 2.0e-6\ninterface = \"" + interface + "\"\n"));
        const auto result = mdr::drivers::run_case(contact_case);
        const mdr::contact::LayerContact layer(*contact_case.layer, 0.5, contact_case.indenter, 1e-5);
        // F(t) = G_inf F_el(d(t)) + G1 [F_el(d(t)) - (1/tau) int_0^t exp(-(t - s)/tau) F_el(d(s)) ds] (by parts,
        // F_el(0) = 0), F_el = 4 (E* = 4G) times the unit force; composite 8-point Gauss-Legendre, 100 panels on
        // the ramp, the hold in closed form.
        const double g_inf = 1e3, g1 = 3e3, tau = 0.2;
        const auto depth = [](double s) { return 1e-6 * std::min(s, 1.0); };
        double hint = 0.0;  // the previous radius: the secant's start
        const auto elastic = [&](double s) {
            const auto state = layer.at_depth(depth(s), hint);
            hint = state.contact_radius;
            return 4.0 * state.force;
        };
        const auto direct = [&](double t) { return mdr::testing::ramp_and_hold_force(t, g_inf, g1, tau, elastic); };
        const double peak = *std::max_element(result.force.begin(), result.force.end());
        const std::size_t rows = result.time.size();
        for (const std::size_t row : {rows / 8, rows / 3, rows / 2, rows - 1}) {
            EXPECT_NEAR(result.force[row], direct(result.time[row]), 1e-5 * peak)
                << interface << " t " << result.time[row];
            EXPECT_NEAR(result.radius[row], layer.at_depth(depth(result.time[row])).contact_radius, 1e-9) << interface;
        }
    }
}

TEST(LayerViscoelastic, VeryThickLayerIsTheHalfSpaceDriver) {
    const auto half_space = mdr::drivers::run_case(mdr::io::parse_case(layer_case("")));
    const auto thick = mdr::drivers::run_case(
        mdr::io::parse_case(layer_case("[layer]\nthickness = 1.0e3\ninterface = \"sliding\"\n")));
    ASSERT_EQ(half_space.time.size(), thick.time.size());
    const double peak = *std::max_element(half_space.force.begin(), half_space.force.end());
    double largest = 0.0;
    for (std::size_t i = 0; i < half_space.time.size(); ++i) {
        ASSERT_EQ(half_space.time[i], thick.time[i]);
        largest = std::max(largest, std::abs(half_space.force[i] - thick.force[i]) / peak);
    }
    // The half-space driver's own error (midpoint elements, O((dx/a)^2), contact_case.hpp default_elements) is
    // below this at its defaults; the layer's, O(a/h) = 1e-8 here.
    EXPECT_LT(largest, 1e-6);
}

TEST(LayerViscoelastic, VeryThickLayerUnloadsAsTheHalfSpaceDriver) {
    // Ting's receding contact on the layer (theory.md eq. L12, L13) against the half-space driver's elements, which
    // know nothing of t1: a triangle whose contact is lost at t ~ 1.5 s, before the depth returns to zero.
    const std::string triangle = "[[0.0, 0.0], [1.0, 1.0e-6], [2.0, 0.0]]";
    const auto half_space = mdr::drivers::run_case(mdr::io::parse_case(layer_case("", triangle)));
    const auto thick = mdr::drivers::run_case(
        mdr::io::parse_case(layer_case("[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n", triangle)));
    ASSERT_EQ(half_space.time.size(), thick.time.size());
    const double peak = *std::max_element(half_space.force.begin(), half_space.force.end());
    const double widest = *std::max_element(half_space.radius.begin(), half_space.radius.end());
    double force_error = 0.0, radius_error = 0.0;
    for (std::size_t i = 0; i < half_space.time.size(); ++i) {
        force_error = std::max(force_error, std::abs(half_space.force[i] - thick.force[i]) / peak);
        radius_error = std::max(radius_error, std::abs(half_space.radius[i] - thick.radius[i]) / widest);
    }
    EXPECT_EQ(thick.force.back(), 0.0);
    EXPECT_GT(thick.force[thick.force.size() * 5 / 8], 0.0);  // t = 1.25 s: still in contact
    // Observed 2.9e-7 and 4.1e-6: the half-space driver's elements (its contact edge located between them).
    EXPECT_LT(force_error, 1e-6);
    EXPECT_LT(radius_error, 1e-5);
}

TEST(LayerViscoelastic, VeryThickLayerUnderForceControlIsTheHalfSpaceDriver) {
    // A force triangle, then none: the contact grows (also after the peak, by creep), recedes, and the indenter
    // rides on the recovering surface; the layer's depth solved each step against the half-space driver's.
    const std::string triangle = "[[0.0, 0.0], [1.0, 3.0e-8], [2.0, 0.0], [3.0, 0.0]]";
    const auto half_space = mdr::drivers::run_case(mdr::io::parse_case(layer_case("", triangle, "force")));
    const auto thick = mdr::drivers::run_case(mdr::io::parse_case(
        layer_case("[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n", triangle, "force")));
    ASSERT_EQ(half_space.time.size(), thick.time.size());
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    const double widest = *std::max_element(half_space.radius.begin(), half_space.radius.end());
    double early = 0.0, late = 0.0, radius_error = 0.0;
    for (std::size_t i = 0; i < half_space.time.size(); ++i) {
        const double error = std::abs(half_space.depth[i] - thick.depth[i]) / deepest;
        double& largest = half_space.time[i] < 0.5 ? early : late;
        largest = std::max(largest, error);
        if (half_space.force[i] > 0.0) {
            radius_error = std::max(radius_error, std::abs(half_space.radius[i] - thick.radius[i]) / widest);
        }
    }
    // The half-space driver's own error at its default elements: observed 2.8e-6 at the first steps (a contact
    // over few elements), 4.5e-7 from t = 0.5 s on; the radius, its contact edge, 1.4e-4.
    EXPECT_LT(early, 5e-6);
    EXPECT_LT(late, 1e-6);
    EXPECT_LT(radius_error, 5e-4);
    EXPECT_GT(thick.depth.back(), 0.0);  // riding on the surface, which has not recovered yet
    EXPECT_EQ(thick.force.back(), 0.0);
}

TEST(LayerViscoelastic, VeryThickLayerUnderAForceRampCreepsAsLeeRadoksClosedForm) {
    // h -> infinity against the half-space's exact solution rather than its driver (whose elements leave 2e-6 at the
    // first steps): a force ramp F = F0 t/T to T, then held. While the contact grows, Lee-Radok's creep form
    // (theory.md eq. L22 with the Hertz force (16/3) G sqrt(R) d^(3/2), E* = 4G) gives d(t)^(3/2) = 3/(16 sqrt(R))
    // int_0^t J(t - s) dF(s), with the standard solid's creep function J(t) = 1/G_inf - (1/G_inf - 1/G_0)
    // exp(-t/tau_c), G_0 = G_inf + G1, tau_c = tau1 G_0/G_inf (Table 1), integrated over the ramp in closed form.
    const double radius = 1e-5, force = 3e-8, ramp = 1.0, g_inf = 1e3, g_0 = 4e3, tau_c = 0.2 * g_0 / g_inf;
    const auto exact = [&](double t) {
        const double loaded = std::min(t, ramp);
        const double creep = loaded / g_inf - (1.0 / g_inf - 1.0 / g_0) * tau_c *
                                                  (std::exp(-(t - loaded) / tau_c) - std::exp(-t / tau_c));
        return std::pow(3.0 / (16.0 * std::sqrt(radius)) * force / ramp * creep, 2.0 / 3.0);
    };
    const auto thick = mdr::drivers::run_case(
        mdr::io::parse_case(layer_case("[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n",
                                       "[[0.0, 0.0], [1.0, 3.0e-8], [3.0, 3.0e-8]]", "force")));
    const double deepest = exact(thick.time.back());
    double largest = 0.0;
    for (std::size_t i = 0; i < thick.time.size(); ++i) {
        largest = std::max(largest, std::abs(thick.depth[i] - exact(thick.time[i])) / deepest);
    }
    // Observed 2.0e-7 at the default numerics (2001 steps; 1.2e-7 at 30000), at every time.
    EXPECT_LT(largest, 1e-6);
}

TEST(LayerViscoelastic, VeryThickLayerUnderSpringControlIsTheHalfSpaceDriver) {
    // The AFM set-up: the base z rises to 2 um and falls below the surface through a cantilever of 0.05 N/m (about
    // the contact's own stiffness at the peak); the indenter presses in, the contact grows, recedes, the indenter
    // lifts off and hangs at the base (d = z) while the surface recovers. The layer's F(d) + k d = k z solved each
    // step against the half-space driver's.
    const std::string base = "[[0.0, 0.0], [1.0, 2.0e-6], [2.0, -0.5e-6], [3.0, -0.5e-6]]\nspring_constant = 0.05";
    const auto half_space = mdr::drivers::run_case(mdr::io::parse_case(layer_case("", base, "spring")));
    const auto thick = mdr::drivers::run_case(mdr::io::parse_case(
        layer_case("[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n", base, "spring")));
    ASSERT_EQ(half_space.time.size(), thick.time.size());
    ASSERT_EQ(thick.base.size(), thick.time.size());
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    const double peak = *std::max_element(half_space.force.begin(), half_space.force.end());
    double depth_error = 0.0, force_error = 0.0;
    for (std::size_t i = 0; i < half_space.time.size(); ++i) {
        depth_error = std::max(depth_error, std::abs(half_space.depth[i] - thick.depth[i]) / deepest);
        force_error = std::max(force_error, std::abs(half_space.force[i] - thick.force[i]) / peak);
        EXPECT_EQ(thick.base[i], half_space.base[i]);
        // F = k (z - d) (the spring's law) on every row.
        EXPECT_NEAR(thick.force[i], 0.05 * (thick.base[i] - thick.depth[i]), 1e-6 * peak) << "t " << thick.time[i];
    }
    // Observed 3.0e-7 and 4.6e-7: the half-space driver's elements.
    EXPECT_LT(depth_error, 1e-6);
    EXPECT_LT(force_error, 1e-6);
    EXPECT_EQ(thick.force.back(), 0.0);  // lifted off
    EXPECT_EQ(thick.depth.back(), -0.5e-6);  // hanging at the base
}

TEST(LayerViscoelastic, FlatPunchUnderForceControlOnAVeryThickLayerIsTheHalfSpaceDriver) {
    // A flat profile gives no depth scale: the depth solves' brackets grew from a zero step, for ever, before they
    // took the punch's radius. The punch's force is the full convolution F = k int_0^t G dd while in contact (L13
    // with L12 for a linear F_el), the half-space's.
    const std::string triangle = "[[0.0, 0.0], [1.0, 3.0e-8], [2.0, 0.0], [3.0, 0.0]]";
    const auto punch = [&](const std::string& layer) {
        std::string text = layer_case(layer, triangle, "force");
        const std::string sphere = "shape = \"sphere\"\nR = 1.0e-5";
        text.replace(text.find(sphere), sphere.size(), "shape = \"flat\"\na = 2.0e-6");
        return mdr::drivers::run_case(mdr::io::parse_case(text));
    };
    const auto half_space = punch("");
    const auto thick = punch("[layer]\nthickness = 1.0e3\ninterface = \"bonded\"\n");
    ASSERT_EQ(half_space.time.size(), thick.time.size());
    const double deepest = *std::max_element(half_space.depth.begin(), half_space.depth.end());
    for (std::size_t i = 0; i < half_space.time.size(); ++i) {
        EXPECT_NEAR(thick.depth[i], half_space.depth[i], 1e-6 * deepest) << "t " << half_space.time[i];  // 2.3e-9
    }
}

TEST(LayerViscoelastic, AHeldDepthThatTheRecoveringSurfaceReachesAgainTouchesWhenTheHalfSpaceDoes) {
    // The centre of the layer's surface recovers as the half-space's after the contact is lost (eq. L14), so the
    // contact regrows (on LayerCells, eq. L16 to L19) when the half-space driver's touches again: within one step
    // (the layer's innermost cell sits at dx/2, the half-space's element likewise).
    const std::string layer = "[layer]\nthickness = 2.0e-6\ninterface = \"bonded\"\n";
    const std::string held = "[[0.0, 0.0], [1.0, 1.0e-6], [1.1, 0.2e-6], [5.0, 0.2e-6]]";
    const auto on_layer = mdr::drivers::run_case(mdr::io::parse_case(layer_case(layer, held)));
    const auto half_space = mdr::drivers::run_case(mdr::io::parse_case(layer_case("", held)));
    const auto touches_again = [](const mdr::drivers::IndentationResult& result) {
        std::size_t row = 0;
        while (result.time[row] < 1.1 || result.force[row] == 0.0) ++row;
        return result.time[row];
    };
    const double step = half_space.time[1] - half_space.time[0];
    EXPECT_NEAR(touches_again(on_layer), touches_again(half_space), 1.01 * step);
}

// The profile of another that counts the layer's contact solves: each evaluates the equivalent profile at its Gauss
// nodes in ascending order, then at the contact's edge, so a solve starts where x falls below the previous call's.
class SolveCountingProfile : public mdr::profile::Profile {
public:
    explicit SolveCountingProfile(std::shared_ptr<const mdr::profile::Profile> profile)
        : profile_(std::move(profile)) {}
    double gap(double r) const override { return profile_->gap(r); }
    double equivalent(double x) const override {
        if (x < last_) ++solves_;
        last_ = x;
        return profile_->equivalent(x);
    }
    double contact_radius(double depth) const override { return profile_->contact_radius(depth); }
    double max_radius() const override { return profile_->max_radius(); }
    bool is_flat_punch() const override { return profile_->is_flat_punch(); }
    std::vector<double> kinks() const override { return profile_->kinks(); }
    double flat_radius() const override { return profile_->flat_radius(); }
    std::optional<double> power_law_exponent() const override { return profile_->power_law_exponent(); }
    std::optional<double> tip_radius() const override { return profile_->tip_radius(); }
    std::string describe() const override { return profile_->describe(); }
    mdr::profile::ProfileDefinition definition() const override { return profile_->definition(); }
    std::size_t solves() const { return solves_; }

private:
    std::shared_ptr<const mdr::profile::Profile> profile_;
    mutable double last_ = 0.0;
    mutable std::size_t solves_ = 0;
};

TEST(LayerViscoelastic, ARecedingDepthAmidLoadingEquilibriaIsInterpolatedWithoutASolve) {
    // While the contact recedes, Ting's d(t1) lies amid four loading steps' equilibria (depths ~1.5e-3 of d apart at
    // the thin film's peak, a/h 15): a^2, F and dF/dd interpolated in d meet the solve's tolerance there, so no
    // solve. Checked against the equilibrium solved at the interpolated radius: its depth is the one asked to a tenth
    // of the solve's tolerance (1e-8 of d), its force and stiffness are the interpolated ones.
    const auto contact_case = mdr::io::parse_case(R"(
[material]
model = "prony"
G_inf = 300.0
terms = [[700.0, 0.1], [400.0, 1.0]]
[indenter]
shape = "sphere"
R = 500e-6
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 0.2e-6]]
[layer]
thickness = 1e-6
interface = "bonded"
)");
    const auto counting = std::make_shared<const SolveCountingProfile>(contact_case.indenter);
    const mdr::contact::LayerContact layer(*contact_case.layer, 0.5, counting, 30e-6);
    std::vector<mdr::contact::LayerContactState> loading;
    for (int k = 0; k < 4; ++k) loading.push_back(layer.at_radius(15e-6 * (1.0 + 4e-4 * k)));
    const double depth = 0.5 * (loading[1].depth + loading[2].depth);
    const std::size_t solves = counting->solves();
    const mdr::contact::LayerContactState receding = layer.at_depth(depth, loading);
    EXPECT_EQ(counting->solves(), solves);
    const mdr::contact::LayerContactState solved = layer.at_radius(receding.contact_radius);
    EXPECT_NEAR(solved.depth / depth, 1.0, 1e-9);
    EXPECT_NEAR(receding.force / solved.force, 1.0, 1e-9);
    EXPECT_NEAR(receding.stiffness / solved.stiffness, 1.0, 1e-9);
}

TEST(LayerViscoelastic, ThinFilmLoadUnloadSolvesTheContactAboutOnceAStep) {
    // Issue 28's thin film (docs/performance.md): a colloidal probe on a bonded layer, a/h up to 19, ramp, hold,
    // unload. Each step that moves the depth solves the contact at one depth (the loading's, or Ting's d(t1) while it
    // recedes): started from the radii of the steps around that depth, one solve meets the depth's tolerance
    // (1e-8 of d) at most steps (1.25 a step); from the last radius alone (a ~ sqrt(d)) it took 3.6.
    auto contact_case = mdr::io::parse_case(R"(
[material]
model = "prony"
G_inf = 300.0
terms = [[700.0, 0.1], [400.0, 1.0]]
[indenter]
shape = "sphere"
R = 500e-6
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 0.2e-6], [2.0, 0.2e-6], [3.0, 0.0]]
[layer]
thickness = 1e-6
interface = "bonded"
)");
    const auto counting = std::make_shared<const SolveCountingProfile>(contact_case.indenter);
    contact_case.indenter = counting;
    const auto result = mdr::drivers::run_case(contact_case);
    std::size_t moving = 0;  // steps in contact that change the depth
    for (std::size_t i = 1; i < result.time.size(); ++i) {
        if (result.radius[i] > 0.0 && result.depth[i] != result.depth[i - 1]) ++moving;
    }
    EXPECT_GT(moving, 900u);  // the contact is lost at t ~ 2.5 s
    EXPECT_LT(static_cast<double>(counting->solves()), 1.5 * static_cast<double>(moving)) << counting->solves();
    // Each loading row at its depth, solved afresh: both radii meet the depth to 1e-8 of d, so each other to ~1e-8.
    const mdr::contact::LayerContact layer(*contact_case.layer, 0.5, contact_case.indenter, 30e-6);
    for (const std::size_t row : {std::size_t{100}, std::size_t{400}, std::size_t{666}}) {
        EXPECT_NEAR(result.radius[row] / layer.at_depth(result.depth[row]).contact_radius, 1.0, 2e-8) << row;
    }
}

}  // namespace
