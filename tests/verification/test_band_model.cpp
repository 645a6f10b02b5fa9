// The band model (src/fit/band_model.*: the element foundation with the elements that provably stay in contact
// summed) against the drivers' element model, an independent implementation of the same foundation (vectorised,
// every element stepped), on random measured-like depth histories: ramps and holds with autoregressive noise of
// 1e-4 to 1e-3 of the peak (the depth dips in about a third of the steps), pauses, partial unloading and reloading,
// random Prony materials and shapes. With the same elements the two are the same sums in another order: they agree
// to 1e-9 of the peak force (round-off; 1e-6 is the fits' requirement). The band model's own convergence in the
// element count is the element model's: second order in the element width.
//
// Under force control (band_depths, the fits' force-driven runs) the same: random measured-like force histories
// (noise that makes the force dip, pauses, partial and full unloading, reloading) against the drivers' element model
// on the drivers' own time grid, each depth solved to 1e-13 of the force by both: the depths agree to 1e-9 of the
// peak depth (the fits' requirement is 1e-6).

#include "fit/band_model.hpp"
#include "fit/curve_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/power_law.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::fit {
namespace {

struct History {
    std::vector<double> time, depth;
};

// Approach from -2 % of the peak, a ramp to the peak at a random rate with a pause, a hold, a partial unloading and
// a reloading, then a hold; AR(1) noise (correlation 0.7) of `noise` times the peak on every point.
History measured_like(std::mt19937& random, double peak, double noise) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    History history;
    const double dt = 1e-3 * (0.5 + unit(random));
    double t = 0.0, smooth = -0.02 * peak, correlated = 0.0;
    const auto add = [&](std::size_t steps, double change) {
        for (std::size_t i = 0; i < steps; ++i) {
            smooth += change / static_cast<double>(steps);
            correlated = 0.7 * correlated + std::sqrt(1.0 - 0.49) * noise * peak * normal(random);
            history.time.push_back(t);
            history.depth.push_back(smooth + correlated);
            t += dt;
        }
    };
    add(40, 0.02 * peak);
    add(150 + static_cast<std::size_t>(100 * unit(random)), 0.5 * peak);
    add(60, 0.0);
    add(150, 0.5 * peak);
    add(300, 0.0);
    add(100, -0.3 * peak * unit(random));
    add(100, 0.3 * peak * unit(random));
    add(200, 0.0);
    return history;
}

std::shared_ptr<const profile::Profile> indenter_of(int trial) {
    switch (trial % 3) {
    case 0: return profile::make_sphere(1e-3);
    case 1: return profile::make_cone(20.0);
    default: return profile::make_power_law(2.0, 1.6);
    }
}

rheology::Rheology random_material(std::mt19937& random, int trial) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<rheology::RelaxationTerm> terms;
    for (int k = 0; k < 1 + trial % 3; ++k) {
        terms.push_back({1e5 * (0.2 + 3.0 * unit(random)), std::pow(10.0, -2.5 + 3.0 * unit(random))});
    }
    return rheology::Rheology::prony(1e5 * (0.05 + unit(random)), terms);
}

// The drivers' element model of the history with `elements` elements (the steps are the points, as in run_curve:
// from the undeformed state one interval before a first point out of contact, else a jump at the first point), its
// forces at the points (after the jump where two points share a time), and its element width.
std::pair<std::vector<double>, double> element_forces(const rheology::Rheology& material,
                                                      const std::shared_ptr<const profile::Profile>& indenter,
                                                      const History& history, std::size_t elements) {
    std::vector<drivers::LoadPoint> points;
    if (history.depth.front() <= 0.0) {
        points.push_back({history.time.front() - (history.time[1] - history.time[0]), 0.0});
    }
    for (std::size_t i = 0; i < history.time.size(); ++i) points.push_back({history.time[i], history.depth[i]});
    drivers::ContactCase contact_case{.title = "band",
                                      .material = material,
                                      .indenter = indenter,
                                      .load = {.history = drivers::LoadHistory(std::move(points), "load.history")},
                                      .end_time = history.time.back()};
    contact_case.numerics.elements = elements;
    double widest = 0.0;
    for (std::size_t i = 1; i < history.time.size(); ++i) {
        widest = std::max(widest, history.time[i] - history.time[i - 1]);
    }
    contact_case.numerics.time_step = widest;
    contact_case.numerics.min_segment_steps = 1;
    contact_case.numerics.output_every = 1;
    const double spacing = drivers::resolve_numerics(contact_case).half_width / static_cast<double>(elements);
    const auto result = drivers::run_case(contact_case);
    std::vector<double> forces;
    std::size_t row = 0;
    for (double t : history.time) {
        while (row + 1 < result.time.size() && result.time[row + 1] <= t) ++row;
        forces.push_back(result.force[row]);
    }
    return {forces, spacing};
}

double largest(const std::vector<double>& values) {
    double peak = 0.0;
    for (double v : values) peak = std::max(peak, std::abs(v));
    return peak;
}

TEST(BandModel, MeasuredLikeHistoriesAgreeWithTheElementModel) {
    std::mt19937 random(25);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 9; ++trial) {
        const auto material = random_material(random, trial);
        const auto indenter = indenter_of(trial);
        const double noise = std::pow(10.0, -4.0 + unit(random));
        const History history = measured_like(random, 1e-5, noise);
        const std::size_t elements = 4000;
        const auto [expected, spacing] = element_forces(material, indenter, history, elements);
        const auto band = band_forces(material, *indenter, spacing, elements, history.time, history.depth);
        ASSERT_TRUE(band.has_value()) << "trial " << trial;
        const double scale = largest(expected);
        for (std::size_t i = 0; i < history.time.size(); ++i) {
            ASSERT_NEAR(band->force[i], expected[i], 1e-9 * scale) << "trial " << trial << ", t = " << history.time[i];
        }
        const double all = static_cast<double>(elements) * static_cast<double>(history.time.size());
        std::cout << "trial " << trial << ": noise " << noise << ", element steps "
                  << static_cast<double>(band->element_steps) / all << " of the element model's\n";
    }
}

// Elements that left contact on a partial unloading creep back (a long relaxation time, a soft G_inf: G(0)/G_inf =
// 101), touch again on a fast reloading past the peak, and then small dips of 1e-3 of the peak move the band's stress
// G_inf d + S to and fro across their floors (band_model.hpp): they are unfolded with their exact states.
TEST(BandModel, TouchingAgainAfterAPartialUnloadingThenDips) {
    const auto material = rheology::Rheology::prony(1e4, {{1e6, 30.0}});
    const std::shared_ptr<const profile::Profile> sphere = profile::make_sphere(1e-3);
    History history;
    double t = 0.0, d = -1e-7;
    const auto ramp = [&](std::size_t steps, double change, double dt) {
        for (std::size_t i = 0; i < steps; ++i) {
            d += change / static_cast<double>(steps);
            history.time.push_back(t);
            history.depth.push_back(d);
            t += dt;
        }
    };
    ramp(100, 1e-5 + 1e-7, 1e-3);
    ramp(50, -0.7e-5, 1e-3);
    ramp(400, 0.0, 1e-2);
    ramp(20, 1.0e-5, 1e-3);
    for (int dip = 0; dip < 40; ++dip) ramp(5, dip % 2 == 0 ? -1e-8 : 1.2e-8, 1e-3);
    const std::size_t elements = 2000;
    const auto [expected, spacing] = element_forces(material, sphere, history, elements);
    const auto band = band_forces(material, *sphere, spacing, elements, history.time, history.depth);
    ASSERT_TRUE(band.has_value());
    const double scale = largest(expected);
    for (std::size_t i = 0; i < history.time.size(); ++i) {
        ASSERT_NEAR(band->force[i], expected[i], 1e-9 * scale) << "t = " << history.time[i];
    }
}

// Convergence in the element count on a measured-like history (noise 3e-4 of the peak): the error against 64 000
// elements falls as N^-2 (the element model's order) and is below 1e-6 of the peak from 1000 elements on (4.8e-7).
TEST(BandModel, ConvergesInTheElementCount) {
    std::mt19937 random(3);
    const auto material = rheology::Rheology::prony(1e5, {{3e5, 0.02}, {2e5, 0.5}});
    const std::shared_ptr<const profile::Profile> indenter = profile::make_cone(20.0);
    const History history = measured_like(random, 1e-5, 3e-4);
    double deepest = 0.0;
    for (double d : history.depth) deepest = std::max(deepest, d);
    const double half_width = 1.1 * indenter->contact_radius(deepest);
    const auto forces = [&](std::size_t elements) {
        const auto band = band_forces(material, *indenter, half_width / static_cast<double>(elements), elements,
                                      history.time, history.depth);
        EXPECT_TRUE(band.has_value());
        return band ? band->force : std::vector<double>{};
    };
    const auto reference = forces(64000);
    const double scale = largest(reference);
    std::vector<double> errors;
    for (std::size_t elements : {1000u, 2000u, 4000u, 8000u}) {
        const auto coarse = forces(elements);
        double error = 0.0;
        for (std::size_t i = 0; i < coarse.size(); ++i) error = std::max(error, std::abs(coarse[i] - reference[i]));
        errors.push_back(error / scale);
        std::cout << elements << " elements: " << errors.back() << " of the peak\n";
    }
    for (std::size_t k = 0; k + 1 < errors.size(); ++k) EXPECT_GT(errors[k] / errors[k + 1], 3.0) << k;
    EXPECT_LT(errors[0], 1e-6);
}

// A fit's element run of a depth-driven curve (run_curve) is the band model, with the drivers' elements: its forces
// at the curve's points are the drivers' element model's.
TEST(BandModel, FitsRunTheElementModelAsTheBandModel) {
    std::mt19937 random(7);
    const auto material = rheology::Rheology::prony(2e5, {{5e5, 0.05}, {3e5, 0.8}});
    const std::shared_ptr<const profile::Profile> indenter = profile::make_cone(20.0);
    const History history = measured_like(random, 1e-5, 3e-4);
    Curve curve;
    curve.name = "measured-like";
    curve.time = history.time;
    curve.depth = history.depth;
    curve.force.assign(history.time.size(), 0.0);
    curve.force_noise = 1e-6;
    const CurveModel prepared = prepare_curve(curve, Fitted::force, 0.0);
    drivers::ContactCase model_case{.title = "fit",
                                    .material = material,
                                    .indenter = indenter,
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    const std::size_t elements = 2000;
    const auto model = run_curve(model_case, prepared, 0.0, {}, elements, ForwardModel::elements);
    ASSERT_TRUE(model.has_value());
    EXPECT_TRUE(model->band);
    const auto expected = element_forces(material, indenter, history, elements).first;
    ASSERT_EQ(model->values.size(), expected.size());
    const double scale = largest(expected);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        ASSERT_NEAR(model->values[i], expected[i], 1e-9 * scale) << "t = " << history.time[i];
    }
}

// Adversarial random histories: ramps to new peaks, drawdowns to 5 % to 95 % of the running maximum D, reloadings
// that end exactly at D, holds of 1 to 300 steps, wiggles of 1e-6 to 1e-2 of D, jumps (two points at one time) up
// and down, half of them starting in contact (a jump at the first point); materials with G(0)/G_inf from 1 to 1000
// and more, one to six branches with tau from 1e-2 to 1e4 steps. The memory bound's deficit m (band_model.hpp)
// matters here and in the measured-like histories: with m set to 0 the forces no longer agree.
History adversarial(std::mt19937& random, double peak) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    History history;
    const double dt = 1e-3;
    double t = 0.0, d = unit(random) < 0.5 ? -0.01 * peak : 0.2 * peak, deepest = std::max(d, 0.0);
    const auto point = [&] {
        history.time.push_back(t);
        history.depth.push_back(d);
        deepest = std::max(deepest, d);
    };
    const auto to = [&](double target, std::size_t steps) {
        const double start = d;
        for (std::size_t i = 1; i <= steps; ++i) {
            t += dt;
            d = i == steps ? target : start + (target - start) * static_cast<double>(i) / static_cast<double>(steps);
            point();
        }
    };
    point();
    to(0.3 * peak * (0.5 + unit(random)), 1 + static_cast<std::size_t>(60 * unit(random)));
    for (int segment = 0; segment < 14; ++segment) {
        const double kind = unit(random);
        const auto steps = 1 + static_cast<std::size_t>(std::pow(300.0, unit(random)));
        if (kind < 0.2) {
            to(deepest * (0.05 + 0.9 * unit(random)), steps);  // a drawdown
        } else if (kind < 0.35) {
            to(deepest, steps);  // back exactly to D
        } else if (kind < 0.5) {
            to(std::min(peak, deepest * (1.0 + 0.3 * unit(random))), steps);  // a new peak
        } else if (kind < 0.65) {
            to(d, steps);  // a hold
        } else if (kind < 0.8) {  // a jump
            d = deepest * (0.5 + 0.5 * unit(random));
            point();
            to(d, steps);
        } else {  // wiggles below D
            const double size = deepest * std::pow(10.0, -6.0 + 4.0 * unit(random));
            for (std::size_t i = 0; i < steps; ++i) to(std::min(deepest, d + size * (unit(random) - 0.5)), 1);
        }
    }
    return history;
}

rheology::Rheology adversarial_material(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<rheology::RelaxationTerm> terms;
    const int count = 1 + static_cast<int>(6 * unit(random));
    double transient = 0.0;
    for (int k = 0; k < count; ++k) {
        terms.push_back({1e5 * std::pow(10.0, unit(random)), 1e-3 * std::pow(10.0, -2.0 + 6.0 * unit(random))});
        transient += terms.back().modulus;
    }
    return rheology::Rheology::prony(transient * std::pow(10.0, -3.0 * unit(random)), terms);
}

// Forces at the points, except the first of two points at one time (the drivers record the state after a jump).
void expect_same_forces(const History& history, const std::vector<double>& band, const std::vector<double>& expected,
                        double tolerance, int trial) {
    const double scale = largest(expected);
    for (std::size_t i = 0; i < history.time.size(); ++i) {
        if (i + 1 < history.time.size() && history.time[i + 1] == history.time[i]) continue;
        ASSERT_NEAR(band[i], expected[i], tolerance * scale) << "trial " << trial << ", t = " << history.time[i];
    }
}

TEST(BandModel, AdversarialHistoriesAgreeWithTheElementModel) {
    std::mt19937 random(2511);
    for (int trial = 0; trial < 60; ++trial) {
        const auto material = adversarial_material(random);
        const auto indenter = indenter_of(trial);
        const History history = adversarial(random, 1e-5);
        const std::size_t elements = 2000;
        const auto [expected, spacing] = element_forces(material, indenter, history, elements);
        const auto band = band_forces(material, *indenter, spacing, elements, history.time, history.depth);
        ASSERT_TRUE(band.has_value()) << "trial " << trial;
        expect_same_forces(history, band->force, expected, 1e-9, trial);
    }
}

// Materials without an equilibrium modulus (G_inf = 0: the power law's series, random fluids of one to four branches)
// have no band g <= L; the memory bound (band_model.hpp) folds the elements instead. On the measured-like and the
// adversarial histories the forces are the element model's to 1e-9 of the peak, and on the measured-like ones the
// band model steps a small share of the elements (printed).
rheology::Rheology fluid_material(std::mt19937& random, int trial) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    if (trial % 2 == 0) {  // G0 (t/t0)^(-beta) over the history's lags, as a fit's power_law candidate converts it
        const rheology::PowerLaw power{.G0 = 1e5 * (0.5 + unit(random)), .beta = 0.05 + 0.6 * unit(random), .t0 = 1.0};
        return rheology::approximate(power, {.shortest = 1e-4, .longest = 10.0}, 1e-4).series;
    }
    std::vector<rheology::RelaxationTerm> terms;
    for (int k = 0; k < 1 + trial % 4; ++k) {
        terms.push_back({1e5 * std::pow(10.0, unit(random)), std::pow(10.0, -4.0 + 5.0 * unit(random))});
    }
    return rheology::Rheology::prony(0.0, terms);
}

TEST(BandModel, MaterialsWithoutAnEquilibriumModulusAgreeWithTheElementModel) {
    std::mt19937 random(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 24; ++trial) {
        const auto material = fluid_material(random, trial);
        ASSERT_EQ(material.equilibrium_modulus(), 0.0);
        const auto indenter = indenter_of(trial);
        const bool measured = trial < 12;
        const History history = measured ? measured_like(random, 1e-5, std::pow(10.0, -4.0 + unit(random)))
                                         : adversarial(random, 1e-5);
        const std::size_t elements = 2000;
        const auto [expected, spacing] = element_forces(material, indenter, history, elements);
        const auto band = band_forces(material, *indenter, spacing, elements, history.time, history.depth);
        ASSERT_TRUE(band.has_value()) << "trial " << trial;
        expect_same_forces(history, band->force, expected, 1e-9, trial);
        const double all = static_cast<double>(elements) * static_cast<double>(history.time.size());
        std::cout << "trial " << trial << (measured ? " (measured-like)" : " (adversarial)") << ": "
                  << material.terms().size() << " branches, element steps "
                  << static_cast<double>(band->element_steps) / all << " of the element model's\n";
    }
}

// A spring in parallel with a long series (a fractional Kelvin-Voigt solid as its fit converts it: a power law's
// series plus a soft G_inf, G(0)/G_inf from 1e3 to 1e6): the dips of a measured depth make L = D - (G(0)/G_inf)(D - d)
// fall below every element, and the memory bound (band_model.hpp, with its G_inf (d - g) term) folds them instead.
// Depth- and force-driven, the element model's values to 1e-9 of the peak; the share of element steps is printed.
rheology::Rheology spring_and_series(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const rheology::PowerLaw power{.G0 = 1e5 * (0.5 + unit(random)), .beta = 0.1 + 0.5 * unit(random), .t0 = 1.0};
    const auto series = rheology::approximate(power, {.shortest = 1e-4, .longest = 10.0}, 1e-4).series;
    return rheology::Rheology::prony(series.instantaneous_modulus() * std::pow(10.0, -3.0 - 3.0 * unit(random)),
                                     series.terms());
}

TEST(BandModel, ASpringWithASeriesAgreesWithTheElementModel) {
    std::mt19937 random(37);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 12; ++trial) {
        const auto material = spring_and_series(random);
        const auto indenter = indenter_of(trial);
        const bool measured = trial < 8;
        const History history = measured ? measured_like(random, 1e-5, std::pow(10.0, -4.0 + unit(random)))
                                         : adversarial(random, 1e-5);
        const std::size_t elements = 2000;
        const auto [expected, spacing] = element_forces(material, indenter, history, elements);
        const auto band = band_forces(material, *indenter, spacing, elements, history.time, history.depth);
        ASSERT_TRUE(band.has_value()) << "trial " << trial;
        expect_same_forces(history, band->force, expected, 1e-9, trial);
        const double all = static_cast<double>(elements) * static_cast<double>(history.time.size());
        std::cout << "trial " << trial << ": G(0)/G_inf "
                  << material.instantaneous_modulus() / material.equilibrium_modulus() << ", element steps "
                  << static_cast<double>(band->element_steps) / all << " of the element model's\n";
    }
}

// A relaxed preload needs G_inf > 0: with G_inf = 0 the band model hands it back.
TEST(BandModel, RefusesARelaxedPreloadWithoutAnEquilibriumModulus) {
    const auto material = rheology::Rheology::prony(0.0, {{1e5, 0.1}});
    const std::shared_ptr<const profile::Profile> sphere = profile::make_sphere(1e-3);
    const std::vector<double> time{0.0, 1e-3, 2e-3}, depth{1e-6, 1.1e-6, 1.2e-6};
    EXPECT_FALSE(band_forces(material, *sphere, 1e-6, 1000, time, depth, {}, true).has_value());
    EXPECT_TRUE(band_forces(material, *sphere, 1e-6, 1000, time, depth, {}, false).has_value());
}

// A fast unloading by delta (one step of tau/20) after a hold of 14 tau at the peak D (the memory relaxed to 1e-6):
// an element stays in contact while G_inf (D - delta - g) - (G(0) - G_inf) delta >= 0 nearly, i.e. g <= L =
// D - (G(0)/G_inf) delta; those beyond leave contact in the step. Here the memory bound's floor test G_inf g + m <=
// G_inf d + S (band_model.hpp) is that edge (m = 0 after the hold, S = -(G(0) - G_inf) delta nearly): the band model
// keeps exactly the elements the element model keeps. G(0)/G_inf = 11.
TEST(BandModel, UnloadingAfterARelaxedHoldReleasesExactlyTheElementsBeyondTheBand) {
    const auto material = rheology::Rheology::prony(1e5, {{1e6, 0.02}});
    const std::shared_ptr<const profile::Profile> sphere = profile::make_sphere(1e-3);
    History history;
    const double peak = 1e-5;
    for (int i = 0; i <= 400; ++i) {
        history.time.push_back(1e-3 * i);
        history.depth.push_back(i == 0 ? -1e-7 : i <= 20 ? peak * i / 20.0 : i <= 300 ? peak : 0.95 * peak);
    }
    const std::size_t elements = 2000;
    const auto [expected, spacing] = element_forces(material, sphere, history, elements);
    const auto band = band_forces(material, *sphere, spacing, elements, history.time, history.depth);
    ASSERT_TRUE(band.has_value());
    expect_same_forces(history, band->force, expected, 1e-9, 0);
}

// Two properties of the drivers' Foundation (every element stepped) on any history. Every update of the foundation
// (contact step, free step, and both parts of a split one) is the exact memory of a w linear over the (sub)step, so
// h_k(t) = int exp(-(t - s)/tau_k) w'(s) ds >= w(t) - max_s<=t w(s) (integration by parts, any history); a free
// element's w never grows (sigma = 0 after a history of sigma >= 0 and a creep compliance with a decreasing slope,
// Prony moduli >= 0), so max w <= D - g, and in contact h_k >= d - D.
// Checked on the adversarial histories: after every step, w <= D - g for each element touched, and h_k >= d - D for
// each one in contact.
TEST(BandModel, TheElementModelNeverLetsASurfaceSinkBelowTheDeepestIndentation) {
    std::mt19937 random(2512);
    for (int trial = 0; trial < 40; ++trial) {
        const auto material = adversarial_material(random);
        const auto indenter = indenter_of(trial);
        const History history = adversarial(random, 1e-5);
        double deepest = 0.0;
        for (double d : history.depth) deepest = std::max(deepest, d);
        const std::size_t elements = 400;
        const double spacing = 1.2 * indenter->contact_radius(deepest) / static_cast<double>(elements);
        foundation::Foundation model(material, *indenter, spacing, elements);
        const std::size_t branches = material.terms().size();
        std::vector<double> state(foundation::Foundation::state_size(elements, branches));
        foundation::StepCoefficients coefficients;
        double peak = 0.0;
        const auto check = [&](double start, double end, double time_step) {
            foundation::fill_step_coefficients(material, time_step, coefficients);
            model.begin_step(coefficients);
            model.advance(start, end);
            peak = std::max(peak, end);
            model.save_state(state);
            const double* w = state.data() + 3;
            const double* contact = w + 2 * elements;
            const double* h = w + 3 * elements;
            const double round_off = 1e-12 * deepest;
            for (std::size_t i = 0; i < model.touched(); ++i) {
                const double g = indenter->equivalent((static_cast<double>(i) + 0.5) * spacing);
                ASSERT_LE(w[i], peak - g + round_off) << "trial " << trial << ", element " << i;
                for (std::size_t k = 0; k < branches && contact[i] != 0.0; ++k) {
                    ASSERT_GE(h[k * elements + i], end - peak - round_off) << "trial " << trial << ", element " << i;
                }
            }
        };
        if (history.depth.front() > 0.0) check(0.0, history.depth.front(), 0.0);
        for (std::size_t i = 1; i < history.time.size(); ++i) {
            check(history.depth[i - 1], history.depth[i], history.time[i] - history.time[i - 1]);
            if (HasFatalFailure()) return;
        }
    }
}

// A tabulated profile ends at its last radius r_n (g is +infinity beyond, not a rigid wall): a depth beyond g(r_n)
// on a foundation of half-width r_n is the drivers' error (key indenter.r), so the band model must hand the run back
// (nullopt) rather than sum a truncated indenter; below it both agree.
TEST(BandModel, HandsADepthBeyondATabulatedProfileBackToTheDrivers) {
    const auto material = rheology::Rheology::prony(1e5, {{3e5, 0.05}});
    std::vector<double> r, f;
    for (int i = 0; i <= 20; ++i) {
        r.push_back(1e-6 * i);
        f.push_back(r.back() * r.back() / 2e-3);  // a sphere of radius 1 mm, to r = 20 um
    }
    const std::shared_ptr<const profile::Profile> table = profile::make_table(r, f);
    const double edge = table->equivalent(r.back());
    const std::size_t elements = 500;
    const double spacing = r.back() / static_cast<double>(elements);
    const auto history = [&](double peak) {
        History ramp;
        for (int i = 0; i <= 100; ++i) {
            ramp.time.push_back(1e-3 * i);
            ramp.depth.push_back(peak * (static_cast<double>(i) - 1.0) / 99.0);
        }
        return ramp;
    };
    const History inside = history(0.99 * edge);
    const auto [expected, inside_spacing] = element_forces(material, table, inside, elements);
    const auto band = band_forces(material, *table, inside_spacing, elements, inside.time, inside.depth);
    ASSERT_TRUE(band.has_value());
    expect_same_forces(inside, band->force, expected, 1e-9, 0);
    const History beyond = history(1.01 * edge);
    EXPECT_FALSE(band_forces(material, *table, spacing, elements, beyond.time, beyond.depth).has_value());
    foundation::Foundation drivers_model(material, *table, spacing, elements);
    foundation::StepCoefficients coefficients;
    foundation::fill_step_coefficients(material, 1e-3, coefficients);
    drivers_model.begin_step(coefficients);
    EXPECT_THROW(drivers_model.advance(0.0, 1.01 * edge), InvalidInput);
}

// A measured-like force history: an approach at zero force with noise (clipped to 0 by the model: no contact), a
// ramp with a pause at constant force, a hold (creep), a partial unloading, a reloading past the peak, a full
// unloading to 0 held (the surface recovers), a reloading and a hold; AR(1) noise (correlation 0.7) of `noise` times
// the peak on every point, so the force dips in about a third of the steps.
History force_like(std::mt19937& random, double peak, double noise) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    History history;  // depth holds the force here
    const double dt = 1e-3 * (0.5 + unit(random));
    double t = 0.0, smooth = 0.0, correlated = 0.0;
    const auto add = [&](std::size_t steps, double change) {
        for (std::size_t i = 0; i < steps; ++i) {
            smooth += change / static_cast<double>(steps);
            correlated = 0.7 * correlated + std::sqrt(1.0 - 0.49) * noise * peak * normal(random);
            history.time.push_back(t);
            history.depth.push_back(smooth + correlated);
            t += dt;
        }
    };
    add(40, 0.0);
    add(100 + static_cast<std::size_t>(100 * unit(random)), 0.5 * peak);
    add(60, 0.0);
    add(100, 0.5 * peak);
    add(300, 0.0);
    add(80, -0.5 * peak * unit(random));
    add(80, 0.3 * peak);
    add(100, 0.0);
    smooth = peak * (1.0 + 0.3 * unit(random));
    add(60, -smooth);
    add(150, 0.0);
    add(80, 0.8 * peak);
    add(150, 0.0);
    return history;
}

// A fit's force-driven model case of `history` (as run_curve builds it: the force above 0, from the undeformed state
// one interval before the first point, the fit's elements).
drivers::ContactCase force_case(const rheology::Rheology& material,
                                const std::shared_ptr<const profile::Profile>& indenter, const History& history,
                                std::size_t elements) {
    std::vector<drivers::LoadPoint> points{{history.time.front() - (history.time[1] - history.time[0]), 0.0}};
    for (std::size_t i = 0; i < history.time.size(); ++i) {
        points.push_back({history.time[i], std::max(history.depth[i], 0.0)});
    }
    drivers::ContactCase contact_case{.title = "band creep",
                                      .material = material,
                                      .indenter = indenter,
                                      .control = drivers::ForceControl{},
                                      .load = {.history = drivers::LoadHistory(std::move(points), "load.history")},
                                      .end_time = history.time.back()};
    contact_case.numerics.elements = elements;
    contact_case.numerics.output_every = 1;
    return contact_case;
}

// The element model's and the band model's depths at the points with a force > 0 (the last row of each time);
// their largest difference relative to the peak depth. Prints the band model's share of the element steps.
double force_driven_difference(const drivers::ContactCase& contact_case, const History& history) {
    const auto numerics = drivers::resolve_numerics(contact_case);
    const auto nodes = drivers::indentation_grid(contact_case, numerics);
    const std::size_t elements = numerics.elements;
    const auto band = band_depths(contact_case.material, *contact_case.indenter,
                                  numerics.half_width / static_cast<double>(elements), elements, nodes);
    EXPECT_TRUE(band.has_value());
    if (!band) return 1.0;
    const auto result = drivers::run_case(contact_case);
    EXPECT_EQ(result.time.size(), nodes.size());
    double difference = 0.0, deepest = 0.0;
    std::size_t row = 0;
    for (std::size_t i = 0; i < history.time.size(); ++i) {
        if (!(history.depth[i] > 0.0)) continue;
        while (row + 1 < result.time.size() && result.time[row + 1] <= history.time[i]) ++row;
        EXPECT_EQ(nodes[row].time, result.time[row]);
        difference = std::max(difference, std::abs(band->depth[row] - result.depth[row]));
        deepest = std::max(deepest, std::abs(result.depth[row]));
    }
    const double all = static_cast<double>(elements) * static_cast<double>(nodes.size());
    std::cout << "element steps " << static_cast<double>(band->element_steps) / all << " of the element model's; ";
    return difference / deepest;
}

TEST(BandModel, MeasuredLikeForceHistoriesAgreeWithTheElementModel) {
    std::mt19937 random(2525);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 9; ++trial) {
        const auto material = random_material(random, trial);
        const auto indenter = indenter_of(trial);
        const double noise = std::pow(10.0, -4.0 + 1.5 * unit(random));
        const History history = force_like(random, 1e-4, noise);
        const double difference = force_driven_difference(force_case(material, indenter, history, 2000), history);
        EXPECT_LT(difference, 1e-9) << "trial " << trial;
        std::cout << "trial " << trial << ": noise " << noise << ", depths agree to " << difference << " of the peak\n";
    }
}

// Force histories of `trials` materials drawn by `material_of(random, trial)`, force_like(random, peak, noise) each,
// on 1000 elements: the band model's depths are the element model's to 1e-9 of the peak.
template <class MaterialOf>
void expect_force_histories_agree(unsigned seed, int trials, MaterialOf material_of, double peak, double noise) {
    std::mt19937 random(seed);
    for (int trial = 0; trial < trials; ++trial) {
        const auto material = material_of(random, trial);
        const auto indenter = indenter_of(trial);
        const History history = force_like(random, peak, noise);
        const double difference = force_driven_difference(force_case(material, indenter, history, 1000), history);
        EXPECT_LT(difference, 1e-9) << "trial " << trial;
        std::cout << "trial " << trial << ": " << material.terms().size() << " branches, " << difference << "\n";
    }
}

// The adversarial materials above (G(0)/G_inf from 1 to 1000 and more, relaxation times from 1e-5 to 10 s, shorter
// than the step: the drivers' graded grid) under the measured-like force histories.
TEST(BandModel, AdversarialMaterialsUnderForceAgreeWithTheElementModel) {
    expect_force_histories_agree(
        2526, 12, [](std::mt19937& random, int) { return adversarial_material(random); }, 1e-3, 1e-3);
}

// The materials without an equilibrium modulus above (the memory bound) under the measured-like force histories.
TEST(BandModel, MaterialsWithoutAnEquilibriumModulusUnderForceAgreeWithTheElementModel) {
    expect_force_histories_agree(2527, 8, fluid_material, 1e-4, 3e-4);
}

// The spring with a series above under the measured-like force histories.
TEST(BandModel, ASpringWithASeriesUnderForceAgreesWithTheElementModel) {
    expect_force_histories_agree(
        2528, 6, [](std::mt19937& random, int) { return spring_and_series(random); }, 1e-4, 3e-4);
}

// A fit's force-driven element run (run_curve, fitted = "depth") is the band model, with the drivers' elements and
// time grid: its depths at the curve's points in contact are the drivers' element model's.
TEST(BandModel, FitsRunForceDrivenCurvesAsTheBandModel) {
    std::mt19937 random(11);
    const auto material = rheology::Rheology::prony(2e3, {{4e3, 0.05}, {3e3, 0.8}});
    const std::shared_ptr<const profile::Profile> indenter = profile::make_sphere(5e-6);
    const History history = force_like(random, 5e-9, 3e-4);
    Curve curve;
    curve.name = "measured-like creep";
    curve.time = history.time;
    curve.force = history.depth;
    curve.depth.assign(history.time.size(), 0.0);
    curve.force_noise = 3e-4 * 5e-9;
    curve.depth_noise = 1e-9;
    const CurveModel prepared = prepare_curve(curve, Fitted::depth, 0.0);
    drivers::ContactCase model_case{.title = "fit",
                                    .material = material,
                                    .indenter = indenter,
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    const std::size_t elements = 1000;
    const double contact_depth = 1e-8;
    const auto model = run_curve(model_case, prepared, contact_depth, {}, elements, ForwardModel::elements);
    ASSERT_TRUE(model.has_value());
    EXPECT_TRUE(model->band);
    const auto expected = drivers::run_case(force_case(material, indenter, history, elements));
    ASSERT_EQ(model->values.size(), prepared.used.size());
    ASSERT_GT(prepared.used.size(), history.time.size() / 2);
    double deepest = 0.0;
    for (double d : expected.depth) deepest = std::max(deepest, d);
    std::size_t row = 0;
    for (std::size_t j = 0; j < prepared.used.size(); ++j) {
        const double t = history.time[prepared.used[j]];
        while (row + 1 < expected.time.size() && expected.time[row + 1] <= t) ++row;
        ASSERT_NEAR(model->values[j], expected.depth[row] + contact_depth, 1e-9 * deepest) << "t = " << t;
    }
}

// A force whose contact outgrows a given half-width: the band model hands the run back (nullopt), and the drivers
// report it (key numerics.half_width).
TEST(BandModel, HandsAForceDrivenContactBeyondTheFoundationBackToTheDrivers) {
    std::mt19937 random(12);
    const auto material = rheology::Rheology::prony(1e5, {{3e5, 0.05}});
    const std::shared_ptr<const profile::Profile> sphere = profile::make_sphere(1e-3);
    const History history = force_like(random, 1e-3, 1e-4);
    auto contact_case = force_case(material, sphere, history, 500);
    contact_case.numerics.half_width = 0.5 * drivers::resolve_numerics(contact_case).half_width;
    const auto numerics = drivers::resolve_numerics(contact_case);
    const auto nodes = drivers::indentation_grid(contact_case, numerics);
    EXPECT_FALSE(band_depths(material, *sphere, numerics.half_width / 500.0, 500, nodes).has_value());
    EXPECT_THROW(drivers::run_case(contact_case), InvalidInput);
}

}  // namespace
}  // namespace mdr::fit
