// The registry of material models (issue 9): one row per model, unique names and keys, and the factories
// reproduce the direct constructors of Table 1.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

// The definition a built material keeps (what mdr.ContactCase's ConvertedMaterial reads back, issue 27): the row's
// name, the values as given (no defaults added), a windowed model's tolerance, and a table's file named absolutely
// from the case's directory, so that the model converts again from anywhere.
TEST(MaterialModels, ABuiltMaterialKeepsItsDefinition) {
    ModelParameters power;
    power.numbers = {{"G0", 1e3}, {"beta", 0.3}};
    const ModelMaterial built = build_material(material_model("power_law"), power, {TimeWindow{1e-3, 1.0}, 1e-5});
    ASSERT_TRUE(built.definition.has_value());
    EXPECT_EQ(built.definition->model, "power_law");
    EXPECT_EQ(built.definition->parameters.numbers, power.numbers);  // t0 not added
    EXPECT_EQ(built.definition->tolerance, 1e-5);

    const auto directory = std::filesystem::temp_directory_path() / "mdr_material_definition_test";
    std::filesystem::create_directories(directory);
    std::ofstream(directory / "master.csv") << "t,G\n0.01,3e6\n0.1,2e6\n1,1.2e6\n";
    ModelParameters table;
    table.texts = {{"file", "master.csv"}};
    const ModelMaterial from_file = build_material(material_model("table"), table, {{}, 1e-4, directory.string()});
    ASSERT_TRUE(from_file.definition.has_value());
    EXPECT_EQ(from_file.definition->parameters.texts.at("file"),
              std::filesystem::absolute(directory / "master.csv").string());
    EXPECT_FALSE(from_file.definition->tolerance.has_value());  // a table takes no tolerance
    std::filesystem::remove_all(directory);
}

// A series as its own model: no certificate, no definition, and times from a conversion only when it has no time at
// all (the default time step then ignores none of its times, resolve_numerics).
TEST(MaterialModels, AnExactMaterialHasTimesOfItsOwnUnlessElastic) {
    EXPECT_TRUE(exact_material(Rheology::elastic(1e6)).origin.times_from_conversion);
    EXPECT_FALSE(exact_material(Rheology::kelvin_voigt(1e6, 1e3)).origin.times_from_conversion);
    const ModelMaterial standard = exact_material(Rheology::standard(1e6, 2e6, 0.1));
    EXPECT_FALSE(standard.origin.times_from_conversion);
    EXPECT_FALSE(standard.origin.certificate.has_value() || standard.definition.has_value());
}

}  // namespace
}  // namespace mdr::rheology
