// The `[load]` keys the reader takes come from the table of controls (drivers/controls.hpp): which keys exist, which
// control takes each, which are required, with the messages for a key of another control, an unknown key and a
// missing one.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace {

std::string message_of(const std::string& load) {
    try {
        mdr::io::parse_case("[material]\nmodel = \"elastic\"\nG = 1e6\n[indenter]\nshape = \"sphere\"\nR = 0.01\n"
                            "mass = 0.01\n[load]\n" + load);
    } catch (const mdr::InvalidInput& error) {
        return error.what();
    }
    return "";
}

const std::string displacement = "control = \"displacement\"\nhistory = [[0.0, 0.0], [1.0, 1e-4]]\n";
const std::string impact = "control = \"impact\"\nvelocity = 0.1\n";

TEST(ControlKeys, EveryRowsKeyIsALoadKeyAndControlComesFirst) {
    const auto keys = mdr::drivers::load_keys();
    ASSERT_FALSE(keys.empty());
    EXPECT_EQ(keys.front(), "control");
    for (const auto& kind : mdr::drivers::controls()) {
        EXPECT_FALSE(kind.keys.empty()) << kind.name;
        for (const auto& entry : kind.keys) {
            EXPECT_EQ(std::count(keys.begin(), keys.end(), entry.key), 1) << entry.key;
            EXPECT_EQ(kind.key_named(entry.key), &entry);
            EXPECT_FALSE(entry.documentation.empty()) << kind.name << "." << entry.key;
        }
    }
    EXPECT_EQ(mdr::drivers::control_named("impact").key_named("history"), nullptr);
}

TEST(ControlKeys, AKeyOfOtherControlsNamesThem) {
    EXPECT_EQ(message_of(displacement + "velocity = 1.0\n"),
              "load.velocity = 1: only with control = \"impact\", not \"displacement\"");
    EXPECT_EQ(message_of(displacement + "spin = 2.0\n"),
              "load.spin = 2: only with control = \"impact\", not \"displacement\"");
    EXPECT_EQ(message_of(displacement + "scale = \"A\"\n"),
              "load.scale = 'A': only with control = \"shore\", not \"displacement\"");
    EXPECT_EQ(message_of(impact + "spring_constant = 1e3\n"),
              "load.spring_constant = 1000: only with control = \"spring\", not \"impact\"");
    const std::string history = message_of(impact + "history = [[0.0, 0.0], [1.0, 1e-4]]\n");
    EXPECT_EQ(history.rfind("load.history = ", 0), 0u) << history;
    EXPECT_NE(history.find(": only with control = \"displacement\", \"force\" or \"spring\", not \"impact\""),
              std::string::npos)
        << history;
    EXPECT_NE(message_of("control = \"shore\"\nscale = \"A\"\nend = 1.0\n").find(
                  "only with control = \"displacement\", \"force\", \"impact\" or \"spring\", not \"shore\""),
              std::string::npos);
}

TEST(ControlKeys, AnUnknownKeyIsSuggestedOrListedFromTheTable) {
    EXPECT_EQ(message_of(impact + "velocty = 1.0\n"), "load.velocty = 1: unknown key; did you mean 'velocity'?");
    std::string valid;
    for (const auto& key : mdr::drivers::load_keys()) valid += (valid.empty() ? "" : ", ") + key;
    EXPECT_EQ(message_of(displacement + "xyzzy = 1.0\n"), "load.xyzzy = 1: unknown key; valid keys: " + valid);
    EXPECT_NE(valid.find("history, harmonic, end, velocity"), std::string::npos) << valid;
}

TEST(ControlKeys, ARequiredKeyIsNamedWithItsControl) {
    EXPECT_EQ(message_of("control = \"spring\"\nhistory = [[0.0, 0.0], [1.0, 1e-4]]\n"),
              "load.spring_constant = (missing): is required with control = \"spring\"");
    EXPECT_EQ(message_of("control = \"shore\"\n"), "load.scale = (missing): is required with control = \"shore\"");
    EXPECT_EQ(message_of("control = \"impact\"\n"), "load.velocity = (missing): is required with control = \"impact\"");
    EXPECT_EQ(message_of("control = \"force\"\n"), "load.history = (missing): is required with control = \"force\"");
    EXPECT_EQ(message_of(impact), "");  // the row's required keys suffice
}

}  // namespace
