// The registry of controls (drivers/controls.hpp): a row per Control found by name and by value (plus the Shore
// durometer, a spring control of its own), and the names that the reader's messages, the description and
// summary.json print come from it.

#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace {

using mdr::drivers::Control;

TEST(ControlRegistry, ARowPerControlFoundByNameAndByValue) {
    std::set<std::string> names;
    for (const Control control : {Control::displacement, Control::force, Control::impact, Control::spring}) {
        const auto& kind = mdr::drivers::control_kind(control);
        EXPECT_EQ(kind.control, control);
        EXPECT_EQ(&mdr::drivers::control_named(kind.name), &kind);
        EXPECT_FALSE(kind.documentation.empty()) << kind.name;
        EXPECT_FALSE(kind.keys.empty()) << kind.name;
        names.insert(kind.name);
    }
    EXPECT_EQ(names.size() + 1, mdr::drivers::controls().size());
    EXPECT_EQ(mdr::drivers::control_kind(Control::force).column, "F");
    // The durometer: found by name, a spring control; by value, Control::spring is the plain spring.
    EXPECT_EQ(mdr::drivers::control_named("shore").control, Control::spring);
    EXPECT_EQ(mdr::drivers::control_kind(Control::spring).name, "spring");
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
