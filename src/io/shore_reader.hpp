#pragma once
// The Shore durometer test of a case's `[load]` (control = "shore"), internal to mdr_io.

#include <memory>

#include "mdr/drivers/shore.hpp"
#include "mdr/io/units.hpp"
#include "mdr/profile/profile.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// A Shore test as read: the test and the durometer's indenter, both in the case's units.
struct ShoreLoad {
    drivers::ShoreTest test;
    std::shared_ptr<const profile::Profile> indenter;
};

/// The Shore test of a `[load]` with `control = "shore"` (keys scale, duration; read_control has checked the keys),
/// the durometer's constants expressed in `system`'s units.
ShoreLoad read_shore(TableReader& load, const UnitSystem& system);

}  // namespace mdr::io
