// io::free_key_unit: the unit of a fit's free key from the registry of its model or shape. The expectations are
// the physics of each key (a relaxation time is a time, a springpot's quasi-property is Pa s^alpha), as the
// handbook's Table 1 states them.
#include "mdr/io/free_key_units.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace mdr::io {
namespace {

CaseTemplate case_of(const char* text) { return CaseTemplate(text, "case.toml"); }

TEST(FreeKeyUnit, PronyTermsTakeTheUnitOfTheirPlaceInThePair) {
    const auto model = case_of(R"(
[material]
model = "prony"
G_inf = 100.0
terms = [[200.0, 0.5], [300.0, 5.0]]
[indenter]
shape = "sphere"
R = 1e-5
)");
    EXPECT_EQ(free_key_unit(model, "material.G_inf"), "Pa");
    EXPECT_EQ(free_key_unit(model, "material.terms[0][0]"), "Pa");
    EXPECT_EQ(free_key_unit(model, "material.terms[1][1]"), "s");
    EXPECT_EQ(free_key_unit(model, "indenter.R"), "m");
}

TEST(FreeKeyUnit, PowerLawSpringpotConeAndBulkTables) {
    const auto model = case_of(R"(
[material]
model = "power_law"
G0 = 1000.0
beta = 0.2
[material.bulk]
model = "standard"
K_inf = 1e4
K1 = 1e4
tau1 = 0.1
[indenter]
shape = "cone"
half_angle_deg = 35.0
[indenter.material]
model = "springpot"
c = 10.0
alpha = 0.3
)");
    EXPECT_EQ(free_key_unit(model, "material.G0"), "Pa");
    EXPECT_EQ(free_key_unit(model, "material.beta"), "1");
    EXPECT_EQ(free_key_unit(model, "material.bulk.K_inf"), "Pa");  // K stands for the registry's G
    EXPECT_EQ(free_key_unit(model, "material.bulk.tau1"), "s");
    EXPECT_EQ(free_key_unit(model, "indenter.half_angle_deg"), "deg");
    EXPECT_EQ(free_key_unit(model, "indenter.material.c"), "Pa s^alpha");
    EXPECT_EQ(free_key_unit(model, "indenter.material.alpha"), "1");
}

TEST(FreeKeyUnit, AKeyNoRegistryDefinesHasNoUnit) {
    const auto model = case_of(R"(
[material]
model = "elastic"
G = 1000.0
K = 5000.0
[indenter]
shape = "sphere"
R = 1e-5
)");
    EXPECT_EQ(free_key_unit(model, "material.K"), "");
    EXPECT_EQ(free_key_unit(model, "material.G"), "Pa");
}

// free_key_upper_limit: the open upper end of each key's physical domain, as the handbook states it: a power law's
// beta and a springpot's alpha in (0, 1), a cone's angles in (0, 90) degrees, moduli, times and lengths > 0 only.
TEST(FreeKeyUpperLimit, ExponentsAndAnglesAreBoundedMostKeysAreNot) {
    const auto model = case_of(R"(
[material]
model = "power_law"
G0 = 1000.0
beta = 0.2
[indenter]
shape = "cone"
half_angle_deg = 35.0
[indenter.material]
model = "springpot"
c = 10.0
alpha = 0.3
)");
    const double unbounded = std::numeric_limits<double>::infinity();
    EXPECT_EQ(free_key_upper_limit(model, "material.beta"), 1.0);
    EXPECT_EQ(free_key_upper_limit(model, "indenter.material.alpha"), 1.0);
    EXPECT_EQ(free_key_upper_limit(model, "indenter.half_angle_deg"), 90.0);
    EXPECT_EQ(free_key_upper_limit(model, "material.G0"), unbounded);
    EXPECT_EQ(free_key_upper_limit(model, "indenter.material.c"), unbounded);
    EXPECT_EQ(free_key_upper_limit(model, "material.K"), unbounded);  // no registry defines it
}

}  // namespace
}  // namespace mdr::io
