// The default bounds of a free key without fit.bounds (parse_fit_case): four decades either side of its start,
// within its physical domain. The expectations are the rule stated in src/fitcase/fit_case.cpp and the domains of the
// handbook (a power law's 0 < beta < 1, a cone's 0 < angle < 90 degrees, a modulus > 0).
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "mdr/fitcase/fit_case.hpp"

namespace mdr::fitcase {
namespace {

const fit::FreeParameter& parameter(const FitCase& fit_case, const std::string& key) {
    for (const auto& free : fit_case.parameters) {
        if (free.name == key) return free;
    }
    throw std::logic_error("no free key " + key);
}

TEST(FitCaseDefaultBounds, StayWithinThePhysicalDomainOfEachKey) {
    const FitCase fit_case = parse_fit_case(R"(
[material]
model = "power_law"
G0 = 1000.0
beta = 0.2
[indenter]
shape = "cone"
half_angle_deg = 35.0
[fit]
free = ["material.G0", "material.beta", "indenter.half_angle_deg"]
[[fit.data]]
file = "curve.csv"
time = "t"
depth = "d"
force = "F"
)",
                                            "case.toml", ".");
    const auto& modulus = parameter(fit_case, "material.G0");
    EXPECT_DOUBLE_EQ(modulus.lower, 0.1);  // 1e-4 G0
    EXPECT_DOUBLE_EQ(modulus.upper, 1e7);  // 1e4 G0: no upper end to its domain
    const auto& exponent = parameter(fit_case, "material.beta");
    EXPECT_DOUBLE_EQ(exponent.lower, 2e-5);              // 1e-4 of beta's distance to 0
    EXPECT_DOUBLE_EQ(exponent.upper, 1.0 - 0.8 * 1e-4);  // 1e-4 of its distance to 1 (before: 2000)
    const auto& angle = parameter(fit_case, "indenter.half_angle_deg");
    EXPECT_DOUBLE_EQ(angle.lower, 35.0e-4);
    EXPECT_DOUBLE_EQ(angle.upper, 90.0 - 55.0 * 1e-4);  // before: 3.5e5 degrees
}

TEST(FitCaseDefaultBounds, EachKeyCarriesTheUpperEndOfItsDomainForItsInterval) {
    // The domain (0, L) of each key's registry row, with or without fit.bounds: beta < 1, a cone's angle < 90
    // degrees, a modulus unbounded above (the 95 % interval's scale: logit on (0, L), else log).
    const FitCase fit_case = parse_fit_case(R"(
[material]
model = "power_law"
G0 = 1000.0
beta = 0.2
[indenter]
shape = "cone"
half_angle_deg = 35.0
[fit]
free = ["material.G0", "material.beta", "indenter.half_angle_deg"]
bounds = {"material.beta" = [0.01, 0.9]}
[[fit.data]]
file = "curve.csv"
time = "t"
depth = "d"
force = "F"
)",
                                            "case.toml", ".");
    EXPECT_EQ(parameter(fit_case, "material.G0").domain_upper, std::numeric_limits<double>::infinity());
    EXPECT_EQ(parameter(fit_case, "material.beta").domain_upper, 1.0);
    EXPECT_EQ(parameter(fit_case, "indenter.half_angle_deg").domain_upper, 90.0);
}

TEST(FitCaseDefaultBounds, AKeyOfABoundedDomainIsFittedLinearlyWithOrWithoutBounds) {
    // fit::fitted_on_logarithm, the rule of the candidates' keys too: a modulus on its logarithm; an exponent and a
    // cone's angle linearly, with default bounds (beta, the angle) or a user's bounds inside the domain (beta).
    for (const std::string bounds : {"", "bounds = {\"material.beta\" = [0.01, 0.9]}\n"}) {
        const FitCase fit_case = parse_fit_case(
            "[material]\nmodel = \"power_law\"\nG0 = 1000.0\nbeta = 0.2\n"
            "[indenter]\nshape = \"cone\"\nhalf_angle_deg = 35.0\n"
            "[fit]\nfree = [\"material.G0\", \"material.beta\", \"indenter.half_angle_deg\"]\n" + bounds +
                "[[fit.data]]\nfile = \"curve.csv\"\ntime = \"t\"\ndepth = \"d\"\nforce = \"F\"\n",
            "case.toml", ".");
        EXPECT_TRUE(fit::on_logarithm(parameter(fit_case, "material.G0"))) << bounds;
        EXPECT_FALSE(fit::on_logarithm(parameter(fit_case, "material.beta"))) << bounds;  // before: on ln(beta)
        EXPECT_FALSE(fit::on_logarithm(parameter(fit_case, "indenter.half_angle_deg"))) << bounds;
    }
}

}  // namespace
}  // namespace mdr::fitcase
