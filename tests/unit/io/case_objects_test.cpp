// CaseObjects: a case given as objects varied by a case file's keys. The expectation is the rule the class states:
// the case that the same case file with each key set builds (CaseTemplate::build, the case reader), and the same
// message for a value that breaks a rule; and the parts no key names are the objects given, untouched.
#include "mdr/io/case_objects.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/case_template.hpp"

namespace {

using mdr::io::CaseObjects;
using mdr::io::CaseTemplate;

// A standard half-space under a sphere that is itself an elastic body, with a harmonic and snapshots.
const std::string two_bodies = R"(
[material]
model = "standard"
G_inf = 1000
G1 = 2000
tau1 = 0.1
[indenter]
shape = "sphere"
R = 1e-5
[indenter.material]
model = "elastic"
G = 1e6
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-6], [2.0, 1.0e-6]]
harmonic = { amplitude = 1e-8, frequency = 2.0, start = 1.0, end = 2.0 }
[output]
snapshots = [0.5, 1.5]
[numerics]
elements = 200
time_step = 0.01
)";

// A compressible power law (converted to a series over the case's window) under a cone, force control.
const std::string power_law = R"(
[material]
model = "power_law"
G0 = 1000
beta = 0.2
K = 1e5
[indenter]
shape = "cone"
slope_deg = 20
[load]
control = "force"
history = [[0.0, 0.0], [1.0, 1.0e-7]]
end = 1.5
)";

mdr::drivers::ContactCase from_file(const std::string& text, const std::vector<std::string>& keys,
                                    const std::vector<double>& values) {
    CaseTemplate model(text, "case");
    for (std::size_t j = 0; j < keys.size(); ++j) model.set_number(keys[j], values[j]);
    return model.build();
}

void expect_same_series(const mdr::rheology::Rheology& a, const mdr::rheology::Rheology& b) {
    EXPECT_EQ(a.equilibrium_modulus(), b.equilibrium_modulus());
    EXPECT_EQ(a.viscosity(), b.viscosity());
    ASSERT_EQ(a.terms().size(), b.terms().size());
    for (std::size_t k = 0; k < a.terms().size(); ++k) {
        EXPECT_EQ(a.terms()[k].modulus, b.terms()[k].modulus) << k;
        EXPECT_EQ(a.terms()[k].relaxation_time, b.terms()[k].relaxation_time) << k;
    }
}

// The objects' build against the file's: the material, the indenter, the load, the numerics, the description.
void expect_as_file(const std::string& text, const std::vector<std::string>& keys, const std::vector<double>& values) {
    const CaseObjects objects(mdr::io::parse_case(text, "case"));
    for (const auto& key : keys) EXPECT_TRUE(objects.has_number(key)) << key;
    const auto built = objects.build(keys, values);
    const auto expected = from_file(text, keys, values);
    expect_same_series(built.material, expected.material);
    EXPECT_EQ(built.indenter->definition(), expected.indenter->definition());
    ASSERT_EQ(built.load.history->points().size(), expected.load.history->points().size());
    for (std::size_t i = 0; i < built.load.history->points().size(); ++i) {
        EXPECT_EQ(built.load.history->points()[i].time, expected.load.history->points()[i].time) << i;
        EXPECT_EQ(built.load.history->points()[i].value, expected.load.history->points()[i].value) << i;
    }
    EXPECT_EQ(built.end_time, expected.end_time);
    EXPECT_EQ(built.snapshots, expected.snapshots);
    EXPECT_EQ(built.numerics.elements, expected.numerics.elements);
    EXPECT_EQ(built.numerics.time_step, expected.numerics.time_step);
    EXPECT_EQ(mdr::io::describe(built), mdr::io::describe(expected));
}

std::string message_of(const auto& build) {
    try {
        static_cast<void>(build());
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "(built)";
}

TEST(CaseObjects, BuildIsTheFilesCase) {
    expect_as_file(two_bodies, {"material.G1", "indenter.R", "indenter.material.G"}, {2500.0, 2e-5, 2e6});
    expect_as_file(two_bodies, {"load.history[1][0]", "load.history[2][0]", "load.harmonic.frequency"},
                   {0.8, 2.5, 3.0});  // the default end follows the history
    expect_as_file(two_bodies, {"output.snapshots[1]", "numerics.elements", "numerics.time_step"},
                   {1.2, 400.0, 0.02});
    expect_as_file(power_law, {"material.beta", "material.G0", "indenter.slope_deg"}, {0.3, 1200.0, 25.0});
    expect_as_file(power_law, {"load.history[1][1]"}, {2e-7});  // not a time: the case's window stays
}

TEST(CaseObjects, PartsNotVariedAreTheObjectsGiven) {
    // A converted series given with its own certificate (here: the case's, from its file, over its window): a key
    // of another part keeps the series and the certificate, bit for bit.
    const auto base = mdr::io::parse_case(power_law, "case");
    const auto built = CaseObjects(base).build({"indenter.slope_deg"}, {30.0});
    expect_same_series(built.material, base.material);
    ASSERT_TRUE(built.material_origin.certificate.has_value());
    EXPECT_EQ(built.material_origin.certificate->error, base.material_origin.certificate->error);
    EXPECT_EQ(built.material_origin.certificate->window.shortest, base.material_origin.certificate->window.shortest);
    EXPECT_EQ(built.material_origin.certificate->window.longest, base.material_origin.certificate->window.longest);
}

TEST(CaseObjects, RefusesAValueWithTheFilesMessage) {
    struct Bad {
        std::string text;
        std::string key;
        double value;
    };
    const std::vector<Bad> bad{{two_bodies, "material.G1", -1.0},          {two_bodies, "indenter.R", 0.0},
                               {two_bodies, "indenter.material.G", -3.0},  {two_bodies, "load.history[1][0]", 3.0},
                               {two_bodies, "numerics.elements", 2.5},     {two_bodies, "numerics.elements", 0.0},
                               {power_law, "material.beta", 1.5},          {power_law, "load.history[1][1]", -1e-7}};
    for (const auto& [text, key, value] : bad) {
        const CaseObjects objects(mdr::io::parse_case(text, "case"));
        const std::string expected = message_of([&] { return from_file(text, {key}, {value}); });
        EXPECT_NE(expected, "(built)") << key;
        EXPECT_EQ(message_of([&] { return objects.build({key}, {value}); }), expected) << key;
    }
}

TEST(CaseObjects, KnowsTheNumbersOfItsParts) {
    const CaseObjects objects(mdr::io::parse_case(two_bodies, "case"));
    for (const std::string key : {"material.G_inf", "indenter.R", "load.history[2][1]", "load.harmonic.end",
                                  "output.snapshots[0]", "numerics.time_step", "indenter.material.G"}) {
        EXPECT_TRUE(objects.has_number(key)) << key;
    }
    for (const std::string key : {"material.nope", "material.tau9", "material.G_inf[0]", "indenter.r[0]",
                                  "load.history[3][0]", "load.history[0][2]", "load.history[x][0]", "load.end",
                                  "output.snapshots[2]", "numerics.half_width", "layer.thickness",
                                  "tangential.friction", "title", ""}) {
        EXPECT_FALSE(objects.has_number(key)) << key;
    }
}

}  // namespace
