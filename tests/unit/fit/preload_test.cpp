// A record that starts in contact under a relaxed preload (docs/theory.md §4d; `[[fit.data]] start = "preloaded"`):
// the continuum model (ting_model.hpp) and the band model (band_model.hpp) against the closed form of the preloaded
// Lee-Radok integral for a cone into a standard solid, written here independently of the library.

#include "fit/band_model.hpp"
#include "fit/ting_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::fit {
namespace {

constexpr double G_inf = 1e3, G1 = 2e3, tau1 = 0.4;  // Pa, Pa, s
constexpr double preload = 0.5e-6, speed = 1e-6, ramp_end = 1.0, hold_end = 3.0;  // m, m/s, s, s
const double slope = 10.0 * std::numbers::pi / 180.0;

// The elastic force of the cone per unit shear modulus, F_el(d) = 8 d^2 / (pi tan theta) (handbook eq. 28 with
// G1 = 0; incompressible body).
double elastic_force(double depth) { return 8.0 * depth * depth / (std::numbers::pi * std::tan(slope)); }

// F(t) - G_inf F_el(d_0) = int_0^t G(t - s) dF_el(d(s)) for d = d_0 + v s up to ramp_end and held after, every
// branch relaxed at t = 0: G_inf [F_el(d(t)) - F_el(d_0)] + G1 (16 v / (pi tan theta)) I(t), with
// I(t) = int_0^min(t, t_r) exp(-(t - s) / tau) (d_0 + v s) ds = d_0 tau (1 - E) + v (tau t - tau^2 (1 - E)),
// E = exp(-t / tau), for t <= t_r, and exp(-(t - t_r) / tau) I(t_r) after.
double preloaded_force(double t) {
    const auto ramp_integral = [](double s) {
        const double decayed = 1.0 - std::exp(-s / tau1);
        return preload * tau1 * decayed + speed * (tau1 * s - tau1 * tau1 * decayed);
    };
    const double loaded = std::min(t, ramp_end);
    const double integral =
        t <= ramp_end ? ramp_integral(t) : std::exp(-(t - ramp_end) / tau1) * ramp_integral(ramp_end);
    const double depth = preload + speed * loaded;
    return G_inf * (elastic_force(depth) - elastic_force(preload)) +
           G1 * 16.0 * speed / (std::numbers::pi * std::tan(slope)) * integral;
}

struct Record {
    std::vector<double> time, depth;
};

Record ramp_and_hold(std::size_t ramp_points, bool hold) {
    Record record;
    for (std::size_t i = 0; i <= ramp_points; ++i) {
        const double t = ramp_end * static_cast<double>(i) / static_cast<double>(ramp_points);
        record.time.push_back(t);
        record.depth.push_back(preload + speed * t);
    }
    for (std::size_t i = 1; hold && i <= 2 * ramp_points; ++i) {
        record.time.push_back(ramp_end + (hold_end - ramp_end) * static_cast<double>(i) /
                                           (2.0 * static_cast<double>(ramp_points)));
        record.depth.push_back(preload + speed * ramp_end);
    }
    return record;
}

const rheology::Rheology material(G_inf, 0.0, {{G1, tau1}});

TEST(Preload, ContinuumModelIsThePreloadedLeeRadokIntegral) {
    const auto cone = profile::make_cone(10.0);
    const Record record = ramp_and_hold(200, false);
    const auto preloaded = ting_forces(material, *cone, record.time, record.depth, 0.0, true, true);
    const auto from_rest = ting_forces(material, *cone, record.time, record.depth, 0.0, true, false);
    ASSERT_TRUE(preloaded && from_rest);
    const double peak = preloaded_force(ramp_end);
    double at_rest_gap = 0.0;
    for (std::size_t i = 0; i < record.time.size(); ++i) {
        EXPECT_NEAR(preloaded->force[i], preloaded_force(record.time[i]), 1e-6 * peak) << "t = " << record.time[i];
        at_rest_gap = std::max(at_rest_gap, std::abs(from_rest->force[i] - preloaded_force(record.time[i])));
        // dF/dG_inf: F_el(d) - F_el(d_0), exact for the linear force.
        EXPECT_NEAR(preloaded->modulus_derivatives[0][i],
                    elastic_force(record.depth[i]) - elastic_force(preload), 1e-6 * peak / G_inf);
    }
    EXPECT_GT(at_rest_gap, 0.1 * peak);  // the unloaded start (a jump at t_0) is another model
}

TEST(Preload, ContinuumModelLeavesAFallingDepthToTheBandModel) {
    const auto cone = profile::make_cone(10.0);
    Record record = ramp_and_hold(50, true);
    record.depth.back() -= 1e-9;
    EXPECT_FALSE(ting_forces(material, *cone, record.time, record.depth, 0.0, true, true));
    EXPECT_TRUE(ting_forces(material, *cone, record.time, record.depth, 0.0, true, false));
}

// The band model's elements converge on the same integral (midpoint sums of the elastic force: second order in the
// spacing) over the ramp and the hold.
TEST(Preload, BandModelConvergesOnThePreloadedIntegral) {
    const auto cone = profile::make_cone(10.0);
    const Record record = ramp_and_hold(200, true);
    const double radius = 2.0 * (preload + speed * ramp_end) / (std::numbers::pi * std::tan(slope));
    const double peak = preloaded_force(ramp_end);
    std::vector<double> errors;
    for (std::size_t count : {500, 1000}) {
        const double spacing = 1.1 * radius / static_cast<double>(count);
        const auto band = band_forces(material, *cone, spacing, count, record.time, record.depth, {}, true);
        ASSERT_TRUE(band);
        double error = 0.0;
        for (std::size_t i = 0; i < record.time.size(); ++i) {
            error = std::max(error, std::abs(band->force[i] - preloaded_force(record.time[i])));
        }
        errors.push_back(error / peak);
    }
    EXPECT_LT(errors[1], 1e-5);
    EXPECT_LT(errors[1], 0.35 * errors[0]);  // second order: a quarter of the error at half the spacing
}

// A depth that dips (a noisy hold: the contact shrinks and grows again, outside the continuum model): the preloaded
// start equals the foundation brought physically to that state, pressed from undeformed to d_0 and held 100 tau1
// (every branch relaxed to exp(-100)), run from rest; its force less G_inf F_el(d_0) at the record's first time.
TEST(Preload, BandModelStartIsTheRelaxedFoundation) {
    const auto cone = profile::make_cone(10.0);
    Record record = ramp_and_hold(100, true);
    for (std::size_t i = 0; i < record.depth.size(); ++i) {
        record.depth[i] -= 0.2 * preload * std::abs(std::sin(0.37 * static_cast<double>(i)));
    }
    Record history;
    const double settle = 100.0 * tau1;
    for (std::size_t i = 0; i <= 200; ++i) {
        history.time.push_back(-settle - 1.0 + static_cast<double>(i) / 200.0);
        history.depth.push_back(preload * static_cast<double>(i) / 200.0);
    }
    history.time.insert(history.time.end(), record.time.begin(), record.time.end());
    history.depth.insert(history.depth.end(), record.depth.begin(), record.depth.end());
    const double radius = 2.0 * (preload + speed * ramp_end) / (std::numbers::pi * std::tan(slope));
    const std::size_t count = 400;
    const double spacing = 1.1 * radius / static_cast<double>(count);
    const auto preloaded = band_forces(material, *cone, spacing, count, record.time, record.depth, {}, true);
    const auto relaxed = band_forces(material, *cone, spacing, count, history.time, history.depth, {}, false);
    ASSERT_TRUE(preloaded && relaxed);
    const std::size_t first = history.time.size() - record.time.size();
    const double preload_force = relaxed->force[first];
    EXPECT_NEAR(preload_force, G_inf * elastic_force(record.depth.front()), 1e-3 * preload_force);
    const double peak = preloaded_force(ramp_end);
    for (std::size_t i = 0; i < record.time.size(); ++i) {
        EXPECT_NEAR(preloaded->force[i], relaxed->force[first + i] - preload_force, 1e-9 * peak) << "row " << i;
    }
}

}  // namespace
}  // namespace mdr::fit
