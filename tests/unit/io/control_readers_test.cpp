// The io table of controls (src/io/control_readers.hpp): one reader per row of the drivers' table, each building
// its row's control type, and read_case meeting the controls' keys in the order it always has (the first error of
// a case with several).

#include "io/control_readers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace mdr::io {
namespace {

const std::string material = "[material]\nmodel = \"elastic\"\nG = 1e6\n";
const std::string sphere = "[indenter]\nshape = \"sphere\"\nR = 0.01\nmass = 0.01\n";

std::string message_of(const std::string& text) {
    try {
        parse_case(text);
    } catch (const InvalidInput& error) {
        return error.what();
    }
    return "";
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

TEST(ControlReaders, EveryRowOfTheDriversTableHasOneReader) {
    const auto& readers = control_readers();
    EXPECT_EQ(readers.size(), drivers::controls().size());
    for (const auto& kind : drivers::controls()) {
        const auto named = [&kind](const ControlReader& row) { return row.name == kind.name; };
        EXPECT_EQ(std::count_if(readers.begin(), readers.end(), named), 1) << kind.name;
    }
}

// A case of each control reads to the type whose row (drivers::control_kind, the drivers' own visitor) is the
// control the case names.
TEST(ControlReaders, EachReaderBuildsItsRowsControl) {
    const std::string history = "history = [[0.0, 0.0], [1.0, 1e-5]]\n";
    const std::pair<std::string, std::string> cases[] = {
        {"displacement", material + sphere + "[load]\ncontrol = \"displacement\"\n" + history},
        {"force", material + sphere + "[load]\ncontrol = \"force\"\n" + history},
        {"spring", material + sphere + "[load]\ncontrol = \"spring\"\nspring_constant = 1e3\n" + history},
        {"impact", material + sphere + "[load]\ncontrol = \"impact\"\nvelocity = 0.1\n"},
        {"shore", material + "[load]\ncontrol = \"shore\"\nscale = \"A\"\n"},
    };
    ASSERT_EQ(std::size(cases), drivers::controls().size());
    for (const auto& [name, text] : cases) {
        EXPECT_EQ(drivers::control_kind(parse_case(text).control).name, name);
    }
}

// The first error of a case with several is the one met first in the order read_case has always read the keys:
// the durometer before [indenter], a spring's constant before its history, an impact's mass after its velocity,
// a spring's force pauses after [output].
TEST(ControlReaders, TheFirstErrorIsMetInTheReadersOrder) {
    EXPECT_EQ(message_of(material + sphere + "[load]\ncontrol = \"shore\"\nscale = \"A\"\n"),
              "indenter = [...]: not with control = \"shore\": the durometer's indenter is the standard's");
    EXPECT_TRUE(starts_with(message_of(material + sphere + "[load]\ncontrol = \"shore\"\nscale = \"B\"\n"), "load.scale = "));
    EXPECT_TRUE(starts_with(message_of(material + sphere +
                                       "[load]\ncontrol = \"spring\"\nspring_constant = \"k\"\nhistory = 1.0\n"),
                            "load.spring_constant = "));
    EXPECT_TRUE(starts_with(message_of(material + "[indenter]\nshape = \"sphere\"\nR = 0.01\n"
                                       "[load]\ncontrol = \"impact\"\nvelocity = \"v\"\n"),
                            "load.velocity = "));
    EXPECT_EQ(message_of(material + "[indenter]\nshape = \"sphere\"\nR = 0.01\n[load]\ncontrol = \"impact\"\n"
                                    "velocity = 0.1\n"),
              "indenter.mass = (missing): is required for an impact");
    EXPECT_TRUE(starts_with(message_of(material + sphere + "[load]\ncontrol = \"spring\"\nspring_constant = 1e3\n"
                                       "history = [[0.0, 0.0], [1.0, 1e-5]]\nforce_pauses = 1.0\n"
                                       "[output]\nsnapshot = 1.0\n"),
                            "output.snapshot = "));
}

}  // namespace
}  // namespace mdr::io
