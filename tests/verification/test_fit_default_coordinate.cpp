// A C++ caller's free exponent with its coordinate unset (FreeParameter::logarithmic) is fitted linearly, by the
// rule of a case's keys (fit::fitted_on_logarithm, docs/case-format.md "Coordinates"), not on its logarithm, where
// the Jacobian column alpha dr/dalpha vanishes as alpha -> 0 and a fit started near 0 takes several times the
// evaluations (docs/performance.md, "A case's exponent, fitted linearly"). Data from the closed form of a springpot
// under a sphere driven at constant speed (never from mdr; test_fit_interval_scale.cpp):
//   G(t) = c t^-alpha / Gamma(1 - alpha), h(t) = v t, incompressible (Lee-Radok):
//   F(t) = 8 sqrt(R) v^3/2 c Gamma(3/2) / Gamma(5/2 - alpha) t^(3/2 - alpha).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"
#include "power_law_ramp.hpp"

namespace mdr {
namespace {

constexpr double R = 1e-5;      // sphere radius [m]
constexpr double speed = 1e-6;  // v [m/s]
constexpr double c = 1e3;       // springpot quasi-property [Pa s^alpha]

// 31 rows of the noise-free ramp over 2 s for a springpot of order `alpha`.
fit::Curve springpot_ramp(double alpha) {
    fit::Curve curve;
    curve.name = "ramp";
    for (int i = 0; i <= 30; ++i) {
        const double t = 2.0 * i / 30.0;
        curve.time.push_back(t);
        curve.depth.push_back(speed * t);
        curve.force.push_back(testing::power_law_sphere_ramp_force(c / std::tgamma(1.0 - alpha), alpha, R, speed, t));
    }
    return curve;
}

TEST(FitDefaultCoordinate, ACallersExponentStartedNearZeroReachesTheMinimumWithoutStalling) {
    // The springpot's model from a case; its free parameters as a C++ caller builds them, the coordinate unset.
    const fitcase::FitCase fit_case = fitcase::parse_fit_case(
        "[material]\nmodel = \"springpot\"\nc = 1.0e3\nalpha = 0.5\n[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n"
        "[fit]\nfree = [\"material.c\", \"material.alpha\"]\ncontact_point = \"fixed\"\nbaseline = \"fixed\"\n",
        "case", ".");
    // Measured (evaluations on ln(alpha), before / linearly): truth 0.05 from 0.005: 91 / 19; 0.2 from 0.01: 57 / 19.
    for (const auto [truth, start] : {std::array{0.05, 0.005}, std::array{0.2, 0.01}}) {
        fit::FitProblem problem = fitcase::make_problem(fit_case, {springpot_ramp(truth)}, {});
        problem.parameters = {
            {.name = "material.c", .start = c, .lower = 1e-1, .upper = 1e7},
            {.name = "material.alpha", .start = start, .lower = 1e-6, .upper = 0.9999, .domain_upper = 1.0}};
        const fit::FitResult result = fit::fit(problem);
        ASSERT_TRUE(result.converged) << truth << ": " << result.status;
        EXPECT_LE(result.evaluations, 30u) << truth << ": " << result.iterations << " iterations";
        // The closed form's values, to the springpot series' own error (measured: 4.3e-6 and 9.3e-7 in alpha).
        EXPECT_NEAR(result.values[1], truth, 1e-5);
        EXPECT_NEAR(result.values[0] / c, 1.0, 1e-5);
        EXPECT_EQ(result.interval_scales, (std::vector<std::string>{"log", "logit"}));
    }
}

}  // namespace
}  // namespace mdr
