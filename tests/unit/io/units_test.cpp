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

TEST(UnitSystems, SizesAreThoseOfTheNames) {
    for (const auto& system : unit_systems()) {
        SCOPED_TRACE(std::string(system.name));
        EXPECT_EQ(si_size(std::string(system.length)), system.length_size);
        EXPECT_EQ(si_size(std::string(system.force)), system.force_size);
        EXPECT_EQ(si_size(std::string(system.time)), system.time_size);
    }
}

TEST(UnitSystems, RegistryUnitsInASystemsNames) {
    // Every unit of the material and shape registries, in SI symbols, is SI's own name and is written in um-nN-s
    // symbol by symbol; what is no unit symbol (rad, deg, path, 1, an exponent) stays.
    const auto& si = unit_system("SI");
    const auto& cells = unit_system("um-nN-s");
    const std::map<std::string, std::string> expected{
        {"Pa", "kPa"},   {"Pa s", "kPa s"}, {"s", "s"},        {"1/Pa", "1/kPa"}, {"Pa s^alpha", "kPa s^alpha"},
        {"Pa, s", "kPa, s"}, {"rad/s", "rad/s"}, {"1", "1"},   {"path", "path"},  {"m", "µm"},
        {"deg", "deg"},  {"kg", "g"},       {"N/m", "nN/µm"}, {"J", "fJ"},       {"m^s", "µm^s"}};
    for (const auto& [unit, in_cells] : expected) {
        EXPECT_EQ(si.names(unit), unit);
        EXPECT_EQ(cells.names(unit), in_cells) << unit;
    }
    EXPECT_EQ(unit_system("mm-N-s").names("Pa s"), "MPa s");
    EXPECT_EQ(unit_system("nm-nN-s").names("1/Pa"), "1/GPa");
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

TEST(UnitSystems, TheModelIsDescribedInTheDeclaredSystem) {
    // The model's keys (and a bulk table's, and a certificate's window) in the system's names; SI as it always was.
    std::string text = case_text;
    text.replace(text.find("model = \"elastic\"\nG = 2.0"), 24,
                 "model = \"kelvin_voigt\"\nG = 2.0\neta = 0.5\n[material.bulk]\nmodel = \"elastic\"\nK = 40.0");
    const std::string cells = describe(parse_case(text));
    EXPECT_NE(cells.find("kelvin_voigt (G = 2 kPa, eta = 0.5 kPa s) with bulk elastic (K = 40 kPa)"), std::string::npos)
        << cells;
    const std::string si_text = text.substr(text.find("[material]"));
    EXPECT_EQ(describe(parse_case(si_text)),
              "sphere R = 5 on a viscoelastic half-space kelvin_voigt (G = 2 Pa, eta = 0.5 Pa s) with bulk elastic "
              "(K = 40 Pa) (G(0+) = inf Pa, G(inf) = 1.906 Pa, 1 branch(es)), displacement control, 2 history "
              "points over t = 0 .. 1 s");
    text = case_text;
    text.replace(text.find("model = \"elastic\"\nG = 2.0"), 24,
                 "model = \"fractional_kelvin_voigt\"\nG = 2.0\nc = 0.5\nalpha = 0.3");
    const std::string fractional = describe(parse_case(text));
    EXPECT_NE(fractional.find("(G = 2 kPa, c = 0.5 kPa s^alpha, alpha = 0.3) as "), std::string::npos) << fractional;
    EXPECT_NE(fractional.find(" s (G(0+) = "), std::string::npos) << fractional;  // the certificate's window
}

}  // namespace
}  // namespace mdr::io
