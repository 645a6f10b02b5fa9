#include "shore_reader.hpp"

#include <stdexcept>
#include <string>
#include <string_view>


namespace mdr::io {
namespace {

// The size of a system's length and force units in m and N (units.cpp's systems): the durometer's constants are
// physical, so they are written in the case's units.
double length_size(std::string_view name) {
    if (name == "m") return 1.0;
    if (name == "mm") return 1e-3;
    if (name == "µm") return 1e-6;
    if (name == "nm") return 1e-9;
    throw std::logic_error("no size for the length unit " + std::string(name));
}
double force_size(std::string_view name) {
    if (name == "N") return 1.0;
    if (name == "nN") return 1e-9;
    throw std::logic_error("no size for the force unit " + std::string(name));
}

}  // namespace

ShoreLoad read_shore(TableReader& load, const UnitSystem& system) {
    const drivers::ShoreScale scale = drivers::shore_scale_named(load.string("scale"));
    const double length_unit = length_size(system.length);
    const double duration = load.optional_number("duration").value_or(drivers::shore_default_duration);
    return ShoreLoad{drivers::make_shore_test(scale, duration, length_unit, force_size(system.force)),
                     drivers::durometer_indenter(scale, length_unit)};
}

}  // namespace mdr::io
