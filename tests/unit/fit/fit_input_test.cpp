// The rules a fit's input and result obey beyond the curves: integer settings in range, model values that are
// not subnormal, a fit that starts where its model cannot run refused naming the key, and no result with a number
// that must be finite and is not.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fit/result_check.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::fit {
namespace {

template <class Body>
std::string message_of(Body body) {
    try {
        body();
    } catch (const std::exception& error) {
        return error.what();
    }
    return "";
}

// A Hertz curve (F = 16/3 G sqrt(R) d^1.5, an incompressible elastic half-space) of a sphere R = 0.5 mm, G = 2e5 Pa.
FitProblem hertz_problem() {
    std::vector<double> time, depth, force;
    for (int i = 0; i < 60; ++i) {
        time.push_back(0.01 * i);
        depth.push_back(1e-7 * i);
        force.push_back(16.0 / 3.0 * 2e5 * std::sqrt(5e-4) * std::pow(depth.back(), 1.5));
    }
    FitProblem problem;
    problem.model = [](const std::vector<double>& values) {
        return drivers::ContactCase{.title = "hertz",
                                    .material = rheology::Rheology::elastic(values[0]),
                                    .indenter = profile::make_sphere(5e-4),
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
    problem.parameters = {{"material.G", 1e5, 1e3, 1e7}};
    problem.curves = {make_curve("hertz", time, depth, force)};
    problem.settings.contact_point = ContactPointMode::fixed;
    problem.settings.baseline = BaselineMode::fixed;
    return problem;
}

// 2^31 once wrapped to a negative int in Ceres' options ("Invalid configuration" became the status and the start
// values the result); fit.elements = 1e9 once made every model run fail instead of naming the key.
TEST(FitValidate, RefusesIntegerSettingsOutOfRange) {
    FitProblem problem = hertz_problem();
    EXPECT_EQ(message_of([&] { validate(problem); }), "");
    problem.settings.max_iterations = std::size_t{1} << 31;
    EXPECT_EQ(message_of([&] { validate(problem); }), "fit.max_iterations = 2147483648: must be from 1 to 1000000");
    problem.settings.max_iterations = 0;
    EXPECT_EQ(message_of([&] { validate(problem); }), "fit.max_iterations = 0: must be from 1 to 1000000");
    problem.settings.max_iterations = max_fit_iterations;
    problem.settings.elements = foundation::max_elements + 1;
    EXPECT_EQ(message_of([&] { validate(problem); }),
              "fit.elements = 268435457: must be from 1 to 268435456 (the state would not fit in memory)");
    problem.settings.elements = 0;
    EXPECT_EQ(message_of([&] { validate(problem); }),
              "fit.elements = 0: must be from 1 to 268435456 (the state would not fit in memory)");
}

// A start value the model refuses (G = 0, inside bounds [0, 1e7] on a linear scale) once ended as "the model cannot
// be evaluated at the fitted values", exit 1, with Ceres' log lines: now the model's own rule, naming its key (here
// the Rheology's `G`; a case's builder names `material.G`).
TEST(Fit, RefusesStartValuesWhereTheModelCannotRun) {
    FitProblem problem = hertz_problem();
    problem.parameters = {{"material.G", 0.0, 0.0, 1e7, false}};
    EXPECT_EQ(message_of([&] { fit(problem); }), "G = 0: must be > 0 (at the start values of fit.free)");
}

TEST(Fit, RefusesACurveThatNeverPassesItsContactPoint) {
    FitProblem problem = hertz_problem();
    for (double& depth : problem.curves[0].depth) depth -= 1.0;  // all below the fixed contact point 0
    EXPECT_EQ(message_of([&] { fit(problem); }),
              "fit.data[0] = hertz: the curve never makes contact: no depth passes its contact point 0");
}

TEST(Fit, RecoversTheModulusOfTheHertzCurve) {  // the rules above leave a sound fit alone
    const FitResult result = fit(hertz_problem());
    EXPECT_TRUE(result.converged) << result.status;
    EXPECT_NEAR(result.values[0], 2e5, 2e5 * 1e-6);
}

// A C++ caller's FreeParameter with its coordinate unset takes the rule of a case's keys (fitted_on_logarithm);
// set, the caller's choice. Before, `logarithmic` defaulted to true: every caller's parameter went on its logarithm.
TEST(FreeParameterCoordinate, UnsetIsTheRuleSetIsTheCallersChoice) {
    const FreeParameter modulus{.name = "material.G", .start = 1e5, .lower = 1e3, .upper = 1e7};
    const FreeParameter from_zero{.name = "material.G", .start = 1e5, .lower = 0.0, .upper = 1e7};
    const FreeParameter exponent{.name = "material.beta", .start = 0.01, .lower = 1e-6, .upper = 0.99,
                                 .domain_upper = 1.0};
    EXPECT_TRUE(on_logarithm(modulus));
    EXPECT_FALSE(on_logarithm(from_zero));
    EXPECT_FALSE(on_logarithm(exponent));
    for (FreeParameter parameter : {modulus, from_zero, exponent}) {
        parameter.logarithmic = true;
        EXPECT_TRUE(on_logarithm(parameter)) << parameter.name;
        parameter.logarithmic = false;
        EXPECT_FALSE(on_logarithm(parameter)) << parameter.name;
    }
}

// A lower bound 0 with the coordinate unset is fitted linearly (before: refused, "must be > 0"), and the Hertz
// curve's closed-form modulus is recovered; asked for on its logarithm, it is refused, naming the key. The caller's
// own parameter: the modulus's excess over 1e5 Pa (>= 0; G itself must be > 0 at every bound).
TEST(FreeParameterCoordinate, ALowerBoundZeroIsFittedLinearlyUnlessTheLogarithmIsAsked) {
    FitProblem problem = hertz_problem();
    problem.model = [hertz = problem.model](const std::vector<double>& values) { return hertz({1e5 + values[0]}); };
    problem.parameters = {{.name = "G_excess", .start = 5e4, .lower = 0.0, .upper = 1e7}};
    const FitResult result = fit(problem);
    EXPECT_TRUE(result.converged) << result.status;
    EXPECT_NEAR(result.values[0], 1e5, 2e5 * 1e-6);  // G = 2e5
    EXPECT_EQ(result.interval_scales, std::vector<std::string>{"linear"});
    problem.parameters[0].logarithmic = true;
    EXPECT_EQ(message_of([&] { fit(problem); }),
              "fit.bounds.G_excess = 0: must be > 0 (the parameter is fitted on its logarithm)");
}

// NaN marks an undetermined parameter's error, interval, correlation and band limits; every other number must be
// finite (a force of 1e308 once gave "converged" with RMS inf and nulls in fit.json).
TEST(FitResultCheck, RefusesNonFiniteValuesButNotUndeterminedErrors) {
    FitResult result;
    result.names = {"material.G"};
    result.values = {2e5};
    result.standard_errors = {std::nan("")};
    result.lower_95 = result.upper_95 = {std::nan("")};
    result.material.times = {1.0};
    result.material.relaxation = {{2e5}, {std::nan("")}, {std::nan("")}};
    result.material.creep = {{5e-6}, {std::nan("")}, {std::nan("")}};
    EXPECT_EQ(message_of([&] { require_finite_result(result); }), "");
    result.material.creep.value = {std::numeric_limits<double>::infinity()};
    EXPECT_EQ(message_of([&] { require_finite_result(result); }),
              "the fit's result is not finite (J = inf at row 1): the input lies outside what double precision can "
              "represent in this problem");
    result.material.creep.value = {5e-6};
    result.rms_residual = std::numeric_limits<double>::infinity();
    EXPECT_NE(message_of([&] { require_finite_result(result); }).find("(rms_residual = inf)"), std::string::npos);
    result.rms_residual = 1.0;
    result.curves.push_back(CurveFit{.name = "c", .time = {0.0, 1.0}, .measured = {0.0, 1.0},
                                     .model = {0.0, std::nan("")}, .drive = {0.0, 1.0}});
    EXPECT_NE(message_of([&] { require_finite_result(result); }).find("(curve c: model = nan at row 2)"),
              std::string::npos);
}

// A subnormal modulus or viscosity (eta = 5e-320) once failed deep inside ("a characteristic rate overflows",
// exit 1) or gave J = inf as a result (G1 = 5e-324): refused where positive values are checked, naming the key.
TEST(RequirePositive, RefusesSubnormalValues) {
    const std::string rule =
        ": must be > 0 and at least 2.2250738585072014e-308, the smallest normal double (a subnormal value has lost "
        "its precision)";
    EXPECT_EQ(message_of([] { require_positive("eta", 5e-320); }), "eta = 5e-320" + rule);
    EXPECT_EQ(message_of([] { rheology::Rheology::standard(5e4, 5e-324, 0.5); }), "G1 = 5e-324" + rule);
    EXPECT_EQ(message_of([] { require_positive("eta", std::numeric_limits<double>::min()); }), "");
    EXPECT_EQ(message_of([] { require_non_negative("G_inf", 0.0); }), "");
    EXPECT_NE(message_of([] { require_non_negative("G_inf", 1e-310); }).find("G_inf = 1e-310: must be 0 or > 0 and at "
                                                                             "least 2.2250738585072014e-308"),
              std::string::npos);
}

}  // namespace
}  // namespace mdr::fit
