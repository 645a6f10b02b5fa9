#pragma once
/// \file
/// Tabulated material functions for `mdr material`: functions.csv (t, G, J) and dynamic.csv (omega, storage, loss).

#include <filesystem>
#include <optional>
#include <vector>

#include "mdr/rheology/approximation.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::io {

/// `count` times log-spaced over the material's time scales: from a hundredth of its shortest time to a hundred
/// times its longest (1e-3 .. 1e3 s for an elastic body).
std::vector<double> default_times(const rheology::Rheology& material, std::size_t count = 121);
/// `count` angular frequencies log-spaced from 1/(100 longest time) to 100/shortest time.
std::vector<double> default_omegas(const rheology::Rheology& material, std::size_t count = 121);

/// Writes functions.csv (`t,G,J`, and `J_shear` when `shear` is given: the creep function without the bulk part)
/// and dynamic.csv (`omega,storage,loss`) into `directory`. G is the regular part of G(t) (a dashpot's delta is
/// left out). When `model` has functions (a power law standing as a series), the model's values are written
/// beside the series': `G_model` and `storage_model,loss_model`.
void write_material_tables(const std::filesystem::path& directory, const rheology::Rheology& material,
                           const std::optional<rheology::Rheology>& shear, const std::vector<double>& times,
                           const std::vector<double>& omegas, const rheology::ModelFunctions& model = {});

}  // namespace mdr::io
