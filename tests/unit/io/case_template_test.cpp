// CaseTemplate: numbers read and set by dotted key (array elements by index), cases built without text.
#include "mdr/io/case_template.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <variant>

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

// A count (`numerics.elements`, read as an integer >= 1) takes a whole value as an integer, and refuses another with
// the reader's rule; a value set on an integer key that is not whole becomes a float.
TEST(CaseTemplate, SetsAWholeNumberOnAnIntegerKeyAsAnInteger) {
    mdr::io::CaseTemplate model(std::string(case_text) + "[numerics]\nelements = 300\n", "case");
    model.take_table("fit");
    model.set_number("numerics.elements", 600.0);
    EXPECT_EQ(model.build().numerics.elements, std::size_t{600});
    model.set_number("material.G_inf", 1.5e6);  // an integer in the file, a float now
    EXPECT_EQ(model.build().material.equilibrium_modulus(), 1.5e6);
    model.set_number("numerics.elements", 2.5);
    try {
        model.build();
        FAIL();
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(std::string(error.what()), "numerics.elements = 2.5: must be an integer >= 1");
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

// The same case given as a tree of values (io::CaseValue, what the Python bindings build from dicts): the same
// numbers by key, the same text, and the readers' messages naming the same keys.
TEST(CaseTemplate, ATreeIsTheSameCaseAsItsText) {
    using mdr::io::CaseArray;
    using mdr::io::CaseTable;
    using mdr::io::CaseValue;
    const auto pair = [](double a, double b) { return CaseValue{CaseArray{{a}, {b}}}; };
    CaseTable root{
        {"material", {CaseTable{{"model", {std::string("prony")}},
                                {"G_inf", {std::int64_t{1000000}}},
                                {"terms", {CaseArray{pair(2.0e6, 0.1), pair(1.0e6, 1.0)}}}}}},
        {"indenter", {CaseTable{{"shape", {std::string("sphere")}}, {"R", {0.01}}}}},
        {"load", {CaseTable{{"control", {std::string("displacement")}},
                            {"history", {CaseArray{pair(0.0, 0.0), pair(1.0, 1.0e-4)}}}}}},
        {"fit", {CaseTable{{"free", {CaseArray{{std::string("material.G_inf")}}}}}}},
    };
    const mdr::io::CaseTemplate from_tree(root, "tree");
    const mdr::io::CaseTemplate from_text(case_text, "case");
    EXPECT_EQ(from_tree.text(), from_text.text());
    EXPECT_EQ(from_tree.number("material.terms[1][1]"), 1.0);
    EXPECT_EQ(from_tree.source(), "tree");
    root.pop_back();                                                // without [fit]: a contact case
    std::get<CaseTable>(root[0].second.value)[1].second = {-1.0};  // material.G_inf = -1
    try {
        mdr::io::CaseTemplate(root, "tree").build();
        FAIL() << "a negative G_inf was accepted";
    } catch (const mdr::InvalidInput& error) {
        EXPECT_EQ(std::string(error.what()).rfind("material.G_inf = -1", 0), 0u) << error.what();
    }
}
