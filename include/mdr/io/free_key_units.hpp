#pragma once
/// \file
/// The unit and physical domain of a fit's free key, from the registry that defines the key: the one source of the
/// units beside fitted values (map.json's `column_units`, the colour bars of the heat maps) and of the domain that
/// bounds a fit by default.

#include <string>

#include "mdr/io/case_template.hpp"

namespace mdr::io {

/// The unit, in SI symbols as the registries write them ("Pa", "s", "Pa s^alpha", "1", "m", "deg"), of the number
/// at the dotted key `key` of `model` (a `fit.free` key): for a key of a material table (`[material]`,
/// `[indenter.material]` and their `bulk` tables, where K stands for the leading G) the unit of its model's row in
/// rheology::material_models(), the pair's own unit for an element `terms[i][j]` ("Pa, s": j = 0 "Pa", j = 1 "s");
/// for a key of `[indenter]` the unit of its shape's row in profile::shapes(). "" when no registry defines the
/// key (a model's extra key such as the elastic bulk modulus `K`).
std::string free_key_unit(const CaseTemplate& model, const std::string& key);

/// The open upper end of the physical domain (0, limit) of the number at `key` of `model`, from the same registry
/// row as free_key_unit: 1 for an exponent or a springpot order, 90 for a cone's angle; infinity for a modulus,
/// time, viscosity or length, and for a key no registry defines.
double free_key_upper_limit(const CaseTemplate& model, const std::string& key);

}  // namespace mdr::io
