#include "shore_reader.hpp"

namespace mdr::io {

drivers::ShoreTest read_shore(TableReader& load, const UnitSystem& system) {
    const drivers::ShoreScale scale = drivers::shore_scale_named(load.string("scale"));
    // The durometer's constants (and the standard's default duration) are physical: written in the case's units by
    // the sizes of the units table.
    const double duration =
        load.optional_number("duration").value_or(drivers::shore_default_duration / system.time_size);
    return drivers::make_shore_test(scale, duration, system.length_size, system.force_size);
}

}  // namespace mdr::io
