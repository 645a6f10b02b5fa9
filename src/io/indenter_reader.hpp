#pragma once
// Reads an `[indenter]` table against the registry of indenter shapes (profile/shapes.hpp).

#include <memory>

#include "mdr/profile/profile.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// Reads `shape` and its keys from the `[indenter]` table, unchecked: the shape's rules are build_indenter's. The
/// table's other keys (mass, moment_of_inertia, material) are read by the case. Throws mdr::InvalidInput with the
/// full dotted key for an unknown shape or key, or a value of the wrong type.
profile::ProfileDefinition read_indenter_definition(TableReader& table);

/// The profile of a definition (profile::make_profile); its errors name the key `indenter.KEY`.
std::shared_ptr<const profile::Profile> build_indenter(const profile::ProfileDefinition& definition);

/// read_indenter_definition, then build_indenter.
std::shared_ptr<const profile::Profile> read_indenter(TableReader& table);

}  // namespace mdr::io
