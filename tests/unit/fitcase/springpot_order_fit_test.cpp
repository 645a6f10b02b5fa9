// A user's fit case with a free springpot order (the JPK relaxation record, examples/data/jpk_sr_cell1-0001.csv,
// started at alpha = 0.005): alpha is fitted linearly, by the rule of every key of a bounded domain
// (fit::fitted_on_logarithm, docs/performance.md "A case's exponent, fitted linearly"), not on its logarithm, where the
// Jacobian column alpha dr/dalpha vanishes near 0 and the steps ran to alpha's upper bound (as for the springpot
// candidate, springpot_candidate_test.cpp).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"

namespace mdr::fitcase {
namespace {

namespace fs = std::filesystem;

// examples/fit/jpk-relaxation-fractional.toml as a springpot from rest, default bounds, alpha started at 0.005.
FitCase jpk_springpot_case(const fs::path& data) {
    const std::string text = "[material]\nmodel = \"springpot\"\nc = 300.0\nalpha = 0.005\n"
                             "[indenter]\nshape = \"cone\"\nhalf_angle_deg = 35.0\n"
                             "[fit]\nfree = [\"material.c\", \"material.alpha\"]\n"
                             "[[fit.data]]\nfile = \"" + data.generic_string() + "\"\n"
                             "time = \"t_s\"\npiezo = \"z_measured_m\"\ndeflection = \"deflection_m\"\n"
                             "spring_constant = 1.0677\nsegment_column = \"segment\"\n"
                             "segments = [\"0\", \"1\", \"2\"]\nstart = \"at_rest\"\n";
    return parse_fit_case(text, "case", ".");
}

TEST(SpringpotOrderFit, StartedNearZeroReachesTheMinimumWithoutStalling) {
    const fs::path data = fs::path(MDR_MEASURED_DATA) / "jpk_sr_cell1-0001.csv";
    if (!fs::exists(data)) GTEST_SKIP() << "no " << data;
    const FitCase fit_case = jpk_springpot_case(data);
    const fit::FitResult result = fit::fit(make_problem(fit_case, load_curves(fit_case), {}));
    ASSERT_TRUE(result.converged) << result.status;
    // On ln(alpha) (before): 10 iterations, 69 model evaluations, 8.0 s CPU; linearly: 7, 37, 0.3 s.
    EXPECT_LE(result.evaluations, 50u) << result.iterations << " iterations";
    EXPECT_NEAR(result.values[1], 0.234885, 1e-5);  // the same minimum as on ln(alpha) from alpha = 0.5 (0.2348854)
}

TEST(SpringpotOrderFit, ACallersOrderWithItsCoordinateUnsetIsFittedLinearlyToo) {
    // The same fit with the free parameters a C++ caller of fit::fit builds, `logarithmic` unset (before: true,
    // the stall above), the case's default bounds and alpha's domain (0, 1).
    const fs::path data = fs::path(MDR_MEASURED_DATA) / "jpk_sr_cell1-0001.csv";
    if (!fs::exists(data)) GTEST_SKIP() << "no " << data;
    const FitCase fit_case = jpk_springpot_case(data);
    fit::FitProblem problem = make_problem(fit_case, load_curves(fit_case), {});
    problem.parameters = {
        {.name = "material.c", .start = 300.0, .lower = 0.03, .upper = 3e6},
        {.name = "material.alpha", .start = 0.005, .lower = 5e-7, .upper = 1.0 - 0.995e-4, .domain_upper = 1.0}};
    const fit::FitResult result = fit::fit(problem);
    ASSERT_TRUE(result.converged) << result.status;
    EXPECT_LE(result.evaluations, 50u) << result.iterations << " iterations";
    EXPECT_NEAR(result.values[1], 0.234885, 1e-5);
}

}  // namespace
}  // namespace mdr::fitcase
