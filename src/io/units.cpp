#include "mdr/io/units.hpp"

#include <array>

#include "mdr/error.hpp"

namespace mdr::io {
namespace {

// Each row consistent: pressure = force / length^2, mass = force s^2 / length, energy = force length.
constexpr std::array<UnitSystem, 4> systems{{
    {"SI", "m", "N", "s", "Pa", "kg", "J"},
    {"mm-N-s", "mm", "N", "s", "MPa", "t", "mJ"},          // N/mm^2 = MPa, N s^2/mm = 1000 kg
    {"um-nN-s", "µm", "nN", "s", "kPa", "g", "fJ"},         // nN/um^2 = kPa, nN s^2/um = 1e-3 kg (AFM on cells)
    {"nm-nN-s", "nm", "nN", "s", "GPa", "kg", "aJ"},        // nN/nm^2 = GPa, nN s^2/nm = 1 kg
}};

}  // namespace

std::span<const UnitSystem> unit_systems() { return systems; }

const UnitSystem& unit_system(std::string_view name) {
    std::string names;
    for (const auto& system : systems) {
        if (system.name == name) return system;
        names += (names.empty() ? "" : ", ") + std::string(system.name);
    }
    throw InvalidInput("units", "\"" + std::string(name) + "\"", "unknown unit system; one of " + names);
}

}  // namespace mdr::io
