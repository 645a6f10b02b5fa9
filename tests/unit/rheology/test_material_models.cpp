// The registry of material models (issue 9): one row per model, unique names and keys, and the factories
// reproduce the direct constructors of Table 1.

#include <gtest/gtest.h>

#include <set>

#include "mdr/error.hpp"
#include "mdr/rheology/material_models.hpp"

namespace mdr::rheology {
namespace {

TEST(MaterialModels, NamesAndKeysAreUniqueAndDocumented) {
    std::set<std::string> names;
    for (const MaterialModel& model : material_models()) {
        EXPECT_TRUE(names.insert(model.name).second) << model.name;
        EXPECT_FALSE(model.documentation.empty()) << model.name;
        EXPECT_NE(model.build, nullptr) << model.name;
        std::set<std::string> keys;
        for (const auto& parameter : model.parameters) {
            EXPECT_TRUE(keys.insert(parameter.key).second) << model.name << "." << parameter.key;
            EXPECT_FALSE(parameter.unit.empty() || parameter.documentation.empty()) << parameter.key;
        }
    }
    for (const char* spec_name : {"elastic", "viscous", "kelvin_voigt", "maxwell", "standard", "prony", "power_law"}) {
        EXPECT_TRUE(names.contains(spec_name)) << spec_name;
    }
}

TEST(MaterialModels, FactoriesGiveTheTable1Materials) {
    ModelParameters p;
    p.numbers = {{"G_inf", 1e6}, {"G1", 2e6}, {"tau1", 0.1}};
    const Rheology built = build_material(material_model("standard"), p).series;
    const Rheology direct = Rheology::standard(1e6, 2e6, 0.1);
    for (double t : {0.0, 0.05, 1.0}) {
        EXPECT_EQ(built.relaxation(t), direct.relaxation(t));
        EXPECT_EQ(built.creep(t), direct.creep(t));
    }
    ModelParameters prony;
    prony.numbers = {{"G_inf", 1.0}};
    prony.pairs = {{"terms", {{2.0, 0.5}, {3.0, 5.0}}}};
    EXPECT_EQ(build_material(material_model("prony"), prony).series.terms().size(), 2u);
    EXPECT_EQ(describe_model(material_model("standard"), p), "standard (G_inf = 1000000 Pa, G1 = 2000000 Pa, tau1 = 0.1 s)");
}

TEST(MaterialModels, ErrorsNameTheKey) {
    try {
        material_model("kelvin");
        FAIL();
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "model");
        EXPECT_NE(error.rule().find("power_law"), std::string::npos) << error.rule();
    }
    ModelParameters p;
    p.numbers = {{"G_inf", 1e6}, {"tau1", 0.1}};
    EXPECT_THROW(build_material(material_model("standard"), p), InvalidInput);
    ModelParameters power;
    power.numbers = {{"G0", 1e3}, {"beta", 0.3}};
    try {
        build_material(material_model("power_law"), power);  // no window
        FAIL();
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "window");
    }
    const ModelMaterial built = build_material(material_model("power_law"), power, {TimeWindow{1e-3, 1.0}});
    ASSERT_TRUE(built.origin.certificate.has_value());
    EXPECT_EQ(built.origin.description, "power_law (G0 = 1000 Pa, beta = 0.3, t0 = 1 s)");  // t0 by default
}

}  // namespace
}  // namespace mdr::rheology
