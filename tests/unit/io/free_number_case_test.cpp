// FreeNumberCase: a case built once whose free numbers rebuild only what they touch, typed. The expectation is the
// rule the class states: the case a copy of the template with each key set builds (CaseTemplate::build, the case
// reader) — the same material, indenter and layer, and the same message for a value that breaks a rule.
#include "mdr/io/free_number_case.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/case_template.hpp"

namespace {

using mdr::io::CaseTemplate;
using mdr::io::FreeNumberCase;

constexpr const char* load = R"(
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-6]]
)";

// A compressible Prony half-space under a sphere that is itself an elastic body.
const std::string two_bodies = std::string(R"(
[material]
model = "prony"
G_inf = 1000
terms = [[2000.0, 0.1], [1000.0, 1.0]]
[material.bulk]
model = "standard"
K_inf = 5000
K1 = 3000
tau1 = 0.5
[indenter]
shape = "sphere"
R = 1e-5
[indenter.material]
model = "elastic"
G = 1e6
K = 3e6
)") + load;

// A compressible power law (converted to a series over the case's window) under a cone.
const std::string power_law = std::string(R"(
[material]
model = "power_law"
G0 = 1000
t0 = 1
beta = 0.2
K = 1e5
[indenter]
shape = "cone"
half_angle_deg = 70
)") + load;

// A compressible elastic layer under a sphere.
const std::string layer = std::string(R"(
[material]
model = "elastic"
G = 1000
K = 5000
[indenter]
shape = "sphere"
R = 1e-5
[layer]
thickness = 2e-5
interface = "bonded"
)") + load;

CaseTemplate with_values(const std::string& text, const std::vector<std::string>& keys,
                         const std::vector<double>& values) {
    CaseTemplate model(text, "case");
    for (std::size_t j = 0; j < keys.size(); ++j) model.set_number(keys[j], values[j]);
    return model;
}

// The typed build against the template's: the material's series, the indenter, the layer, the description.
void expect_as_template(const std::string& text, const std::vector<std::string>& keys,
                        const std::vector<double>& values) {
    const FreeNumberCase free(CaseTemplate(text, "case"), keys);
    ASSERT_TRUE(free.typed());
    const auto typed = free.build(values);
    const auto expected = with_values(text, keys, values).build();
    EXPECT_EQ(typed.material.equilibrium_modulus(), expected.material.equilibrium_modulus());
    EXPECT_EQ(typed.material.viscosity(), expected.material.viscosity());
    ASSERT_EQ(typed.material.terms().size(), expected.material.terms().size());
    for (std::size_t k = 0; k < typed.material.terms().size(); ++k) {
        EXPECT_EQ(typed.material.terms()[k].modulus, expected.material.terms()[k].modulus) << k;
        EXPECT_EQ(typed.material.terms()[k].relaxation_time, expected.material.terms()[k].relaxation_time) << k;
    }
    EXPECT_EQ(typed.shear_material.has_value(), expected.shear_material.has_value());
    EXPECT_EQ(typed.bulk_material.has_value(), expected.bulk_material.has_value());
    EXPECT_EQ(typed.tangential_exact, expected.tangential_exact);
    EXPECT_EQ(typed.indenter->definition(), expected.indenter->definition());
    EXPECT_EQ(typed.layer.has_value(), expected.layer.has_value());
    if (typed.layer) {
        EXPECT_EQ(typed.layer->thickness, expected.layer->thickness);
    }
    EXPECT_EQ(mdr::io::describe(typed), mdr::io::describe(expected));
}

std::string message_of(const auto& build) {
    try {
        static_cast<void>(build());
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "(built)";
}

TEST(FreeNumberCase, TypedBuildIsTheTemplatesCase) {
    expect_as_template(two_bodies, {"material.G_inf", "material.terms[1][1]", "material.bulk.K1", "indenter.R"},
                       {1500.0, 2.5, 4000.0, 2e-5});
    expect_as_template(two_bodies, {"indenter.material.G", "indenter.material.K", "material.terms[0][0]"},
                       {2e6, 5e6, 2500.0});
    expect_as_template(power_law, {"material.G0", "material.beta", "material.K", "indenter.half_angle_deg"},
                       {1200.0, 0.3, 2e5, 65.0});
    expect_as_template(layer, {"material.G", "material.K", "layer.thickness", "indenter.R"}, {1500.0, 2e4, 5e-5, 3e-5});
    // The values as given: a typed build sets exactly them.
    const FreeNumberCase free(CaseTemplate(layer, "case"), {"layer.thickness", "indenter.R"});
    const auto built = free.build({3e-5, 2e-5});
    EXPECT_EQ(built.layer->thickness, 3e-5);
    EXPECT_EQ(built.indenter->definition().numbers.at("R"), 2e-5);
}

TEST(FreeNumberCase, RefusesAValueWithTheTemplatesMessage) {
    struct Bad {
        std::string text;
        std::string key;
        double value;
    };
    const std::vector<Bad> bad{{two_bodies, "material.terms[1][1]", -1.0},
                               {two_bodies, "material.bulk.K1", -2.0},
                               {two_bodies, "indenter.R", 0.0},
                               {two_bodies, "indenter.material.K", -3e6},
                               {power_law, "material.beta", 1.5},
                               {power_law, "material.K", 0.0},
                               {power_law, "indenter.half_angle_deg", 95.0},
                               {layer, "layer.thickness", -1e-5},
                               {layer, "material.G", -1.0}};
    for (const auto& [text, key, value] : bad) {
        const FreeNumberCase free(CaseTemplate(text, "case"), {key});
        ASSERT_TRUE(free.typed()) << key;
        const std::string expected = message_of([&] { return with_values(text, {key}, {value}).build(); });
        EXPECT_NE(expected, "(built)") << key;
        EXPECT_EQ(message_of([&] { return free.build({value}); }), expected) << key;
    }
}

// With several values that break rules, the one the case reader meets first is reported: a body's K when read,
// the indenter, then the bodies when built (the indenter's own first), then the layer.
TEST(FreeNumberCase, ReportsTheRuleTheReaderMeetsFirst) {
    struct Bad {
        std::string text;
        std::vector<std::string> keys;
        std::vector<double> values;
        std::string first_key;
    };
    const std::vector<Bad> bad{
        {two_bodies, {"material.terms[1][1]", "indenter.R"}, {-1.0, 0.0}, "indenter.R"},
        {two_bodies, {"indenter.material.G", "material.G_inf"}, {-1.0, -1.0}, "indenter.material.G"},
        {two_bodies, {"indenter.material.K", "indenter.R"}, {-1.0, -1.0}, "indenter.R"},
        {power_law, {"indenter.half_angle_deg", "material.K"}, {95.0, -1.0}, "material.K"},
        {layer, {"layer.thickness", "material.G"}, {0.0, -1.0}, "material.G"},
    };
    for (const auto& [text, keys, values, first_key] : bad) {
        const FreeNumberCase free(CaseTemplate(text, "case"), keys);
        const std::string expected = message_of([&] { return with_values(text, keys, values).build(); });
        EXPECT_EQ(expected.rfind(first_key + " = ", 0), 0u) << expected;
        EXPECT_EQ(message_of([&] { return free.build(values); }), expected) << first_key;
    }
}

TEST(FreeNumberCase, OtherKeysGoThroughTheTemplate) {
    const std::string impact = R"(
[material]
model = "elastic"
G = 1e6
[indenter]
shape = "sphere"
R = 1e-3
mass = 1e-3
[load]
control = "impact"
velocity = 0.1
end = 1e-3
[numerics]
time_step = 1e-6
)";
    const FreeNumberCase free(CaseTemplate(impact, "case"), {"indenter.mass", "indenter.R"});
    EXPECT_FALSE(free.typed());
    const auto built = free.build({2e-3, 2e-3});
    EXPECT_EQ(std::get<mdr::drivers::ImpactControl>(built.control).mass, 2e-3);
    EXPECT_EQ(built.indenter->definition().numbers.at("R"), 2e-3);
    EXPECT_THROW(FreeNumberCase(CaseTemplate(impact, "case"), {"material.G2"}), mdr::InvalidInput);
}

}  // namespace
