#pragma once
// The Shore durometer test of a case's `[load]` (control = "shore"), internal to mdr_io.

#include <memory>
#include <optional>

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

/// The Shore test when `load.control = "shore"` (keys control, scale, duration; any other key is refused), the
/// durometer's constants expressed in `system`'s units; none for another control, which must not have `scale` or
/// `duration`.
std::optional<ShoreLoad> read_shore(TableReader& load, const UnitSystem& system);

}  // namespace mdr::io
