// The registry of controls (drivers/controls.hpp): a row per control type found by name and by value (plus the
// Shore durometer, a spring control with its own row), and the names that the reader's messages, the description and
// summary.json print come from it.

#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

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

// The table is made from the control types' own rows, in the order of LoadControl's types: the row of the n-th type's
// value is the n-th row once the durometer's is left out, and the durometer's row follows the spring's.
TEST(ControlRegistry, TheRowsFollowTheOrderOfTheControlTypes) {
    using namespace mdr::drivers;
    std::vector<std::string> by_type;
    [&by_type]<std::size_t... Index>(std::index_sequence<Index...>) {
        (by_type.push_back(control_kind(LoadControl(std::in_place_index<Index>)).name), ...);
    }(std::make_index_sequence<std::variant_size_v<LoadControl>>{});
    std::vector<std::string> table;
    for (const auto& kind : controls()) table.push_back(kind.name);
    const auto shore = std::find(table.begin(), table.end(), "shore");
    ASSERT_NE(shore, table.end());
    EXPECT_EQ(*std::prev(shore), "spring");
    table.erase(shore);
    EXPECT_EQ(table, by_type);
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
