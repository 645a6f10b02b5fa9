#pragma once
/// \file
/// The unit system a case declares (`units = "SI"`, the default): the names printed beside its numbers in the
/// description, the command line's report, summary.json and the figures. Nothing is converted: the solver has no
/// physical constants and no absolute tolerances, so a case in any consistent system gives the results of its SI
/// twin in that system's units (tests/python/test_units.py runs such twins). The declaration only makes the
/// printed names true; each declared system is consistent (force = mass x length / time^2, pressure = force /
/// length^2).

#include <span>
#include <string>
#include <string_view>

namespace mdr::io {

/// One consistent unit system: its name in the case file and the names of its units.
struct UnitSystem {
    std::string_view name;      ///< the value of `units`, e.g. "um-nN-s"
    std::string_view length;    ///< e.g. "m"
    std::string_view force;     ///< e.g. "N"
    std::string_view time;      ///< e.g. "s"
    std::string_view pressure;  ///< force / length^2 (moduli, stresses), e.g. "Pa"
    std::string_view mass;      ///< force time^2 / length, e.g. "kg"
    std::string_view energy;    ///< force length, e.g. "J"

    std::string velocity() const { return std::string(length) + "/" + std::string(time); }
    std::string viscosity() const { return std::string(pressure) + " " + std::string(time); }
    std::string compliance() const { return "1/" + std::string(pressure); }
};

/// The declared systems, SI first (the default).
std::span<const UnitSystem> unit_systems();

/// The system named `name`. Throws mdr::InvalidInput (key `units`) for an unknown name, listing the known ones.
const UnitSystem& unit_system(std::string_view name);

}  // namespace mdr::io
