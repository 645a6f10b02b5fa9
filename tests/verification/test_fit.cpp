// mdr::fit against data made by independent models (tests/support/reference: Lee-Radok and Ting quadratures, the
// creep law eq. 34), never by mdr itself: noise-free recovery, contact point, coverage of the 95 % intervals
// under Gaussian noise, and the parameters flagged as undetermined.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mdr/error.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "reference/closed_forms.hpp"
#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/ting.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-3;       // sphere radius [m]
constexpr double depth = 2e-5;   // peak depth [m]

// The standard-solid model of a sphere of radius R; values = (G_inf, G1, tau1).
fit::ModelBuilder standard_solid_sphere() {
    return [](const std::vector<double>& values) {
        // The load is replaced by each curve's history.
        return drivers::ContactCase{.title = "fit model",
                                    .material = rheology::Rheology::standard(values[0], values[1], values[2]),
                                    .indenter = profile::make_sphere(R),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
}

std::vector<fit::FreeParameter> standard_solid_parameters(double G_inf, double G1, double tau1) {
    return {{"material.G_inf", G_inf, 1e3, 1e9}, {"material.G1", G1, 1e3, 1e9}, {"material.tau1", tau1, 1e-3, 1e3}};
}

// Load-hold data: d = depth t / ramp up to `ramp`, then held to `end`; the force by Lee-Radok quadrature.
fit::Curve load_hold_curve(const reference::PronyMaterial& material, double ramp, double end, std::size_t points) {
    const reference::PiecewiseLinear history{{0.0, ramp, end}, {0.0, depth, depth}};
    fit::Curve curve;
    curve.name = "load-hold";
    for (std::size_t i = 0; i < points; ++i) {
        const double t = end * static_cast<double>(i) / static_cast<double>(points - 1);
        curve.time.push_back(t);
        curve.depth.push_back(history.value(t));
        curve.force.push_back(reference::lee_radok_force(reference::sphere_indenter(R), material, history, t));
    }
    return curve;
}

fit::FitProblem noise_free_problem(fit::Curve curve, std::vector<fit::FreeParameter> parameters) {
    fit::FitProblem problem;
    problem.model = standard_solid_sphere();
    problem.parameters = std::move(parameters);
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    return problem;
}

void expect_relative(const fit::FitResult& result, const std::vector<double>& truth, double tolerance) {
    ASSERT_TRUE(result.converged) << result.status;
    for (std::size_t j = 0; j < truth.size(); ++j) {
        EXPECT_NEAR(result.values[j] / truth[j], 1.0, tolerance) << result.names[j];
    }
}

TEST(Fit, StandardSolidFromLoadHoldWithoutNoiseFromTwoStarts) {
    // A load-hold is in Ting's class: the continuum model (no elements, exact for a piecewise-linear depth) runs
    // every evaluation and recovers the material to 1e-8 (measured: ~1e-10).
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const auto curve = load_hold_curve(truth, 1.0, 4.0, 401);  // the ramp's end is a sample
    for (const auto& start : {std::vector<double>{3e5, 5e6, 2.0}, std::vector<double>{4e6, 4e5, 0.05}}) {
        const auto result = fit::fit(noise_free_problem(curve, standard_solid_parameters(start[0], start[1], start[2])));
        expect_relative(result, {1e6, 2e6, 0.5}, 1e-8);
        EXPECT_TRUE(result.undetermined.empty()) << result.undetermined.front().reason;
        EXPECT_LT(result.rms_residual, 1e-8 * 0.05);
        EXPECT_EQ(result.element_evaluations, 0u);
    }
}

TEST(Fit, DepthOutsideTingsClassRunsOnElements) {
    // The same data with the depth dipping by 3 % of its value for one sample while it loads: an element that left
    // contact comes back, which only the element model follows. Every run is then an element run (one model per
    // evaluation), and the fit still recovers the material to the dip's own effect (~1e-3).
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    auto curve = load_hold_curve(truth, 1.0, 4.0, 401);
    curve.depth[50] = 0.97 * curve.depth[50];  // below the sample before it
    auto problem = noise_free_problem(curve, standard_solid_parameters(3e5, 5e6, 2.0));
    problem.settings.elements = 500;
    const auto result = fit::fit(problem);
    expect_relative(result, {1e6, 2e6, 0.5}, 1e-2);
    EXPECT_GT(result.element_evaluations, 0u);
    EXPECT_EQ(result.element_evaluations, result.evaluations);
    // The cost of the fit: an iteration runs its line search's trial points (values only: one, or two where it
    // backtracks; the candidate is the last of them, kept) and, once accepted, the 3 difference columns of the
    // Jacobian; the start's Jacobian, the check of the start and the Jacobian of the uncertainties add at most 4 each.
    // With the Jacobian at every trial point (Ceres' default, cubic interpolation) it took 77 runs for 7 iterations.
    EXPECT_LE(result.evaluations, 5 * (result.iterations + 3)) << result.iterations << " iterations";
    // Where the runs went (issue 25): one count per iteration and the start, each of an iteration at most its
    // trial points and 3 columns (5), all within the fit's runs.
    ASSERT_EQ(result.runs_per_iteration.size(), result.iterations + 1);
    std::size_t runs = 0;
    for (std::size_t i = 1; i < result.runs_per_iteration.size(); ++i) EXPECT_LE(result.runs_per_iteration[i], 5u) << i;
    for (const std::size_t r : result.runs_per_iteration) runs += r;
    EXPECT_LE(runs, result.evaluations);
    EXPECT_GE(runs + 8, result.evaluations);  // after the last iteration: the uncertainties' Jacobian and the bands
}

TEST(Fit, StandardSolidFromLoadUnloadTing) {
    // Ting's solution: the contact shrinks on unloading and is lost before the indenter is back.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.3}}};
    const reference::TingSolution ting(reference::sphere_indenter(R), truth, depth, 1.0);
    fit::Curve curve;
    curve.name = "ting";
    for (std::size_t i = 0; i <= 400; ++i) {
        const double t = 0.005 * static_cast<double>(i);
        curve.time.push_back(t);
        curve.depth.push_back(ting.depth(t));
        curve.force.push_back(ting.force(t));
    }
    const auto result = fit::fit(noise_free_problem(curve, standard_solid_parameters(3e5, 5e6, 2.0)));
    expect_relative(result, {1e6, 2e6, 0.3}, 1e-8);  // the continuum model: ~1e-10 measured
    EXPECT_EQ(result.element_evaluations, 0u);
}

TEST(Fit, CreepAndRelaxationCurvesShareOneMaterial) {
    // A load-hold (depth drives, force fitted: Lee-Radok) and a creep test (force drives, depth fitted: eq. 34 with
    // the standard solid's creep function, Table 1), each curve with its own `fitted`, one standard solid for both.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    fit::Curve relaxation = load_hold_curve(truth, 1.0, 4.0, 401);
    fit::Curve creep;
    creep.name = "creep";
    creep.fitted = fit::Fitted::depth;
    const double force = 0.5;
    const auto compliance = [](double t) { return reference::standard_solid_creep(1e6, 2e6, 0.5, t); };
    for (std::size_t i = 0; i <= 400; ++i) {
        const double t = 0.005 * static_cast<double>(i);
        creep.time.push_back(t);
        creep.force.push_back(force * std::min(t / 0.05, 1.0));
        creep.depth.push_back(reference::sphere_creep_depth(compliance, R, force, 0.05, t));
    }
    auto problem = noise_free_problem(relaxation, standard_solid_parameters(3e5, 5e6, 2.0));
    problem.curves.push_back(creep);
    problem.settings.elements = 1000;  // the creep curve's force-controlled run: its time step's error
    const auto result = fit::fit(problem);
    expect_relative(result, {1e6, 2e6, 0.5}, 1e-4);
    ASSERT_EQ(result.curves.size(), 2u);
    EXPECT_EQ(result.curves[0].fitted, fit::Fitted::force);
    EXPECT_EQ(result.curves[1].fitted, fit::Fitted::depth);
    // Each curve alone is fitted with what it measures: the creep curve's model is a depth.
    EXPECT_NEAR(result.curves[1].model.back(), creep.depth.back(), 1e-4 * creep.depth.back());
}

TEST(Fit, KelvinVoigtFromCreepUnderForce) {
    // The measured force drives the model, the depth is fitted: eq. 34 for a force ramp of 0.05 s and a hold.
    const double G = 1e6, eta = 2e5, force = 0.5;
    const auto creep = [&](double t) { return t <= 0.0 ? 0.0 : -std::expm1(-t * G / eta) / G; };
    fit::Curve curve;
    curve.name = "creep";
    for (std::size_t i = 0; i <= 400; ++i) {
        const double t = 0.005 * static_cast<double>(i);
        curve.time.push_back(t);
        curve.force.push_back(force * std::min(t / 0.05, 1.0));
        curve.depth.push_back(reference::sphere_creep_depth(creep, R, force, 0.05, t));
    }
    fit::FitProblem problem;
    problem.model = [](const std::vector<double>& values) {
        return drivers::ContactCase{.title = "fit model",
                                    .material = rheology::Rheology::kelvin_voigt(values[0], values[1]),
                                    .indenter = profile::make_sphere(R),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    problem.parameters = {{"material.G", 3e5, 1e3, 1e9}, {"material.eta", 1e6, 1e2, 1e9}};
    problem.curves = {curve};
    problem.settings.fitted = fit::Fitted::depth;
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    problem.settings.elements = 1000;  // the force-controlled run's error is its time step's (second order)
    const auto result = fit::fit(problem);
    expect_relative(result, {G, eta}, 1e-4);
}

// Load-hold data seen from 0.2 s before contact, the depth shifted by `contact` and the force by `baseline`,
// with Gaussian force noise.
fit::Curve measured_curve(const reference::PronyMaterial& material, double contact, double baseline, double noise,
                          unsigned seed) {
    const reference::PiecewiseLinear history{{0.0, 1.0, 3.0}, {0.0, depth, depth}};
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gaussian(0.0, noise);
    fit::Curve curve;
    curve.name = "noisy";
    for (std::size_t i = 0; i <= 320; ++i) {
        const double t = -0.2 + 0.01 * static_cast<double>(i);
        curve.time.push_back(t);
        curve.depth.push_back(contact + (t < 0.0 ? depth * t : history.value(t)));
        const double f = t <= 0.0 ? 0.0 : reference::lee_radok_force(reference::sphere_indenter(R), material, history, t);
        curve.force.push_back(baseline + f + gaussian(random));
    }
    curve.force_noise = noise;
    return curve;
}

TEST(Fit, ContactPointAndBaselineFromNoisyData) {
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const double contact = 3e-6, baseline = 2e-4, noise = 1e-4;  // the peak force is ~0.1 N: noise 1e-3 of it
    auto curve = measured_curve(truth, contact, baseline, noise, 7);
    curve.contact_depth = 2e-6;  // rough estimates, as an instrument's software gives
    curve.force_baseline = 0.0;
    fit::FitProblem problem;
    problem.model = standard_solid_sphere();
    problem.parameters = standard_solid_parameters(3e5, 5e6, 2.0);
    problem.curves = {curve};
    problem.settings.baseline = fit::BaselineMode::fit;  // fitted with its error (the default takes it from the rows
                                                         // before contact, which estimate_contact finds)
    problem.settings.elements = 500;
    const auto result = fit::fit(problem);
    ASSERT_TRUE(result.converged) << result.status;
    const auto& fitted = result.curves.front();
    // The contact point to a fraction of the depth that the noise corresponds to at the peak (noise / stiffness).
    const double stiffness = 8.0 * 3e6 * std::sqrt(R * depth) * 0.3;  // a lower bound of the contact stiffness
    EXPECT_NEAR(fitted.contact_depth, contact, 0.3 * noise / stiffness + 3.0 * fitted.contact_depth_error);
    EXPECT_NEAR(fitted.baseline, baseline, 3.0 * fitted.baseline_error + 1e-9);
    EXPECT_NEAR(result.rms_residual / noise, 1.0, 0.15);
    const std::vector<double> exact{1e6, 2e6, 0.5};
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(result.values[j], exact[j], 4.0 * result.standard_errors[j]);

    // The identified G(t) and its 95 % band against the delta method written out for the standard solid:
    // dG/dG_inf = 1, dG/dG1 = e, dG/dtau1 = G1 t e / tau1^2 with e = exp(-t / tau1).
    const auto& bands = result.material;
    ASSERT_EQ(bands.times.size(), 121u);
    EXPECT_NEAR(bands.times.front(), 0.01, 1e-12);  // the sampling interval ...
    EXPECT_NEAR(bands.times.back(), 3.2, 1e-9);     // ... to the record
    const auto& s = result.standard_errors;
    const auto& rho = result.correlation;
    for (std::size_t i = 0; i < bands.times.size(); i += 20) {
        const double t = bands.times[i], g1 = result.values[1], tau = result.values[2];
        const double e = std::exp(-t / tau);
        const double g[3] = {1.0, e, g1 * t * e / (tau * tau)};
        double variance = 0.0;
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) variance += g[a] * g[b] * s[a] * s[b] * rho[a][b];
        }
        EXPECT_NEAR(bands.relaxation.value[i], result.values[0] + g1 * e, 1e-12 * bands.relaxation.value[i]);
        EXPECT_NEAR(bands.relaxation.upper[i] - bands.relaxation.value[i], 1.96 * std::sqrt(variance),
                    1e-4 * 1.96 * std::sqrt(variance)) << "t = " << t;
    }
    EXPECT_LT(bands.creep.lower.back(), bands.creep.value.back());
    EXPECT_NEAR(bands.omegas.front() * bands.times.back(), 1.0, 1e-12);
}

TEST(Fit, NinetyFivePercentIntervalsCoverTheTruth) {
    // 200 noise realisations: each interval holds the true value in 90-98 % of them.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const std::vector<double> exact{1e6, 2e6, 0.5};
    const reference::PiecewiseLinear history{{0.0, 1.0, 3.0}, {0.0, depth, depth}};
    fit::Curve clean;
    for (std::size_t i = 0; i <= 150; ++i) {
        const double t = 0.02 * static_cast<double>(i);
        clean.time.push_back(t);
        clean.depth.push_back(history.value(t));
        clean.force.push_back(reference::lee_radok_force(reference::sphere_indenter(R), truth, history, t));
    }
    std::vector<int> covered(3, 0);
    constexpr int seeds = 200;
    for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937_64 random(static_cast<unsigned>(seed));
        std::normal_distribution<double> gaussian(0.0, 2e-3);  // 2 % of the peak force
        fit::Curve curve = clean;
        for (double& f : curve.force) f += gaussian(random);
        curve.force_noise = 2e-3;
        auto problem = noise_free_problem(curve, standard_solid_parameters(1e6, 2e6, 0.5));
        problem.settings.elements = 250;  // model error ~1e-6, far below the noise
        const auto result = fit::fit(problem);
        ASSERT_TRUE(result.converged) << result.status;
        for (std::size_t j = 0; j < 3; ++j) covered[j] += result.lower_95[j] <= exact[j] && exact[j] <= result.upper_95[j];
    }
    for (std::size_t j = 0; j < 3; ++j) {
        EXPECT_GE(covered[j], 180) << j;
        EXPECT_LE(covered[j], 196) << j;
    }
}

TEST(Fit, AtABoundOnlyWhenTheValueIsThere) {
    // G_inf fitted on a linear scale within [1, 1e11] (a bound must be where the material can be built: G_inf > 0):
    // the true 1e6 is 1e-5 of that span from the lower bound, and was once flagged "at its lower bound" (as a
    // spectrum's G[3] = 0.0145 with bound 0). It is not at it.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    auto parameters = standard_solid_parameters(1.2e6, 2e6, 0.5);
    parameters[0].lower = 1.0;
    parameters[0].upper = 1e11;
    parameters[0].logarithmic = false;
    const auto result = fit::fit(noise_free_problem(load_hold_curve(truth, 1.0, 4.0, 201), parameters));
    expect_relative(result, {1e6, 2e6, 0.5}, 1e-6);
    for (const auto& entry : result.undetermined) EXPECT_NE(entry.name, "material.G_inf") << entry.reason;

    // A time held at its upper bound (the data want a longer one) is at it, and the message gives the bound.
    auto held = standard_solid_parameters(1e6, 2e6, 0.2);
    held[2].upper = 0.3;
    const auto at_bound = fit::fit(noise_free_problem(load_hold_curve(truth, 1.0, 4.0, 201), held));
    bool flagged = false;
    for (const auto& entry : at_bound.undetermined) {
        flagged |= entry.reason == "material.tau1 = 0.3 is at its upper bound 0.3: the data push it beyond";
    }
    EXPECT_TRUE(flagged);
}

TEST(Fit, YoungModuliOfTheFittedShearModuli) {
    // E = 2 (1 + nu) G with nu = 0.5 for every key whose registry unit is Pa: G_inf and the modulus of a Prony term
    // (terms[0][0]), not its time (terms[0][1]). A compressible body (a bulk part: shear_material set) has none, and
    // a flag says why.
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    fit::FitProblem problem = noise_free_problem(load_hold_curve(truth, 1.0, 4.0, 201), {});
    const auto prony_sphere = [](const std::vector<double>& values) {
        return drivers::ContactCase{.title = "fit model",
                                    .material = rheology::Rheology::prony(values[0], {{values[1], values[2]}}),
                                    .indenter = profile::make_sphere(R),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    problem.model = prony_sphere;
    problem.parameters = {{"material.G_inf", 1.2e6, 1e3, 1e9},
                          {"material.terms[0][0]", 1.5e6, 1e3, 1e9},
                          {"material.terms[0][1]", 0.4, 1e-3, 1e3}};
    const auto result = fit::fit(problem);
    ASSERT_EQ(result.young_moduli.size(), 2u);
    EXPECT_EQ(result.young_moduli[0].name, "material.G_inf");
    EXPECT_EQ(result.young_moduli[1].name, "material.terms[0][0]");
    EXPECT_NEAR(result.young_moduli[0].value / 3e6, 1.0, 1e-6);
    EXPECT_NEAR(result.young_moduli[1].value / 6e6, 1.0, 1e-6);

    problem.model = [prony_sphere](const std::vector<double>& values) {
        auto model = prony_sphere(values);
        model.shear_material = model.material;  // as a case with a bulk part folds it in
        return model;
    };
    const auto compressible = fit::fit(problem);
    EXPECT_TRUE(compressible.young_moduli.empty());
    ASSERT_FALSE(compressible.flags.empty());
    EXPECT_EQ(compressible.flags.back().rfind("young_moduli: not reported: the body is compressible", 0), 0u);
}

TEST(Fit, TimesTheDataCannotDetermineAreFlagged) {
    // A relaxation time ten times longer than the record: flagged, not reported as a confident number.
    const reference::PronyMaterial slow{1e6, 0.0, {{2e6, 40.0}}};
    auto problem_slow = noise_free_problem(load_hold_curve(slow, 1.0, 4.0, 201), standard_solid_parameters(1e6, 2e6, 40.0));
    problem_slow.settings.elements = 500;  // flags, not digits, are tested here
    const auto result = fit::fit(problem_slow);
    ASSERT_FALSE(result.undetermined.empty());
    bool tau_flagged = false;
    for (const auto& entry : result.undetermined) tau_flagged |= entry.name == "material.tau1";
    EXPECT_TRUE(tau_flagged);

    // Two equal relaxation times in a two-term Prony series.
    const reference::PronyMaterial one_time{1e6, 0.0, {{2e6, 0.5}}};
    fit::FitProblem problem = noise_free_problem(load_hold_curve(one_time, 1.0, 4.0, 201), {});
    problem.model = [](const std::vector<double>& values) {
        return drivers::ContactCase{
            .title = "fit model",
            .material = rheology::Rheology::prony(values[0], {{values[1], values[2]}, {values[3], values[4]}}),
            .indenter = profile::make_sphere(R),
            .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
            .end_time = 1.0};
    };
    problem.parameters = {{"material.G_inf", 1e6, 1e3, 1e9},          {"material.terms[0][0]", 1e6, 1e3, 1e9},
                          {"material.terms[0][1]", 0.4, 1e-3, 1e3}, {"material.terms[1][0]", 1e6, 1e3, 1e9},
                          {"material.terms[1][1]", 0.6, 1e-3, 1e3}};
    problem.settings.elements = 500;
    const auto two = fit::fit(problem);
    EXPECT_GE(two.undetermined.size(), 2u);
}

TEST(Fit, BadProblemsAreRefused) {
    const reference::PronyMaterial truth{1e6, 0.0, {{2e6, 0.5}}};
    const auto curve = load_hold_curve(truth, 1.0, 4.0, 41);
    auto inverted = noise_free_problem(curve, standard_solid_parameters(1e6, 2e6, 0.5));
    inverted.parameters[2].lower = 10.0;
    EXPECT_THROW(fit::fit(inverted), InvalidInput);
    auto outside = noise_free_problem(curve, standard_solid_parameters(1e6, 2e6, 5000.0));
    EXPECT_THROW(fit::fit(outside), InvalidInput);
    auto few = noise_free_problem(load_hold_curve(truth, 1.0, 4.0, 3), standard_solid_parameters(1e6, 2e6, 0.5));
    EXPECT_THROW(fit::fit(few), InvalidInput);
    auto none = noise_free_problem(curve, standard_solid_parameters(1e6, 2e6, 0.5));
    none.settings.fitted = fit::Fitted::depth;
    for (double& f : none.curves.front().force) f = 0.0;
    EXPECT_THROW(fit::fit(none), InvalidInput);
}

}  // namespace
}  // namespace mdr
