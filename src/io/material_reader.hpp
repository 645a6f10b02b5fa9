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

/// The effective shear material of a half-space with the given shear and bulk rheology (eq. 56): the shear
/// material in series with one of operational modulus K(s) + G(s)/3, J_eff = J + J_B.
rheology::Rheology compressible_effective(const rheology::Rheology& shear, const rheology::Rheology& bulk);

}  // namespace mdr::io
