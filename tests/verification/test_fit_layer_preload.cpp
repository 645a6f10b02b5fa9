// A preloaded record on a layer (`[[fit.data]] start = "preloaded"` with a `[layer]`; docs/theory.md 4d, eq. L21):
// the moduli, the contact point (hence the preload depth d_0) and the thickness fitted back from a relaxation made
// independently of mdr's drivers and of the fit's interpolated model. The history (a jump to d_0 held 40 relaxation
// times, then a ramp and a hold) has a contact that only grows, so Lee & Radok is exact: F(t) = G(t) F_el(d_0) +
// int_8^t G(t - s) dF_el(d(s)), by direct quadrature (tests/support/lee_radok_ramp.hpp) of the layer's elastic
// solution (contact::LayerContact::at_depth: against scipy in test_layer_contact.cpp and an own finite-element model,
// tests/cli/layer_fe.py). And for h -> inf the half-space's preloaded fit of the same quadrature of Hertz's force.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lee_radok_ramp.hpp"
#include "mdr/contact/layer_contact.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr {
namespace {

constexpr double G_inf = 1e3, G1 = 3e3, tau1 = 0.2;  // Pa, Pa, s: the truth
constexpr double radius = 1e-5;                      // m, the sphere
constexpr double thickness = 2e-6;                   // m
constexpr double preload = 0.4e-6, top = 1.2e-6;     // m: d_0 from t = 0, the ramp's end
constexpr double ramp_start = 8.0;                   // s: 40 tau1 at d_0, then the ramp over 1 s
constexpr double offset = 3e-6;  // the data's zero of depth lies 3 um above the surface: contact point -3 um

// The fit's model case: a bonded layer h = 2 um under a sphere R = 10 um (its half-space contact radius at 1.2 um:
// 1.7 h). Its history is not used: the fit takes the record's depths.
std::string layer_case() {
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
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.2e-6]]
[layer]
thickness = 2.0e-6
interface = "bonded"
)";
}

// The times since the ramp's start of the record's rows on the ramp (every 1 ms: the fit's model takes F_el linear
// in time over a row, an error second order in the row, 1.3e-5 of G_inf with h free on 2 ms rows) and the hold (every
// 2 ms; the depth constant there).
std::vector<double> since_ramp_start() {
    std::vector<double> times;
    for (int i = 0; i <= 1000; ++i) times.push_back(1e-3 * i);
    for (int i = 1; i <= 1500; ++i) times.push_back(1.0 + 2e-3 * i);
    return times;
}

// The record of a jump to d_0 at t = 0, held to t = 8 s (the branches relaxed to exp(-40)), a ramp to `top` over
// 1 s and a hold to 12 s, from t = 7.5 s (the pause every 50 ms), the depth shifted by the data's zero. The force as
// measured: F(t) = G(t) F_el(d_0) + int_8^t G(t - s) dF_el(d(s)) (Lee & Radok 1960, exact as the contact only
// grows), the integral by direct quadrature (testing::ramp_and_hold_forces) of the increment F_el(d(s)) - F_el(d_0),
// s = t - 8; `elastic` is F_el at unit shear modulus. The pause holds G_inf F_el(d_0) (and 3 exp(-37.5) = 2e-16 of it
// still relaxing): the baseline is that force, as `baseline = "constant"` takes it from a real record's pause.
fit::Curve preloaded_curve(const std::function<double(double)>& elastic) {
    const double at_preload = elastic(preload);
    const auto depth = [](double s) { return preload + (top - preload) * std::clamp(s, 0.0, 1.0); };
    const auto increment = [&](double s) { return elastic(depth(s)) - at_preload; };
    const auto preload_force = [&](double t) { return (G_inf + G1 * std::exp(-t / tau1)) * at_preload; };
    fit::Curve curve;
    curve.name = "preloaded relaxation";
    for (int i = 0; i < 10; ++i) {
        const double t = 7.5 + 0.05 * i;
        curve.time.push_back(t);
        curve.depth.push_back(preload + offset);
        curve.force.push_back(preload_force(t));
    }
    const auto since = since_ramp_start();
    const auto change = testing::ramp_and_hold_forces(since, G_inf, G1, tau1, increment);
    for (std::size_t i = 0; i < since.size(); ++i) {
        curve.time.push_back(ramp_start + since[i]);
        curve.depth.push_back(depth(since[i]) + offset);
        curve.force.push_back(preload_force(ramp_start + since[i]) + change[i]);
    }
    curve.preloaded = true;
    curve.force_baseline = curve.force.front();
    curve.contact_depth = curve.depth.front();  // the estimate of a record that starts in contact: its first row
    return curve;
}

// F_el(d) at unit shear modulus on the layer: 4 (E* = 4 G, incompressible) times at_depth's unit force, on 64 Gauss
// nodes, each solve started from the last; memoised, for every node of the hold is the depth `top` and each row's end
// is asked twice.
std::function<double(double)> layer_elastic_force() {
    const contact::Layer layer{thickness, contact::LayerInterface::bonded};
    const std::shared_ptr<const profile::Profile> sphere = profile::make_sphere(radius);
    const auto exact = std::make_shared<contact::LayerContact>(layer, 0.5, sphere,
                                                               3.0 * sphere->contact_radius(top), std::size_t{64});
    auto solved = std::make_shared<std::map<double, double>>();
    auto near = std::make_shared<contact::LayerContactState>();  // the last solution: the root's start
    return [exact, solved, near](double depth) {
        const auto [at, added] = solved->try_emplace(depth, 0.0);
        if (added) {
            *near = exact->at_depth(depth, *near);
            at->second = 4.0 * near->force;
        }
        return at->second;
    };
}

// Hertz at unit shear modulus: F_el = 16 a^3 / (3 R) with a^2 = R d (handbook eq. 35, 31), (16/3) sqrt(R) d^1.5.
double hertz_elastic_force(double depth) { return 16.0 / 3.0 * std::sqrt(radius) * std::pow(depth, 1.5); }

// values = (G_inf, G1, tau1[, h]): the layer case with them; the thickness `fixed` when it is not free.
fit::FitProblem preloaded_problem(fit::Curve curve, bool thickness_free, double fixed = thickness) {
    fit::FitProblem problem;
    problem.model = [base = io::parse_case(layer_case()), fixed](const std::vector<double>& values) {
        auto model = base;
        model.material = rheology::Rheology::standard(values[0], values[1], values[2]);
        model.bodies.reset();  // the material replaced is no body's (drivers::validate)
        model.layer->thickness = values.size() > 3 ? values[3] : fixed;
        return model;
    };
    problem.parameters = {{"material.G_inf", 3e3, 1.0, 1e6}, {"material.G1", 1e3, 1.0, 1e6},
                          {"material.tau1", 1.0, 1e-3, 1e3}};
    if (thickness_free) problem.parameters.push_back({"layer.thickness", 5e-6, 1e-7, 1e-4});
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fit;
    problem.settings.baseline = fit::BaselineMode::estimate;
    return problem;
}

TEST(FitLayerPreload, TheRowByRowQuadratureIsTheDirectOne) {
    // The record's quadrature carried from row to row (ramp_and_hold_forces) against the whole integral at each row
    // (ramp_and_hold_force, the reference of test_layer_viscoelastic.cpp), on Hertz's increment from d_0: both
    // Gauss-Legendre of smooth integrands, to round-off (observed 5.5e-15 of the peak).
    const auto increment = [](double s) {
        return hertz_elastic_force(preload + (top - preload) * std::min(s, 1.0)) - hertz_elastic_force(preload);
    };
    const auto since = since_ramp_start();
    const auto carried = testing::ramp_and_hold_forces(since, G_inf, G1, tau1, increment);
    const double peak = testing::ramp_and_hold_force(1.0, G_inf, G1, tau1, increment);
    double largest = 0.0;
    for (std::size_t i = 0; i < since.size(); ++i) {
        const double direct = testing::ramp_and_hold_force(since[i], G_inf, G1, tau1, increment);
        largest = std::max(largest, std::abs(carried[i] - direct) / peak);
    }
    EXPECT_LT(largest, 1e-12);
}

TEST(FitLayerPreload, ModuliPreloadAndThicknessFromAPreloadedRelaxation) {
    // The model meets the quadrature to its interpolation (eq. L15) and F_el linear in time over each row
    // (LayerPreload.ARampFromTheRelaxedPreloadIsLeeRadokOfTheChangeSince: 1.4e-7 of the peak on 1 ms rows): the
    // values come back to 1e-5 (observed: h fixed 4.0e-7, the contact 5.6e-7 of d_0; h free 3.7e-6, h 1.4e-6, the
    // contact 1.3e-6 of d_0; on 2 ms ramp rows 1.3e-5, on 0.5 ms 1.4e-6 with h free, 1.0e-7 with h fixed).
    const auto curve = preloaded_curve(layer_elastic_force());
    for (const bool thickness_free : {false, true}) {
        const auto result = fit::fit(preloaded_problem(curve, thickness_free));
        ASSERT_TRUE(result.converged) << thickness_free << ": " << result.status;
        std::vector<double> expected{G_inf, G1, tau1};
        if (thickness_free) expected.push_back(thickness);
        for (std::size_t j = 0; j < expected.size(); ++j) {
            EXPECT_NEAR(result.values[j] / expected[j], 1.0, 1e-5) << thickness_free << " " << result.names[j];
        }
        ASSERT_EQ(result.curves.size(), 1u);
        EXPECT_NEAR(result.curves[0].contact_depth, offset, 1e-5 * preload) << thickness_free;
        EXPECT_EQ(result.element_evaluations, 0u);  // the layer model alone
    }
}

TEST(FitLayerPreload, AThickLayerIsTheHalfSpacesPreloadedFit) {
    // The same record on the half-space (Hertz's F_el) fitted on the half-space (tests/unit/fit/preload_test.cpp: its
    // model against the closed form) and on a layer of 1 km: the same values to 2e-6 (the kernel vanishes as
    // h -> inf, eq. L4; the layer model's interpolation, eq. L15; observed 1.6e-7, the contact 5.9e-7 of d_0), the
    // half-space's the truth to 1e-8 (its model and the quadrature both exact to round-off: observed 4.3e-13).
    const auto curve = preloaded_curve(hertz_elastic_force);
    const auto on_layer = fit::fit(preloaded_problem(curve, false, 1e3));
    auto half_space = preloaded_problem(curve, false);
    const auto base = half_space.model;
    half_space.model = [base](const std::vector<double>& values) {
        auto model = base(values);
        model.layer.reset();
        return model;
    };
    const auto on_half_space = fit::fit(half_space);
    ASSERT_TRUE(on_layer.converged && on_half_space.converged) << on_layer.status << "; " << on_half_space.status;
    const std::vector<double> expected{G_inf, G1, tau1};
    for (std::size_t j = 0; j < expected.size(); ++j) {
        EXPECT_NEAR(on_layer.values[j] / on_half_space.values[j], 1.0, 2e-6) << on_layer.names[j];
        EXPECT_NEAR(on_half_space.values[j] / expected[j], 1.0, 1e-8) << on_layer.names[j];
    }
    EXPECT_NEAR(on_layer.curves[0].contact_depth, on_half_space.curves[0].contact_depth, 1e-5 * preload);
}

}  // namespace
}  // namespace mdr
