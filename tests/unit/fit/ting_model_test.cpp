// The continuum forward model of depth-driven fits (src/fit/ting_model.*) against the independent reference
// solutions of the tests (Ting's triangle, the Lee-Radok quadrature for a load-hold), and the histories it must
// refuse because they leave Ting's class. Its only error is the quadrature of one step: the force is exact for any
// piecewise-linear depth, so a coarse sampling of the same history is as accurate as a fine one.

#include "fit/exponential_quadrature.hpp"
#include "fit/ting_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "reference/closed_forms.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/ting.hpp"

namespace mdr::fit {
namespace {

rheology::Rheology library_material(const reference::PronyMaterial& material) {
    std::vector<rheology::RelaxationTerm> terms;
    for (const auto& [modulus, time] : material.terms) terms.push_back({modulus, time});
    return rheology::Rheology(material.G_inf, 0.0, terms);
}

struct Shape {
    std::string name;
    std::shared_ptr<const profile::Profile> library;
    reference::PowerLawIndenter reference;
};

std::vector<Shape> shapes() {
    const double slope = 10.0 * std::numbers::pi / 180.0;
    return {{"sphere", profile::make_sphere(1e-3), reference::sphere_indenter(1e-3)},
            {"cone", profile::make_cone(10.0), reference::cone_indenter(slope)},
            {"power 1.5", profile::make_power_law(0.5, 1.5), reference::PowerLawIndenter{0.5, 1.5}}};
}

std::vector<std::pair<std::string, reference::PronyMaterial>> materials() {
    return {{"standard solid", {1e6, 0.0, {{2e6, 0.3}}}},
            {"maxwell", {0.0, 0.0, {{1e6, 0.5}}}},
            {"prony 3 (one term far shorter than a step)", {1e5, 0.0, {{2e5, 1e-4}, {5e5, 0.05}, {3e5, 2.0}}}}};
}

double largest(const std::vector<double>& values) {
    double peak = 0.0;
    for (double v : values) peak = std::max(peak, std::abs(v));
    return peak;
}

// Ting's triangle d = v t up to t_m = 1 s and back, sampled from before contact to after contact loss: the force
// at every point within 1e-9 of the peak, for 2401 and for 25 points (no time discretisation error).
TEST(TingModel, TriangleAgreesWithTingsSolution) {
    const double peak_depth = 1e-4;
    for (const auto& shape : shapes()) {
        for (const auto& [name, material] : materials()) {
            const reference::TingSolution ting(shape.reference, material, peak_depth, 1.0);
            for (std::size_t points : {2401u, 25u}) {  // the peak is a point of both
                std::vector<double> time, depth, expected;
                for (std::size_t i = 0; i < points; ++i) {
                    const double t = -0.1 + 2.4 * static_cast<double>(i) / static_cast<double>(points - 1);
                    time.push_back(t);
                    depth.push_back(t < 1.0 ? peak_depth * t : peak_depth * (2.0 - t));
                    expected.push_back(t <= 0.0 ? 0.0 : ting.force(t));
                }
                const auto forces = ting_forces(library_material(material), *shape.library, time, depth);
                ASSERT_TRUE(forces.has_value()) << shape.name << ", " << name;
                const double peak = largest(expected);
                for (std::size_t i = 0; i < points; ++i) {
                    ASSERT_NEAR(forces->force[i], expected[i], 1e-9 * peak)
                        << shape.name << ", " << name << ", " << points << " points, t = " << time[i];
                }
            }
        }
    }
}

// Load, hold, unload to beyond contact loss against the Lee-Radok quadrature while loading and holding (the contact
// radius does not shrink before the unloading).
TEST(TingModel, LoadHoldAgreesWithLeeRadok) {
    const double peak_depth = 2e-6;
    const reference::PiecewiseLinear history{{0.0, 0.5, 1.5}, {0.0, peak_depth, peak_depth}};
    for (const auto& shape : shapes()) {
        for (const auto& [name, material] : materials()) {
            std::vector<double> time, depth, expected;
            for (int i = 0; i <= 300; ++i) {
                const double t = -0.05 + 0.005 * i;
                time.push_back(t);
                depth.push_back(t < 0.0 ? peak_depth * t : history.value(t));
                expected.push_back(t <= 0.0 ? 0.0 : reference::lee_radok_force(shape.reference, material, history, t));
            }
            const auto forces = ting_forces(library_material(material), *shape.library, time, depth);
            ASSERT_TRUE(forces.has_value());
            const double peak = largest(expected);
            for (std::size_t i = 0; i < time.size(); ++i) {
                ASSERT_NEAR(forces->force[i], expected[i], 1e-9 * peak) << shape.name << ", " << name << ", t = " << time[i];
            }
        }
    }
}

// A smooth indenter that is none of the library's shapes (the paraboloid f = r^2/(2R), g = x^2/R of eq. 30 written
// out here, under its own name) has the continuum path because its type says g is a power law, not because of its
// name: Ting's triangle as for the sphere.
class Paraboloid final : public profile::Profile {
public:
    explicit Paraboloid(double radius) : radius_(radius) {}
    double gap(double r) const override { return r * r / (2.0 * radius_); }
    double equivalent(double x) const override { return x * x / radius_; }
    double contact_radius(double depth) const override { return std::sqrt(radius_ * std::max(depth, 0.0)); }
    double max_radius() const override { return std::numeric_limits<double>::infinity(); }
    std::optional<double> power_law_exponent() const override { return 2.0; }
    std::string describe() const override { return "paraboloid"; }
    profile::ProfileDefinition definition() const override { return {"paraboloid", {{"R", radius_}}}; }

private:
    double radius_;
};

TEST(TingModel, AnyPowerLawProfileHasTheContinuumPath) {
    const Paraboloid indenter(1e-3);
    const auto cases = materials();
    const auto& [name, material] = cases.front();
    ASSERT_TRUE(ting_model_applies(library_material(material), indenter)) << name;
    const double peak_depth = 1e-4;
    const reference::TingSolution ting(reference::sphere_indenter(1e-3), material, peak_depth, 1.0);
    std::vector<double> time, depth;
    for (int i = 0; i <= 200; ++i) {
        time.push_back(0.01 * i);
        depth.push_back(time.back() < 1.0 ? peak_depth * time.back() : peak_depth * (2.0 - time.back()));
    }
    const auto forces = ting_forces(library_material(material), indenter, time, depth);
    ASSERT_TRUE(forces.has_value());
    const double peak = ting.force(1.0);
    for (std::size_t i = 1; i < time.size(); ++i) {
        ASSERT_NEAR(forces->force[i], ting.force(time[i]), 1e-9 * peak) << "t = " << time[i];
    }
}

// The product rule is exact for cubics whatever tau; the composite rule integrates a square-root start to 1e-12.
TEST(ExponentialQuadrature, ExactForCubicsAndSquareRootStarts) {
    const auto cubic = [](double s) { return 1.0 + s - 2.0 * s * s + 0.5 * s * s * s; };
    for (double tau : {1e-3, 0.1, 1.0}) {
        // int_0^1 exp(-(1 - s)/tau) p(s) ds by parts: tau [sum_k (-tau)^k p^(k)(1) - exp(-1/tau) sum_k (-tau)^k
        // p^(k)(0)] (longer tau cancel in this form).
        const double p1 = 0.5, d1 = 1.0 - 4.0 + 1.5, dd1 = -4.0 + 3.0, ddd = 3.0;
        const double p0 = 1.0, d0 = 1.0, dd0 = -4.0;
        const double at_one = p1 - tau * d1 + tau * tau * dd1 - tau * tau * tau * ddd;
        const double at_zero = p0 - tau * d0 + tau * tau * dd0 - tau * tau * tau * ddd;
        const double exact = tau * (at_one - std::exp(-1.0 / tau) * at_zero);
        const auto w = ExponentialRule::weights(1.0 / tau);
        double rule = 0.0;
        for (std::size_t j = 0; j < w.size(); ++j) rule += w[j] * cubic(ExponentialRule::nodes()[j]);
        EXPECT_NEAR(rule, exact, 1e-13) << "tau = " << tau;
    }
    const auto plain = ExponentialRule::weights(0.0);  // tau = +infinity
    double rule = 0.0;
    for (std::size_t j = 0; j < plain.size(); ++j) rule += plain[j] * cubic(ExponentialRule::nodes()[j]);
    EXPECT_NEAR(rule, 1.0 + 0.5 - 2.0 / 3.0 + 0.125, 1e-14);
    // int_0^1 sqrt(s) ds = 2/3 (tau infinite) and int_0^1 exp(-(1 - s)) sqrt(s) ds against a fine midpoint sum in
    // the variable v = sqrt(s) (smooth there).
    const auto root = [](double s) { return std::sqrt(s); };
    EXPECT_NEAR(exponential_integral(root, 0.0, 1.0, std::numeric_limits<double>::infinity(), true), 2.0 / 3.0, 1e-14);
    double midpoint = 0.0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double v = (i + 0.5) / n;
        midpoint += 2.0 * v * v * std::exp(-(1.0 - v * v)) / n;
    }
    EXPECT_NEAR(exponential_integral(root, 0.0, 1.0, 1.0, true), midpoint, 1e-10);
}

std::vector<double> uniform(double start, double end, std::size_t points) {
    std::vector<double> values;
    for (std::size_t i = 0; i < points; ++i) values.push_back(start + (end - start) * static_cast<double>(i) / static_cast<double>(points - 1));
    return values;
}

// dF/dG_b from the run itself against central differences of the force in each modulus, over a triangle with a
// hold at the top (loading: the force is linear in the moduli; unloading: the edge moves with them): 1e-6 of the
// largest derivative.
TEST(TingModel, ModulusDerivativesAgreeWithDifferences) {
    const auto sphere = profile::make_sphere(1e-3);
    const double g_inf = 1e5;
    const std::vector<rheology::RelaxationTerm> terms{{2e5, 0.05}, {3e5, 0.4}};
    std::vector<double> time, depth;
    for (int i = 0; i <= 300; ++i) {
        const double t = -0.1 + 0.01 * i;
        time.push_back(t);
        depth.push_back(t < 1.0 ? 1e-4 * t : t < 1.3 ? 1e-4 : 1e-4 * (2.3 - t));
    }
    const auto response = ting_forces(rheology::Rheology::prony(g_inf, terms), *sphere, time, depth);
    ASSERT_TRUE(response.has_value());
    ASSERT_EQ(response->modulus_derivatives.size(), 3u);
    for (std::size_t b = 0; b < 3; ++b) {
        const double h = 1e-4 * (b == 0 ? g_inf : terms[b - 1].modulus);
        const auto shifted = [&](double sign) {
            double inf = g_inf;
            auto moved = terms;
            (b == 0 ? inf : moved[b - 1].modulus) += sign * h;
            return ting_forces(rheology::Rheology::prony(inf, moved), *sphere, time, depth)->force;
        };
        const auto up = shifted(1.0), down = shifted(-1.0);
        const double scale = largest(response->modulus_derivatives[b]);
        for (std::size_t i = 0; i < time.size(); ++i) {
            ASSERT_NEAR(response->modulus_derivatives[b][i], (up[i] - down[i]) / (2.0 * h), 1e-6 * scale)
                << "branch " << b << ", t = " << time[i];
        }
    }
}

// Histories where an element that left contact could be pushed back: the model refuses rather than guess.
TEST(TingModel, RefusesHistoriesOutsideTingsClass) {
    const auto sphere = profile::make_sphere(1e-3);
    const auto material = rheology::Rheology::standard(1e6, 2e6, 0.3);
    const auto time = uniform(0.0, 3.0, 301);
    const auto depth_at = [&](auto shape) {
        std::vector<double> depth;
        for (double t : time) depth.push_back(shape(t));
        return depth;
    };
    // Load, unload half, reload: the edge moves outwards again.
    const auto cycle = depth_at([](double t) { return t < 1.0 ? 1e-4 * t : t < 1.5 ? 1e-4 * (2.0 - t) : 5e-5 + 1e-4 * (t - 1.5); });
    EXPECT_FALSE(ting_forces(material, *sphere, time, cycle).has_value());
    // Load, unload a little quickly, hold: relaxation pushes the edge out again.
    const auto partial = depth_at([](double t) { return t < 1.0 ? 1e-4 * t : t < 1.01 ? 1e-4 * (1.0 - 5.0 * (t - 1.0)) : 0.95e-4; });
    EXPECT_FALSE(ting_forces(material, *sphere, time, partial).has_value());
    // A load that dips and goes on.
    const auto dip = depth_at([](double t) { return 1e-4 * t + (std::abs(t - 1.0) < 0.015 ? -2e-6 : 0.0); });
    EXPECT_FALSE(ting_forces(material, *sphere, time, dip).has_value());
    // A parallel dashpot; a flat punch: not covered.
    const auto loading = depth_at([](double t) { return 1e-4 * t; });
    EXPECT_FALSE(ting_forces(rheology::Rheology::kelvin_voigt(1e6, 1e5), *sphere, time, loading).has_value());
    EXPECT_FALSE(ting_forces(material, *profile::make_flat_punch(1e-3), time, loading).has_value());
    // While a plain load-hold-unload is covered.
    const auto load_hold_unload = depth_at([](double t) { return t < 1.0 ? 1e-4 * t : t < 2.0 ? 1e-4 : 1e-4 * (3.0 - t); });
    EXPECT_TRUE(ting_forces(material, *sphere, time, load_hold_unload).has_value());
}

// The measured depth with its contact point taken in place (depth_shift, as the fit passes it to avoid a copy of a
// long curve) is the run of the shifted depth, bit for bit, and a run without the modulus derivatives gives the same
// forces: the stated rule of ting_forces, for approach, load, hold and unloading to separation, and a start in contact.
TEST(TingModel, ShiftedDepthInPlaceIsTheRunOfTheShiftedDepth) {
    const auto sphere = profile::make_sphere(1e-3);
    const auto material = rheology::Rheology::prony(1e5, {{2e5, 0.01}, {3e5, 0.3}});
    const auto time = uniform(-0.1, 3.0, 311);
    const double contact = 3e-5;
    for (const double start : {0.0, 2e-5}) {  // the first point out of contact, or in contact
        std::vector<double> measured, shifted;
        for (double t : time) {
            measured.push_back(contact + start + (t < 1.0 ? 1e-4 * t : t < 1.5 ? 1e-4 : 1e-4 * (2.5 - t)));
            shifted.push_back(measured.back() - contact);
        }
        const auto reference = ting_forces(material, *sphere, time, shifted);
        const auto in_place = ting_forces(material, *sphere, time, measured, contact);
        const auto force_alone = ting_forces(material, *sphere, time, measured, contact, false);
        ASSERT_TRUE(reference && in_place && force_alone);
        EXPECT_EQ(in_place->force, reference->force);
        EXPECT_EQ(in_place->modulus_derivatives, reference->modulus_derivatives);
        EXPECT_EQ(force_alone->force, reference->force);
        EXPECT_TRUE(force_alone->modulus_derivatives.empty());
    }
}

// A history that starts in contact jumps to its first depth at its first time, as the element model's history does:
// load-hold-unload from 20 % of the peak depth, against the drivers' element model at 1000 and 4000 elements, whose
// error falls as N^-2 towards the continuum.
TEST(TingModel, StartInContactIsTheElementModelsJump) {
    const std::shared_ptr<const profile::Profile> sphere = profile::make_sphere(1e-3);
    const auto material = rheology::Rheology::prony(1e5, {{2e5, 0.01}, {3e5, 0.3}});
    const auto time = uniform(0.0, 3.0, 301);
    std::vector<double> depth;
    for (double t : time) depth.push_back(t < 1.0 ? 1e-4 * (0.2 + 0.8 * t) : t < 2.0 ? 1e-4 : 1e-4 * (3.0 - t));
    const auto forces = ting_forces(material, *sphere, time, depth);
    ASSERT_TRUE(forces.has_value());
    std::vector<double> errors;
    for (std::size_t elements : {1000u, 4000u}) {
        std::vector<drivers::LoadPoint> points;
        for (std::size_t i = 0; i < time.size(); ++i) points.push_back({time[i], depth[i]});
        drivers::ContactCase contact_case{.title = "start in contact",
                                          .material = material,
                                          .indenter = sphere,
                                          .load = {.history = drivers::LoadHistory(std::move(points), "load.history")},
                                          .end_time = time.back()};
        contact_case.numerics.elements = elements;
        contact_case.numerics.time_step = time[1] - time[0];
        contact_case.numerics.min_segment_steps = 1;
        contact_case.numerics.output_every = 1;
        const auto result = drivers::run_case(contact_case);
        double error = 0.0;
        std::size_t row = 0;
        for (std::size_t i = 0; i < time.size(); ++i) {
            while (row + 1 < result.time.size() && result.time[row + 1] <= time[i]) ++row;
            error = std::max(error, std::abs(result.force[row] - forces->force[i]));
        }
        errors.push_back(error / largest(forces->force));
    }
    EXPECT_LT(errors[1], 1e-6);
    EXPECT_NEAR(errors[0] / errors[1], 16.0, 4.0);  // second order in the element size
}

// Random histories of the class (approach, loading at varying rates with holds, unloading at rising speeds past
// contact loss) on random materials and shapes, against the drivers' element model at 4000 elements, a different
// method (per element, exact per step): within 1e-6 of the peak force every time (its own error is ~5e-8).
TEST(TingModel, RandomHistoriesAgreeWithTheElementModel) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::vector<std::shared_ptr<const profile::Profile>> indenters{
        profile::make_sphere(1e-3), profile::make_cone(20.0), profile::make_power_law(2.0, 1.6)};
    for (int trial = 0; trial < 12; ++trial) {
        std::vector<rheology::RelaxationTerm> terms;
        const int count = 1 + trial % 3;
        for (int k = 0; k < count; ++k) terms.push_back({1e5 * (0.2 + unit(random)), std::pow(10.0, -2.0 + 2.5 * unit(random))});
        const auto material = rheology::Rheology::prony(trial % 4 == 0 ? 0.0 : 1e5 * unit(random), terms);
        const auto& indenter = indenters[static_cast<std::size_t>(trial) % indenters.size()];
        // Rates drawn per segment: approach, 3 loading pieces with a hold, unloading in 3 pieces to below 0.
        std::vector<double> time{0.0}, depth{-1e-5};
        const auto add = [&](double duration, double change) {
            const std::size_t steps = 40;
            for (std::size_t i = 1; i <= steps; ++i) {
                time.push_back(time.back() + duration / steps);
                depth.push_back(depth.back() + change / steps);
            }
        };
        add(0.2, 1e-5 * (1.0 + unit(random)));
        for (int piece = 0; piece < 3; ++piece) add(0.1 + unit(random), 3e-5 * unit(random));
        add(0.5 * unit(random) + 0.1, 0.0);
        // Unloading at speeds that never fall (a slower unloading after a faster one may let the edge move out
        // again, which the model refuses: then the element model runs).
        const double peak = depth.back();
        double speed = peak * (0.5 + unit(random));
        for (int piece = 0; piece < 3; ++piece) {
            const double duration = 0.2 + 0.3 * unit(random);
            add(duration, -speed * duration);
            speed *= 1.0 + unit(random);
        }
        const auto forces = ting_forces(material, *indenter, time, depth);
        ASSERT_TRUE(forces.has_value()) << "trial " << trial;
        std::vector<drivers::LoadPoint> points{{time.front() - 0.01, 0.0}};
        for (std::size_t i = 0; i < time.size(); ++i) points.push_back({time[i], depth[i]});
        drivers::ContactCase contact_case{.title = "random",
                                          .material = material,
                                          .indenter = indenter,
                                          .load = {.history = drivers::LoadHistory(std::move(points), "load.history")},
                                          .end_time = time.back()};
        contact_case.numerics.elements = 4000;
        double widest = 0.0;
        for (std::size_t i = 1; i < time.size(); ++i) widest = std::max(widest, time[i] - time[i - 1]);
        contact_case.numerics.time_step = widest;
        contact_case.numerics.min_segment_steps = 1;
        const auto result = drivers::run_case(contact_case);
        const double scale = largest(forces->force);
        std::size_t row = 0;
        for (std::size_t i = 0; i < time.size(); ++i) {
            while (row + 1 < result.time.size() && result.time[row + 1] <= time[i]) ++row;
            ASSERT_NEAR(result.force[row], forces->force[i], 1e-6 * scale) << "trial " << trial << ", t = " << time[i];
        }
    }
}

}  // namespace
}  // namespace mdr::fit
