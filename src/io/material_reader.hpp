#pragma once
// Reads a `[material]`-like table against the registry of material models (rheology/material_models.hpp).

#include <string>
#include <vector>

#include "mdr/rheology/material_models.hpp"
#include "mdr/io/units.hpp"
#include "toml_reader.hpp"

namespace mdr::io {

/// A material table read and checked against its model's keys, not yet built: a model converted to a series
/// waits for the time window of the case.
struct MaterialSpec {
    const rheology::MaterialModel* model = nullptr;
    rheology::ModelParameters parameters{};  ///< by the registry's (shear) key names
    std::string prefix{};                    ///< the table's dotted path with a trailing dot (`material.`)
    bool bulk = false;                       ///< a bulk table: K for the leading G of every key
    std::optional<double> tolerance{};       ///< `tolerance`, for a model converted to a series
};

/// Reads `model` and its keys from `table` (`modulus` "G" for shear tables, "K" for a bulk table; `extra_keys`
/// are the other keys the table may hold). Throws mdr::InvalidInput with the full dotted key.
MaterialSpec read_material(TableReader& table, const std::string& modulus, const std::vector<std::string>& extra_keys);

/// The number of `spec` that its table writes `name` with `indices` (`tau1`; `G[2]`, an array's element; `terms[0][1]`,
/// the second value of a pair; `K_inf` in a bulk table), or nullptr when the spec holds no number there.
double* material_number(MaterialSpec& spec, const std::string& name, const std::vector<std::size_t>& indices);

/// Builds the material of a spec over `window` (used by models converted to a series), described in the case's
/// `units`. Errors name the full key.
rheology::ModelMaterial build_material(const MaterialSpec& spec, const std::optional<rheology::TimeWindow>& window,
                                       const std::string& directory, const UnitSystem& units);

}  // namespace mdr::io
