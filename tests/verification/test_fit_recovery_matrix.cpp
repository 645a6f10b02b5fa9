// The fit's noise-free recovery over the materials and histories that issue 10 names: elastic, standard solid and a
// 3-term Prony series, each from a loading-only, a load-hold, a load-unload and a cyclic curve of a sphere. The data
// come from the independent references (tests/support/reference: Ting's solution for the triangle and its loading
// part, the Lee-Radok quadrature for the load-hold), never from mdr. The cyclic curve is two triangles apart by a
// pause of 40 times the longest relaxation time: after it every branch's memory of the first cycle is below
// e^-40 (the surface has recovered and sum G(t - s) de(s) over the first cycle is G_inf times its net strain, 0),
// so the second cycle is Ting's triangle again, shifted. Its reloading lies outside Ting's class, so the fit runs it
// on the element model; the other three run on the continuum model.
// (Kelvin-Voigt creep under force: tests/verification/test_fit.cpp.)

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "reference/closed_forms.hpp"
#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/ting.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-3;      // sphere radius [m]
constexpr double speed = 2e-5;  // loading speed [m/s]; the peak depth is speed x peak time
constexpr double peak = 1.0;    // time of the peak depth [s]

struct Material {
    std::string name;
    reference::PronyMaterial truth;  // G_inf and the (G_k, tau_k)
    std::vector<double> start;       // the fit's start: G_inf, then G_k, tau_k per term
};

// The material's free values in the fit's order: G_inf, then G_k, tau_k per term.
std::vector<double> values_of(const reference::PronyMaterial& material) {
    std::vector<double> values{material.G_inf};
    for (const auto& [modulus, time] : material.terms) values.insert(values.end(), {modulus, time});
    return values;
}

fit::FitProblem problem_for(const Material& material, fit::Curve curve) {
    fit::FitProblem problem;
    problem.model = [](const std::vector<double>& values) {
        std::vector<rheology::RelaxationTerm> terms;
        for (std::size_t k = 1; k + 1 < values.size(); k += 2) terms.push_back({values[k], values[k + 1]});
        return drivers::ContactCase{.title = "fit model",
                                    .material = rheology::Rheology(values[0], 0.0, std::move(terms)),
                                    .indenter = profile::make_sphere(R),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    problem.parameters.push_back({"material.G_inf", material.start[0], 1e3, 1e9});
    for (std::size_t k = 1; k + 1 < material.start.size(); k += 2) {
        const std::string term = "material.terms[" + std::to_string(k / 2) + "]";
        problem.parameters.push_back({term + "[0]", material.start[k], 1e3, 1e9});
        problem.parameters.push_back({term + "[1]", material.start[k + 1], 1e-3, 1e3});
    }
    problem.curves = {std::move(curve)};
    problem.settings.contact_point = fit::ContactPointMode::fixed;
    problem.settings.baseline = fit::BaselineMode::fixed;
    return problem;
}

// A curve of `points` samples over [0, end] of depth(t) and force(t).
template <class Depth, class Force>
fit::Curve sampled(const std::string& name, double end, std::size_t points, Depth depth, Force force) {
    fit::Curve curve;
    curve.name = name;
    for (std::size_t i = 0; i < points; ++i) {
        const double t = end * static_cast<double>(i) / static_cast<double>(points - 1);
        curve.time.push_back(t);
        curve.depth.push_back(depth(t));
        curve.force.push_back(force(t));
    }
    return curve;
}

fit::Curve history_curve(const std::string& history, const reference::PronyMaterial& material) {
    const reference::TingSolution ting(reference::sphere_indenter(R), material, speed, peak);
    double longest = 0.0;
    for (const auto& term : material.terms) longest = std::max(longest, term.second);
    if (history == "loading") {
        return sampled(history, peak, 401, [&](double t) { return ting.depth(t); },
                       [&](double t) { return ting.force(t); });
    }
    if (history == "load-unload") {
        return sampled(history, 2.0 * peak, 401, [&](double t) { return ting.depth(t); },
                       [&](double t) { return ting.force(t); });
    }
    if (history == "load-hold") {
        const double end = peak + 4.0 * std::max(longest, peak);
        const reference::PiecewiseLinear depth{{0.0, peak, end}, {0.0, speed * peak, speed * peak}};
        const auto points = static_cast<std::size_t>(std::lround(50.0 * end / peak)) + 1;  // the ramp's end a sample
        return sampled(history, end, points, [&](double t) { return depth.value(t); },
                       [&](double t) {
                           return reference::lee_radok_force(reference::sphere_indenter(R), material, depth, t);
                       });
    }
    // cyclic: a triangle, a pause of 40 longest times at zero depth, the same triangle again
    const double second = 2.0 * peak + 40.0 * std::max(longest, peak);
    fit::Curve curve = sampled(history, 2.0 * peak, 201, [&](double t) { return ting.depth(t); },
                               [&](double t) { return ting.force(t); });
    const fit::Curve cycle = curve;
    // The pause, sampled geometrically (the free surface recovers on the material's times after the contact ends).
    for (int i = 1; i < 100; ++i) {
        curve.time.push_back(2.0 * peak * std::pow(second / (2.0 * peak), i / 100.0));
        curve.depth.push_back(0.0);
        curve.force.push_back(0.0);
    }
    for (std::size_t i = 0; i < cycle.time.size(); ++i) {
        curve.time.push_back(second + cycle.time[i]);
        curve.depth.push_back(cycle.depth[i]);
        curve.force.push_back(cycle.force[i]);
    }
    return curve;
}

struct Case {
    Material material;
    std::string history;
    double tolerance;  // relative, of every recovered value
};

void PrintTo(const Case& c, std::ostream* out) { *out << c.material.name << ", " << c.history; }

class FitRecoveryMatrix : public ::testing::TestWithParam<Case> {};

TEST_P(FitRecoveryMatrix, NoiseFreeDataGiveTheMaterialBack) {
    const auto& [material, history, tolerance] = GetParam();
    const auto result = fit::fit(problem_for(material, history_curve(history, material.truth)));
    ASSERT_TRUE(result.converged) << result.status;
    const auto truth = values_of(material.truth);
    double worst = 0.0;
    for (std::size_t j = 0; j < truth.size(); ++j) {
        worst = std::max(worst, std::abs(result.values[j] / truth[j] - 1.0));
        EXPECT_NEAR(result.values[j] / truth[j], 1.0, tolerance) << result.names[j];
    }
    RecordProperty("worst_relative_error", fmt::format("{:.2e}", worst));
    RecordProperty("evaluations", std::to_string(result.evaluations));
    if (history == "cyclic") {
        EXPECT_EQ(result.element_evaluations, result.evaluations);  // reloading: the element model
    } else {
        EXPECT_EQ(result.element_evaluations, 0u);  // Ting's class: the continuum model
    }
}

Material material(std::string name, double G_inf, std::vector<std::pair<double, double>> terms,
                  std::vector<double> start) {
    Material made;
    made.name = std::move(name);
    made.truth.G_inf = G_inf;
    made.truth.terms = std::move(terms);
    made.start = std::move(start);
    return made;
}

// Every material with every history, and the tolerance of each.
std::vector<Case> recovery_cases() {
    const Material elastic = material("elastic", 1e6, {}, {3e5});
    const Material standard = material("standard", 1e6, {{2e6, 0.3}}, {3e5, 5e6, 2.0});
    const Material prony3 =
        material("prony3", 1e6, {{3e6, 0.1}, {2e6, 1.0}, {1e6, 10.0}}, {7e5, 2e6, 0.15, 1.5e6, 1.5, 1.5e6, 7.0});
    std::vector<Case> cases;
    for (const char* history : {"loading", "load-hold", "load-unload", "cyclic"}) {
        cases.push_back(Case{elastic, history, 1e-6});
        cases.push_back(Case{standard, history, 1e-6});
    }
    // Three times over three decades need a record that sees them all: the load-hold to 41 s (a 1 s ramp or a 2 s
    // triangle cannot tell a 10 s time from the equilibrium modulus).
    cases.push_back(Case{prony3, "load-hold", 1e-6});
    return cases;
}

std::string case_name(const ::testing::TestParamInfo<Case>& param_info) {
    std::string name = param_info.param.material.name + "_" + param_info.param.history;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

INSTANTIATE_TEST_SUITE_P(MaterialsAndHistories, FitRecoveryMatrix, ::testing::ValuesIn(recovery_cases()), case_name);

}  // namespace
}  // namespace mdr
