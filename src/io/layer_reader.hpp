#pragma once
// Reads the `[layer]` table of a case (shared spec case-format.md, "Layers").

#include <string>

#include "mdr/contact/layer.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// The rule of a layer's thickness (> 0; finite as any number read): throws mdr::InvalidInput(`key`, `text`, ...),
/// `text` being the value as the message shows it.
void require_layer_thickness(const std::string& key, double thickness, const std::string& text);

/// Reads `thickness` (> 0, finite) and `interface` ("bonded" or "sliding", required); throws mdr::InvalidInput
/// with the full dotted key for an unknown key, a missing one or a value that breaks its rule.
contact::Layer read_layer(TableReader& table);

}  // namespace mdr::io
