// The registry of controls (drivers/controls.hpp): a row per control type found by name and by value (plus the
// Shore durometer, a spring control with its own row), and the names that the reader's messages, the description and
// summary.json print come from it.

#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

using mdr::drivers::LoadControl;

TEST(ControlRegistry, ARowPerControlFoundByNameAndByValue) {
    using namespace mdr::drivers;
    std::set<std::string> names;
    for (const LoadControl& control : {LoadControl(DisplacementControl{}), LoadControl(ForceControl{}),
                                       LoadControl(ImpactControl{}), LoadControl(SpringControl{})}) {
        const auto& kind = control_kind(control);
        EXPECT_EQ(&control_named(kind.name), &kind);
        EXPECT_FALSE(kind.documentation.empty()) << kind.name;
        EXPECT_FALSE(kind.keys.empty()) << kind.name;
        names.insert(kind.name);
    }
    EXPECT_EQ(names.size() + 1, mdr::drivers::controls().size());
    EXPECT_EQ(control_kind(ForceControl{}).column, "F");
    // The durometer: a spring control with a Shore test, found by value as the row "shore"; a plain spring is "spring".
    SpringControl durometer{.shore = make_shore_test(ShoreScale::D, 15.0)};
    EXPECT_EQ(control_kind(durometer).name, "shore");
    EXPECT_EQ(control_kind(SpringControl{}).name, "spring");
}

TEST(ControlRegistry, UnknownControlListsTheTable) {
    std::string message;
    try {
        mdr::io::parse_case("[material]\nmodel = \"elastic\"\nG = 1e6\n[indenter]\nshape = \"sphere\"\nR = 0.01\n"
                            "[load]\ncontrol = \"position\"\nhistory = [[0.0, 0.0], [1.0, 1e-5]]\n");
    } catch (const mdr::InvalidInput& error) {
        message = error.what();
    }
    std::string names;
    for (const auto& kind : mdr::drivers::controls()) names += (names.empty() ? "" : ", ") + kind.name;
    EXPECT_EQ(message, "load.control = \"position\": unknown control; one of " + names);
    EXPECT_EQ(names, "displacement, force, impact, spring, shore");
}

TEST(ControlRegistry, TheHistoryColumnNamesTheValueInMessages) {
    std::string message;
    try {
        mdr::io::parse_case("[material]\nmodel = \"elastic\"\nG = 1e6\n[indenter]\nshape = \"sphere\"\nR = 0.01\n"
                            "[load]\ncontrol = \"spring\"\nspring_constant = 1.0\nhistory = [[0.0, 0.0], [1.0]]\n");
    } catch (const mdr::InvalidInput& error) {
        message = error.what();
    }
    EXPECT_NE(message.find("[t, z]"), std::string::npos) << message;
}

}  // namespace
