#pragma once
// Reads a `[material]`-like table into the canonical rheology.

#include "mdr/rheology/rheology.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// The model names a material table accepts.
const std::vector<std::string>& model_names();

/// Reads `model` and its parameters from `table` (keys of the spec; `modulus` is "G" for shear tables and "K"
/// for a bulk table). Throws mdr::InvalidInput with the full dotted key.
rheology::Rheology read_rheology(TableReader& table, const std::string& modulus, std::vector<std::string> extra_keys);

}  // namespace mdr::io
