// The declared unit systems: each row consistent (pressure = force / length^2, mass = force s^2 / length, energy =
// force length), checked from the SI size of each printed name; the reader takes `units` and refuses unknown ones.

#include "mdr/io/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"

namespace mdr::io {
namespace {

// The SI size of a unit name: an SI prefix (or none) on a base name; t is the tonne.
double si_size(std::string name) {
    static const std::map<std::string, double> bases{{"m", 1.0}, {"N", 1.0}, {"s", 1.0}, {"Pa", 1.0}, {"J", 1.0},
                                                     {"g", 1e-3}, {"t", 1e3}};
    static const std::map<std::string, double> prefixes{{"a", 1e-18}, {"f", 1e-15}, {"n", 1e-9}, {"µ", 1e-6},
                                                        {"m", 1e-3},  {"k", 1e3},   {"M", 1e6},  {"G", 1e9}};
    if (bases.count(name)) return bases.at(name);
    for (const auto& [prefix, factor] : prefixes) {
        if (name.rfind(prefix, 0) == 0 && bases.count(name.substr(prefix.size()))) {
            return factor * bases.at(name.substr(prefix.size()));
        }
    }
    ADD_FAILURE() << "unknown unit name " << name;
    return NAN;
}

TEST(UnitSystems, EveryRowIsConsistent) {
    ASSERT_EQ(unit_systems().front().name, "SI");
    for (const auto& system : unit_systems()) {
        SCOPED_TRACE(std::string(system.name));
        const double length = si_size(std::string(system.length)), force = si_size(std::string(system.force));
        const double time = si_size(std::string(system.time));
        EXPECT_NEAR(si_size(std::string(system.pressure)) / (force / (length * length)), 1.0, 1e-12);
        EXPECT_NEAR(si_size(std::string(system.mass)) / (force * time * time / length), 1.0, 1e-12);
        EXPECT_NEAR(si_size(std::string(system.energy)) / (force * length), 1.0, 1e-12);
        EXPECT_EQ(system.velocity(), std::string(system.length) + "/" + std::string(system.time));
        EXPECT_EQ(&unit_system(system.name), &system);
    }
}

constexpr const char* case_text = R"(
units = "um-nN-s"
[material]
model = "elastic"
G = 2.0
[indenter]
shape = "sphere"
R = 5.0
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0]]
)";

TEST(UnitSystems, TheReaderTakesTheDeclaredSystem) {
    const auto contact_case = parse_case(case_text);
    EXPECT_EQ(contact_case.units, "um-nN-s");
    const std::string description = describe(contact_case);
    EXPECT_NE(description.find("G(0+) = 2 kPa"), std::string::npos) << description;
    EXPECT_NE(description.find("[units um-nN-s]"), std::string::npos) << description;
    std::string text = case_text;
    EXPECT_EQ(parse_case(text.substr(text.find("[material]"))).units, "SI");
    text.replace(text.find("um-nN-s"), 7, "nano");
    try {
        parse_case(text);
        FAIL() << "no error";
    } catch (const InvalidInput& error) {
        EXPECT_STREQ(error.what(), "units = \"nano\": unknown unit system; one of SI, mm-N-s, um-nN-s, nm-nN-s");
    }
}

}  // namespace
}  // namespace mdr::io
