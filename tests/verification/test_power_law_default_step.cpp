// The default time step of a power law under displacement control (issue 12): its series' nodes (a continuous
// spectrum, one within a factor exp(h) above any step) no longer shorten the step to a fifth of a node, so a ramp
// takes default_steps; the Lee-Radok closed form of the ramp (test_power_law.cpp) is met as well as with four times
// as many steps. Under force control too, with steps graded after each fast load change.
//   Sphere ramp d = v t: F(t) = 8 sqrt(R) G0 t0^beta v^(3/2) Gamma(3/2) Gamma(1 - beta) / Gamma(5/2 - beta) t^(3/2 - beta)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/io/case_file.hpp"
#include "run_case.hpp"
#include "power_law_ramp.hpp"

namespace mdr {
namespace {

constexpr double G0 = 2.0e3, t0 = 0.5, R = 5e-6, v = 1e-6, duration = 2.0;

std::string ramp(double beta, const char* control, const std::string& numerics) {
    return fmt::format(R"(
[material]
model = "power_law"
G0 = {}
beta = {}
t0 = {}
[indenter]
shape = "sphere"
R = {}
[load]
control = "{}"
history = [[0.0, 0.0], [{}, {}]]
{}
)",
                       G0, beta, t0, R, control, duration, duration * v, numerics);
}

// The largest deviation of the force from the closed form over the written times, relative to the peak.
double ramp_error(const drivers::IndentationResult& result, double beta) {
    double peak = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < result.time.size(); ++i) {
        const double exact = testing::power_law_sphere_ramp_force(G0 * std::pow(t0, beta), beta, R, v, result.time[i]);
        peak = std::max(peak, exact);
        worst = std::max(worst, std::abs(result.force[i] - exact));
    }
    return worst / peak;
}

class PowerLawDefaultStep : public ::testing::TestWithParam<double> {};

TEST_P(PowerLawDefaultStep, DisplacementRampTakesTheDefaultStepsAtTheAccuracyOfFourTimesAsMany) {
    const double beta = GetParam();
    const auto coarse = testing::run_toml(ramp(beta, "displacement", ""));
    EXPECT_EQ(coarse.steps, drivers::default_steps);
    const auto fine = testing::run_toml(
        ramp(beta, "displacement", fmt::format("[numerics]\ntime_step = {}", duration / drivers::default_steps / 4.0)));
    const double coarse_error = ramp_error(coarse, beta), fine_error = ramp_error(fine, beta);
    RecordProperty("default_error", fmt::format("{:.2e}", coarse_error));
    RecordProperty("fine_error", fmt::format("{:.2e}", fine_error));
    EXPECT_LT(coarse_error, 1e-4) << "beta = " << beta;  // issue 12: 1e-4 at defaults
    // The error is the elements' (the contact edge) and the series', not the steps': four times the steps gain
    // less than 1% of the bound (measured: 6e-7 at beta = 0.05, 1e-7 at 0.2 and 0.5, none at 0.7).
    EXPECT_LT(coarse_error - fine_error, 1e-6) << "beta = " << beta;
}

INSTANTIATE_TEST_SUITE_P(Betas, PowerLawDefaultStep, ::testing::Values(0.05, 0.2, 0.5, 0.7));

TEST(PowerLawDefaultStepUnderForceControl, TakesTheDefaultStepGradedAfterTheStart) {
    // The creep after a load change is taken on graded steps (test_power_law_fast_force_step.cpp), not on a fifth
    // of a series node everywhere.
    const auto contact_case = io::parse_case(ramp(0.3, "force", ""));
    const auto numerics = drivers::resolve_numerics(contact_case);
    EXPECT_DOUBLE_EQ(numerics.time_step, duration / drivers::default_steps);
    EXPECT_EQ(numerics.grading_ratio, drivers::jump_grading_ratio);
    EXPECT_DOUBLE_EQ(numerics.first_graded_step, contact_case.material.shortest_time());
}

}  // namespace
}  // namespace mdr
