// The registry of tangential controls (drivers/controls.hpp): a row per TangentialControl found by name and by value;
// the reader's default, its "unknown control" message and the history column of its messages come from it.

#include <gtest/gtest.h>

#include <string>

#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace {

using mdr::drivers::TangentialControl;

const std::string normal_case =
    "[material]\nmodel = \"elastic\"\nG = 1e6\n[indenter]\nshape = \"sphere\"\nR = 0.01\n[load]\n"
    "control = \"displacement\"\nhistory = [[0.0, 0.0], [0.1, 1e-4], [0.2, 1e-4]]\n[tangential]\nfriction = 0.3\n";

std::string message_of(const std::string& tangential) {
    try {
        mdr::io::parse_case(normal_case + tangential);
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "";
}

TEST(TangentialControlRegistry, ARowPerControlFoundByNameAndByValue) {
    for (const TangentialControl control : {TangentialControl::displacement, TangentialControl::force}) {
        const auto& kind = mdr::drivers::tangential_control_kind(control);
        EXPECT_EQ(kind.control, control);
        EXPECT_EQ(&mdr::drivers::tangential_control_named(kind.name), &kind);
        EXPECT_FALSE(kind.documentation.empty()) << kind.name;
    }
    EXPECT_EQ(mdr::drivers::tangential_controls().size(), 2u);
    EXPECT_EQ(mdr::drivers::tangential_control_kind(TangentialControl::force).column, "Fx");
}

TEST(TangentialControlRegistry, TheReaderTakesItsNamesDefaultAndColumnsFromIt) {
    const auto by_default = mdr::io::parse_case(normal_case + "history = [[0.1, 0.0], [0.2, 1e-6]]\n");
    EXPECT_EQ(by_default.tangential->control, mdr::drivers::tangential_controls().front().control);
    const auto force = mdr::io::parse_case(normal_case + "control = \"force\"\nhistory = [[0.1, 0.0], [0.2, 0.01]]\n");
    EXPECT_EQ(force.tangential->control, TangentialControl::force);
    EXPECT_EQ(message_of("control = \"forc\"\nhistory = [[0.1, 0.0], [0.2, 0.01]]\n"),
              "tangential.control = \"forc\": unknown control; one of displacement, force");
    EXPECT_NE(message_of("control = \"force\"\nhistory = [[0.1, 0.0], [0.2]]\n").find("Fx"), std::string::npos);
}

}  // namespace
