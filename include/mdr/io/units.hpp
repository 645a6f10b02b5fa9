#pragma once
/// \file
/// The unit system a case declares (`units = "SI"`, the default): the names printed beside its numbers in the
/// description, the command line's report, summary.json, fit.json and the figures, and the sizes of its units in
/// SI. The case's numbers are not converted: the solver has no physical constants and no absolute tolerances, so a
/// case in any consistent system gives the results of its SI twin in that system's units
/// (tests/python/test_units.py runs such twins). What is converted into the case's system are the quantities given
/// in other units: measured data with their own `units` (fitcase/fit_data_reader.cpp) and the physical constants of a
/// Shore durometer (shore_reader.cpp). Each declared system is consistent (force = mass x length / time^2,
/// pressure = force / length^2).

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace mdr::io {

/// One consistent unit system: its name in the case file, the names of its units and their sizes in SI.
struct UnitSystem {
    std::string_view name;      ///< the value of `units`, e.g. "um-nN-s"
    std::string_view length;    ///< e.g. "m"
    std::string_view force;     ///< e.g. "N"
    std::string_view time;      ///< e.g. "s"
    std::string_view pressure;  ///< force / length^2 (moduli, stresses), e.g. "Pa"
    std::string_view mass;      ///< force time^2 / length, e.g. "kg"
    std::string_view energy;    ///< force length, e.g. "J"
    double length_size = 1.0;   ///< one length unit in m, e.g. 1e-6 for µm
    double force_size = 1.0;    ///< one force unit in N
    double time_size = 1.0;     ///< one time unit in s

    std::string velocity() const { return std::string(length) + "/" + std::string(time); }
    std::string viscosity() const { return std::string(pressure) + " " + std::string(time); }
    std::string compliance() const { return "1/" + std::string(pressure); }

    /// A unit written with SI symbols (m, N, s, Pa, kg, J), e.g. a model key's unit "Pa s^alpha", in this system's
    /// names ("kPa s^alpha" in um-nN-s): each whole symbol is replaced, anything else ("1/", "rad", "^alpha", ", ")
    /// is kept. SI returns `si_unit` unchanged.
    std::string names(std::string_view si_unit) const;
};

/// The declared systems, SI first (the default).
std::span<const UnitSystem> unit_systems();

/// How rheology's descriptions print a registry unit in `system` (UnitSystem::names; a rheology::UnitNames);
/// `system` is one of unit_systems(), which live as long as the program.
std::function<std::string(const std::string&)> unit_names(const UnitSystem& system);

/// The size in SI of a unit written as an SI prefix (p, n, u or µ, m, c, k, or none) and `base` ("nm" with base
/// "m": 1e-9); nothing when `name` is not of that form.
std::optional<double> prefixed_unit_size(std::string_view name, std::string_view base);

/// The size of one spring-constant unit in `system`'s force / length (docs/case-format.md, "Measured curves").
/// `unit` is a force / length of prefixed SI symbols ("N/m", "nN/um", "pN/nm"); empty means the case's own force /
/// length, which is refused unless that is N/m: in a case whose force / length is not N/m a spring constant must
/// state its unit, one rule for case files (`units.spring_constant`) and mdr.fit's arrays (`units`), since a bare
/// 0.019 reads as N/m to an AFM user and as nN/µm to the case. Throws mdr::InvalidInput: key `key`, value
/// `value_text` (the spring constant as given) for a missing unit; key `unit_key` for an unknown unit.
double spring_constant_unit(std::string_view unit, const UnitSystem& system, const std::string& key,
                            const std::string& value_text, const std::string& unit_key);

/// The system named `name`. Throws mdr::InvalidInput (key `units`) for an unknown name, listing the known ones.
const UnitSystem& unit_system(std::string_view name);

}  // namespace mdr::io
