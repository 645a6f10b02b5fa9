// The depth flags of fit/plausibility (issue 24, units cannot slip): every indenter's largest indentation and its
// contact radius lie within 0.1 nm to 10 cm, a sphere's depth within 1e-4 R to R. The contact radii expected are the
// closed forms of the shapes: a cone's a = 2 d / (pi tan(theta)) (eq. 24, 25), a flat punch's its radius.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "mdr/fit/plausibility.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::fit {
namespace {

const PlausibilityUnits si{};
const PlausibilityUnits micrometres{"µm", "kPa", 1e-6, 1e-9};  // um-nN-s

// A fit problem's model: an elastic body under `indenter` (the flags read the indenter only).
ModelBuilder model_on(std::shared_ptr<const profile::Profile> indenter) {
    return [indenter](const std::vector<double>&) {
        return drivers::ContactCase{.title = "plausibility",
                                    .material = rheology::Rheology::elastic(1e3),
                                    .indenter = indenter,
                                    .load = {.history = drivers::LoadHistory({{0.0, 0.0}, {1.0, 0.0}}, "load.history")},
                                    .end_time = 1.0};
    };
}

// The curve flags of one curve pressed `depth` deep (from contact at 0) by `indenter`, in `units`.
std::vector<std::string> depth_flags(std::shared_ptr<const profile::Profile> indenter, double depth,
                                     const PlausibilityUnits& units = si) {
    FitProblem problem;
    problem.model = model_on(indenter);
    Curve curve;
    curve.depth = {-0.5 * depth, 0.0, depth};
    problem.curves = {curve};
    FitResult result;
    result.curves.resize(1);
    result.curves[0].drive = {0.0, 0.0, depth};
    result.curves[0].contact_depth = 0.0;
    add_plausibility_flags(problem, units, result);
    return result.curves[0].flags;
}

TEST(Plausibility, ACurveOnAConeIsHeldToTheLengthsOfContacts) {
    std::shared_ptr<const profile::Profile> cone = profile::make_cone_from_half_angle(35.0);
    EXPECT_TRUE(depth_flags(cone, 3e-6).empty());  // an AFM indentation
    EXPECT_TRUE(depth_flags(cone, 1e-9).empty());
    EXPECT_TRUE(depth_flags(cone, greatest_contact_length_m).empty());  // the ends belong to the range
    const auto shallow = depth_flags(cone, 3e-12);  // 3 um of a file in metres, read as um and converted
    ASSERT_EQ(shallow.size(), 1u);
    EXPECT_EQ(shallow[0].rfind("largest indentation 3e-12 m (3e-12 m) is outside the lengths of indentation contacts "
                               "(1e-10 m to 0.1 m",
                               0),
              0u)
        << shallow[0];
    EXPECT_NE(shallow[0].find("units.length"), std::string::npos);
    ASSERT_EQ(depth_flags(cone, 3.0).size(), 1u);  // 3 um read as 3 m
}

TEST(Plausibility, TheRuleIsInTheCasesLengthUnit) {
    std::shared_ptr<const profile::Profile> cone = profile::make_cone_from_half_angle(35.0);
    EXPECT_TRUE(depth_flags(cone, 3.0, micrometres).empty());
    const auto flags = depth_flags(cone, 3e-6, micrometres);
    ASSERT_EQ(flags.size(), 1u);
    EXPECT_EQ(flags[0].rfind("largest indentation 3e-06 µm (3e-12 m) is outside", 0), 0u) << flags[0];
}

TEST(Plausibility, ABluntConesContactRadiusIsHeldToo) {
    // Slope 0.01 deg: a = 2 d / (pi tan(theta)) = 3648 d (eq. 24, 25). 10 um deep: a = 3.6 cm; 100 um: 36 cm.
    std::shared_ptr<const profile::Profile> cone = profile::make_cone(0.01);
    const double per_depth = 2.0 / (std::numbers::pi * std::tan(0.01 * std::numbers::pi / 180.0));
    ASSERT_LT(1e-5 * per_depth, greatest_contact_length_m);
    ASSERT_GT(1e-4 * per_depth, greatest_contact_length_m);
    EXPECT_TRUE(depth_flags(cone, 1e-5).empty());
    const auto flags = depth_flags(cone, 1e-4);
    ASSERT_EQ(flags.size(), 1u);
    EXPECT_EQ(flags[0].rfind("the contact radius 0.365 m (0.365 m) at the largest indentation 0.0001 m is outside", 0),
              0u)
        << flags[0];
    EXPECT_NE(flags[0].find("[indenter]"), std::string::npos);
}

TEST(Plausibility, AFlatPunchsRadiusIsItsContactRadius) {
    EXPECT_TRUE(depth_flags(profile::make_flat_punch(2e-6), 3e-7).empty());
    EXPECT_TRUE(depth_flags(profile::make_flat_punch(greatest_contact_length_m), least_contact_length_m).empty());
    EXPECT_TRUE(depth_flags(profile::make_flat_punch(least_contact_length_m), 1e-9).empty());
    const auto flags = depth_flags(profile::make_flat_punch(2e-12), 3e-7);  // metres written in a um-nN-s case
    ASSERT_EQ(flags.size(), 1u);
    EXPECT_EQ(flags[0].rfind("the contact radius 2e-12 m (2e-12 m) at the largest indentation 3e-07 m", 0), 0u)
        << flags[0];
}

TEST(Plausibility, ASphereIsHeldToItsRadiusWithOneFlag) {
    std::shared_ptr<const profile::Profile> sphere = profile::make_sphere(5e-6);
    EXPECT_TRUE(depth_flags(sphere, 3e-6).empty());
    const auto shallow = depth_flags(sphere, 3e-12);  // below 1e-4 R and below 0.1 nm: the sphere's flag alone
    ASSERT_EQ(shallow.size(), 1u);
    EXPECT_EQ(shallow[0].rfind("largest indentation 3e-12 m is below 0.0001 of the sphere's R", 0), 0u) << shallow[0];
    const auto deep = depth_flags(sphere, 6e-6);
    ASSERT_EQ(deep.size(), 1u);
    EXPECT_NE(deep[0].find("exceeds the sphere's R"), std::string::npos) << deep[0];
}

// The flags of a start value `start` [Pa] of material.G on `indenter` (one curve, an AFM indentation of 1 um).
std::vector<std::string> modulus_flags(std::shared_ptr<const profile::Profile> indenter, double start) {
    FitProblem problem;
    problem.model = model_on(indenter);
    problem.parameters = {{.name = "material.G", .start = start, .lower = 1e-6 * start, .upper = 1e6 * start}};
    Curve curve;
    curve.depth = {0.0, 1e-6};
    problem.curves = {curve};
    FitResult result;
    result.names = {"material.G"};
    result.values = {1e3};
    result.curves.resize(1);
    result.curves[0].drive = curve.depth;
    add_plausibility_flags(problem, si, result);
    return result.flags;
}

// On a power-law probe f = c r^n the force sets G (kappa_n c)^(-1/n) alone (a stand-in c scales every modulus), so
// a modulus out of the materials' range asks for c first; on any other indenter for the units only.
TEST(Plausibility, AModulusOnAPowerLawProbeAsksForItsScale) {
    const auto power = modulus_flags(profile::make_power_law(5e4, 3.9), 0.0233);
    ASSERT_EQ(power.size(), 1u);
    EXPECT_EQ(power[0].rfind("material.G: the start value 0.0233 Pa (0.0233 Pa) is outside the moduli of materials", 0),
              0u)
        << power[0];
    EXPECT_NE(power[0].find("power-law probe (indenter.c = 5e+04, n = 3.9)"), std::string::npos) << power[0];
    EXPECT_NE(power[0].find("those of the case?"), std::string::npos) << power[0];
    const auto sphere = modulus_flags(profile::make_sphere(5e-6), 0.0233);
    ASSERT_EQ(sphere.size(), 1u);
    EXPECT_EQ(sphere[0].find("indenter.c"), std::string::npos) << sphere[0];
    EXPECT_NE(sphere[0].find("are the data's units those of the case?"), std::string::npos) << sphere[0];
    EXPECT_TRUE(modulus_flags(profile::make_power_law(5e4, 3.9), 300.0).empty());
}

}  // namespace
}  // namespace mdr::fit
