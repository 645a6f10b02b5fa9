// The registry of indenter shapes (profile/shapes.hpp): every row builds, a profile's definition builds it again,
// the default description names the row's keys, and bad definitions give `key = value: rule` with the registry's
// names. The case reader's side (indenter.* keys, the list of valid keys) is tested here too.

#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/profile/shapes.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using mdr::profile::ProfileDefinition;

template <class F>
std::string message_of(F&& make) {
    try {
        make();
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "no InvalidInput thrown";
}

// A definition of each row with values for its required keys (a cone by its slope).
ProfileDefinition example(const std::string& shape) {
    if (shape == "profile") return {"profile", {}, {{"r", {0.0, 1.0, 2.0}}, {"f", {0.0, 0.5, 2.0}}}};
    ProfileDefinition definition{shape};
    for (const auto& parameter : mdr::profile::shape_named(shape).parameters) {
        if (parameter.required && parameter.alternative_to.empty()) definition.numbers[parameter.key] = 1.5;
    }
    if (shape == "cone") definition.numbers["slope_deg"] = 20.0;
    return definition;
}

TEST(ShapeRegistry, EveryRowBuildsAndItsDefinitionBuildsItAgain) {
    ASSERT_EQ(mdr::profile::shapes().size(), 5u);
    for (const auto& shape : mdr::profile::shapes()) {
        SCOPED_TRACE(shape.name);
        EXPECT_FALSE(shape.documentation.empty());
        for (const auto& parameter : shape.parameters) EXPECT_FALSE(parameter.documentation.empty()) << parameter.key;
        const auto profile = mdr::profile::make_profile(example(shape.name));
        const ProfileDefinition definition = profile->definition();
        EXPECT_EQ(definition.shape, shape.name);
        const auto again = mdr::profile::make_profile(definition);
        EXPECT_EQ(again->describe(), profile->describe());
        for (const double x : {0.0, 0.3, 0.9, 1.4}) EXPECT_EQ(again->equivalent(x), profile->equivalent(x)) << x;
    }
}

TEST(ShapeRegistry, DescriptionNamesTheRowsKeysByDefault) {
    EXPECT_EQ(mdr::profile::make_profile({"sphere", {{"R", 0.01}}})->describe(), "sphere R = 0.01");
    EXPECT_EQ(mdr::profile::make_profile({"flat", {{"a", 0.001}}})->describe(), "flat punch a = 0.001");
    EXPECT_EQ(mdr::profile::describe_shape({"power", {{"n", 1.5}, {"c", 2.0}}}), "power law c = 2, n = 1.5");
    // The cone prints both of its angles (either may be the one given).
    EXPECT_EQ(mdr::profile::make_profile({"cone", {{"half_angle_deg", 70.3}}})->describe(),
              "cone slope_deg = 19.7 (half_angle_deg = 70.3)");
}

TEST(ShapeRegistry, TheConeTakesExactlyOneOfItsAngles) {
    const auto by_half_angle = mdr::profile::make_profile({"cone", {{"half_angle_deg", 60.0}}});
    const auto by_slope = mdr::profile::make_profile({"cone", {{"slope_deg", 30.0}}});
    EXPECT_NEAR(by_half_angle->equivalent(2.0), by_slope->equivalent(2.0), 1e-15 * by_slope->equivalent(2.0));
    const std::string rule = "give one of slope_deg (angle theta between flank and surface, 0 < theta < 90) or "
                             "half_angle_deg (angle between flank and axis, as tips are specified: 90 - theta)";
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"cone"}); }), "slope_deg = (missing): " + rule);
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"cone", {{"slope_deg", 30.0}, {"half_angle_deg", 60.0}}}); }),
              "slope_deg = given with half_angle_deg: " + rule);
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"cone", {{"half_angle_deg", 90.0}}}); }),
              "half_angle_deg = 90: must be < 90");
}

TEST(ShapeRegistry, BadDefinitionsNameTheKeyAndTheRule) {
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"ball", {{"R", 1.0}}}); }),
              "shape = \"ball\": unknown shape; one of sphere, cone, flat, power, profile");
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"sphere"}); }), "R = (missing): is required");
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"sphere", {{"R", 1.0}, {"a", 2.0}}}); }),
              "a = 2: unknown key for shape = \"sphere\"; valid keys: R");
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"sphere", {}, {{"R", {1.0}}}}); }),
              "R = [...]: must be a number");
    EXPECT_EQ(message_of([] { mdr::profile::make_profile({"profile", {}, {{"r", {0.0, 1.0}}}}); }),
              "f = (missing): is required");
    EXPECT_EQ(message_of([] {
                  mdr::profile::make_profile({"profile", {}, {{"r", {0.0, 1.0}}, {"f", {0.0, 1.0}}}, {{"interpolation", "spline"}}});
              }),
              "interpolation = \"spline\": must be monotone_cubic or linear");
    // An optional text takes its default: monotone cubics.
    const auto table = mdr::profile::make_profile({"profile", {}, {{"r", {0.0, 1.0}}, {"f", {0.0, 1.0}}}});
    EXPECT_EQ(table->definition().texts.at("interpolation"), "monotone_cubic");
}

TEST(InterpolationRegistry, EveryRowBuildsItsTableAndNamesItselfBack) {
    for (const auto& row : mdr::profile::interpolations()) {
        const auto table = mdr::profile::make_profile(
            {"profile", {}, {{"r", {0.0, 1.0, 2.0}}, {"f", {0.0, 1.0, 4.0}}}, {{"interpolation", row.name}}});
        EXPECT_EQ(table->definition().texts.at("interpolation"), row.name);
        EXPECT_EQ(mdr::profile::interpolation_kind(mdr::profile::interpolation_named(row.name)).name, row.name);
    }
    // The default is the first row, and the shape registry documents every row with its use.
    EXPECT_EQ(mdr::profile::interpolations().front().interpolation, mdr::profile::Interpolation::monotone_cubic);
    EXPECT_EQ(mdr::profile::interpolation_list(true),
              "monotone_cubic (smooth profiles) or linear (profiles with kinks)");
}

std::string case_with_indenter(const std::string& indenter) {
    return "[material]\nmodel = \"elastic\"\nG = 1e6\n[indenter]\n" + indenter +
           "[load]\ncontrol = \"displacement\"\nhistory = [[0.0, 0.0], [1.0, 1e-5]]\n";
}

TEST(ShapeRegistry, TheCaseReaderTakesKeysAndMessagesFromTheRow) {
    const auto parse = [](const std::string& indenter) {
        return [indenter] { mdr::io::parse_case(case_with_indenter(indenter)); };
    };
    EXPECT_EQ(message_of(parse("shape = \"ball\"\nR = 0.01\n")),
              "indenter.shape = \"ball\": unknown shape; one of sphere, cone, flat, power, profile");
    // Nothing close: every valid key of the shape (and of the indenter) is listed.
    EXPECT_EQ(message_of(parse("shape = \"power\"\nc = 1.0\nn = 2.0\nexponent = 2\n")),
              "indenter.exponent = 2: unknown key; valid keys: shape, mass, moment_of_inertia, material, c, n");
    EXPECT_EQ(message_of(parse("shape = \"sphere\"\nRR = 0.01\n")), "indenter.RR = 0.01: unknown key; did you mean 'R'?");
    EXPECT_EQ(message_of(parse("shape = \"flat\"\n")), "indenter.a = (missing): is required");
    EXPECT_EQ(message_of(parse("shape = \"cone\"\nhalf_angle_deg = -3\n")), "indenter.half_angle_deg = -3: must be > 0");
    EXPECT_EQ(message_of(parse("shape = \"profile\"\nr = [0.0, 1e-3]\nf = 1\n")),
              "indenter.f = 1: must be an array of numbers");
    const auto contact_case = mdr::io::parse_case(case_with_indenter("shape = \"profile\"\nr = [0.0, 1e-3]\nf = [0.0, 1e-6]\n"));
    EXPECT_EQ(contact_case.indenter->definition().texts.at("interpolation"), "monotone_cubic");
}

}  // namespace
