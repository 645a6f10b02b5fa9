#pragma once
// Reads the `[layer]` table of a case (shared spec case-format.md, "Layers").

#include "mdr/contact/layer.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// Reads `thickness` (> 0, finite) and `interface` ("bonded" or "sliding", required); throws mdr::InvalidInput
/// with the full dotted key for an unknown key, a missing one or a value that breaks its rule.
contact::Layer read_layer(TableReader& table);

}  // namespace mdr::io
