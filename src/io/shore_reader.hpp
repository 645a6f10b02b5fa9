#pragma once
// The Shore durometer test of a case's `[load]` (control = "shore"), internal to mdr_io.

#include "mdr/drivers/shore.hpp"
#include "mdr/io/units.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// The Shore test of a `[load]` with `control = "shore"` (keys scale, duration; read_control has checked the keys),
/// the durometer's constants expressed in `system`'s units.
drivers::ShoreTest read_shore(TableReader& load, const UnitSystem& system);

}  // namespace mdr::io
