// CaseTemplate: numbers read and set by dotted key (array elements by index), cases built without text.
#include "mdr/io/case_template.hpp"

#include <gtest/gtest.h>

#include "mdr/error.hpp"

namespace {

constexpr const char* case_text = R"(
[material]
model = "prony"
G_inf = 1000000
terms = [[2.0e6, 0.1], [1.0e6, 1.0]]
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4]]
[fit]
free = ["material.G_inf"]
)";

TEST(CaseTemplate, ReadsAndSetsNumbersByDottedKeyAndArrayIndex) {
    mdr::io::CaseTemplate model(case_text, "case");
    EXPECT_TRUE(model.has_table("fit"));
    EXPECT_FALSE(model.take_table("fit").empty());
    EXPECT_FALSE(model.has_table("fit"));
    EXPECT_EQ(model.number("material.G_inf"), 1e6);       // an integer in the file
    EXPECT_EQ(model.number("material.terms[1][1]"), 1.0);  // tau of the second term
    model.set_number("material.G_inf", 2.5e6);
    model.set_number("material.terms[1][1]", 3.0);
    model.set_number("load.history[1][1]", 2e-4);
    const auto built = model.build();
    EXPECT_EQ(built.material.equilibrium_modulus(), 2.5e6);
    EXPECT_EQ(built.material.terms()[1].relaxation_time, 3.0);
    EXPECT_EQ(built.load.history->points()[1].value, 2e-4);
    const mdr::io::CaseTemplate copy = model;  // independent copies
    model.set_number("material.G_inf", 1.0);
    EXPECT_EQ(copy.number("material.G_inf"), 2.5e6);
}

TEST(CaseTemplate, RefusesKeysThatNameNoNumber) {
    mdr::io::CaseTemplate model(case_text, "case");
    for (const char* key : {"material.G2", "material.terms[2][0]", "material.model", "load.history[1]", "x"}) {
        EXPECT_FALSE(model.has_number(key)) << key;
        EXPECT_THROW(model.set_number(key, 1.0), mdr::InvalidInput) << key;
    }
}

TEST(CaseTemplate, BuildAppliesTheCaseRules) {
    mdr::io::CaseTemplate model(case_text, "case");
    model.take_table("fit");
    model.set_number("material.G_inf", -1.0);
    try {
        model.build();
        FAIL();
    } catch (const mdr::InvalidInput& error) {
        EXPECT_NE(std::string(error.what()).find("material.G_inf"), std::string::npos) << error.what();
    }
}

}  // namespace
