#pragma once
// Reads an `[indenter]` table against the registry of indenter shapes (profile/shapes.hpp).

#include <memory>

#include "mdr/profile/profile.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// Reads `shape` and its keys from the `[indenter]` table and builds the profile; the table's other keys (mass,
/// moment_of_inertia, material) are read by the case. Throws mdr::InvalidInput with the full dotted key.
std::shared_ptr<const profile::Profile> read_indenter(TableReader& table);

}  // namespace mdr::io
