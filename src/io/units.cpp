#include "mdr/io/units.hpp"

#include <array>
#include <utility>

#include <fmt/format.h>

#include "mdr/error.hpp"

namespace mdr::io {
namespace {

// Each row consistent: pressure = force / length^2, mass = force s^2 / length, energy = force length; then the
// sizes of its length, force and time units in m, N and s (the only unit sizes mdr knows).
constexpr std::array<UnitSystem, 4> systems{{
    {"SI", "m", "N", "s", "Pa", "kg", "J", 1.0, 1.0, 1.0},
    {"mm-N-s", "mm", "N", "s", "MPa", "t", "mJ", 1e-3, 1.0, 1.0},       // N/mm^2 = MPa, N s^2/mm = 1000 kg
    {"um-nN-s", "µm", "nN", "s", "kPa", "g", "fJ", 1e-6, 1e-9, 1.0},    // nN/um^2 = kPa, nN s^2/um = 1e-3 kg (AFM)
    {"nm-nN-s", "nm", "nN", "s", "GPa", "kg", "aJ", 1e-9, 1e-9, 1.0},   // nN/nm^2 = GPa, nN s^2/nm = 1 kg
}};

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

}  // namespace

std::span<const UnitSystem> unit_systems() { return systems; }

std::optional<double> prefixed_unit_size(std::string_view name, std::string_view base) {
    static const std::pair<std::string_view, double> prefixes[] = {{"", 1.0},    {"p", 1e-12}, {"n", 1e-9}, {"u", 1e-6},
                                                                   {"µ", 1e-6}, {"m", 1e-3},  {"c", 1e-2}, {"k", 1e3}};
    for (const auto& [prefix, size] : prefixes) {
        if (name.size() == prefix.size() + base.size() && name.starts_with(prefix) && name.ends_with(base)) return size;
    }
    return std::nullopt;
}

double spring_constant_unit(std::string_view unit, const UnitSystem& system, const std::string& key,
                            const std::string& value_text, const std::string& unit_key) {
    const double system_size = system.force_size / system.length_size;  // the case's force / length in N/m
    if (unit.empty()) {
        if (system_size == 1.0) return 1.0;
        throw InvalidInput(key, value_text,
                           fmt::format("a spring constant in a {} case must state its unit: {} = \"N/m\" (as "
                                       "cantilevers are quoted) or \"{}/{}\" (the case's force / length)",
                                       system.name, unit_key, system.force,
                                       system.length == "µm" ? "um" : system.length));
    }
    const auto slash = unit.find('/');
    if (slash != std::string_view::npos) {
        const auto force = prefixed_unit_size(unit.substr(0, slash), "N");
        const auto length = prefixed_unit_size(unit.substr(slash + 1), "m");
        if (force && length) return *force / *length / system_size;
    }
    throw InvalidInput(unit_key, fmt::format("\"{}\"", unit),
                       "must be a force / length of SI symbols with a prefix (p, n, u or µ, m, c, k): \"N/m\", "
                       "\"nN/um\", \"pN/nm\"");
}

std::string UnitSystem::names(std::string_view si_unit) const {
    const std::pair<std::string_view, std::string_view> symbols[] = {
        {"m", length}, {"N", force}, {"s", time}, {"Pa", pressure}, {"kg", mass}, {"J", energy}};
    std::string text;
    for (std::size_t i = 0; i < si_unit.size();) {
        std::size_t end = i;
        while (end < si_unit.size() && is_letter(si_unit[end])) ++end;
        if (end == i) {
            text += si_unit[i++];
            continue;
        }
        const std::string_view word = si_unit.substr(i, end - i);
        const bool exponent = i > 0 && si_unit[i - 1] == '^';  // "^alpha" is no unit
        std::string_view replaced = word;
        for (const auto& [symbol, system_name] : symbols) {
            if (!exponent && word == symbol) replaced = system_name;
        }
        text += replaced;
        i = end;
    }
    return text;
}

std::function<std::string(const std::string&)> unit_names(const UnitSystem& system) {
    return [&system](const std::string& si_unit) { return system.names(si_unit); };
}

const UnitSystem& unit_system(std::string_view name) {
    std::string names;
    for (const auto& system : systems) {
        if (system.name == name) return system;
        names += (names.empty() ? "" : ", ") + std::string(system.name);
    }
    throw InvalidInput("units", "\"" + std::string(name) + "\"", "unknown unit system; one of " + names);
}

}  // namespace mdr::io
