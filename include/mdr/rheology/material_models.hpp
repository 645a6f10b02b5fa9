#pragma once
/// \file
/// The one table of material models: name, keys with units and one-line documentation, and factory. The case
/// reader, its error messages, the description of a case, the Python factories, the stubs and the model list of
/// docs/case-format.md all come from it; adding a model is one row (material_models.cpp) plus its factory.

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mdr/rheology/approximation.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::rheology {

/// What a key holds.
enum class ParameterKind {
    number,  ///< a finite number
    pairs,   ///< an array of [a, b] pairs (pair_names name a and b in messages)
    numbers, ///< an array of numbers
    text,    ///< a string
};

/// One key of a model.
struct ModelParameter {
    std::string key;            ///< as in a shear table; a bulk table writes K for a leading G (G_inf -> K_inf)
    ParameterKind kind = ParameterKind::number;
    std::string unit;           ///< in SI symbols, e.g. "Pa", "Pa s", "s", "1" (a case's system: UnitNames)
    std::string documentation;  ///< one line
    bool required = true;       ///< false: optional (a number then takes default_value)
    double default_value = 0.0; ///< for an optional number
    std::pair<std::string, std::string> pair_names{};  ///< for pairs: the names of the two values
    /// The open upper end of a number's physical domain: 1 for an exponent or order (0 < beta < 1), infinity for a
    /// modulus, time or viscosity (> 0 only). A fit's default bounds stay inside it (io::free_key_upper_limit).
    double upper_limit = std::numeric_limits<double>::infinity();
};

/// The values a case or a caller gave, by key (shear naming).
struct ModelParameters {
    std::map<std::string, double> numbers{};
    std::map<std::string, std::vector<std::pair<double, double>>> pairs{};
    std::map<std::string, std::vector<double>> arrays{};
    std::map<std::string, std::string> texts{};

    /// The number under `key` (throws mdr::InvalidInput `key = (missing): is required` if absent).
    double number(const std::string& key) const;
    /// True when any kind of value is given for `key`.
    bool has(const std::string& key) const;
};

/// How the description prints a registry unit (written with SI symbols, e.g. "Pa s"): in the case's declared
/// system (io::UnitSystem::names gives "kPa s" in um-nN-s). Empty: the registry's own, SI.
using UnitNames = std::function<std::string(const std::string&)>;

/// What a conversion to a series needs besides the parameters.
struct ConversionOptions {
    std::optional<TimeWindow> window{};        ///< the lags the problem needs (required by models with a window)
    double tolerance = default_material_tolerance;  ///< relative, for models converted to a series
    std::string directory{};                   ///< where relative file names are found ("" = working directory)
    UnitNames unit_names{};                    ///< the units of the description (empty: SI)
};

/// A model as given to build_material: what a converted series stands for, so that the series can be described
/// again in another case's units and the model converted again over another case's window (mdr.ConvertedMaterial,
/// also as read back from a case's body).
struct ModelDefinition {
    std::string model;                ///< the row's name (`model = "name"`)
    ModelParameters parameters;       ///< the values given, a file named absolutely (ConversionOptions::directory)
    std::optional<double> tolerance;  ///< ConversionOptions::tolerance of a model converted over a window; else none
};

/// What a factory builds.
struct ModelMaterial {
    Rheology series;       ///< what the solver uses
    MaterialOrigin origin; ///< what it stands for
    /// The model given to build_material; none for a material built otherwise (exact_material, a combination).
    std::optional<ModelDefinition> definition{};
};

/// `series` as its own model (the models of Table 1, a plain mdr.Material): exact, no certificate, and with
/// MaterialOrigin::times_from_conversion when it has no time at all (no terms, no dashpot: elastic).
ModelMaterial exact_material(Rheology series);

/// The model a series that stands for itself is written as in a case's `[material]` table (a plain mdr.Material in
/// a case dict, python/mdr/_case_tree.py; a sweep's keys of a case given as objects): elastic (G), viscous (eta) or
/// kelvin_voigt (G, eta) without branches, else prony (G_inf, terms and, with a parallel dashpot, eta).
ModelDefinition series_definition(const Rheology& series);

/// One row of the table.
struct MaterialModel {
    std::string name;                        ///< `model = "name"`
    std::string documentation;               ///< one line, e.g. the relaxation modulus
    std::vector<ModelParameter> parameters;  ///< keys, in the order of the Python factory's arguments
    bool needs_window = false;               ///< converted to a series over the problem's time window
    ModelMaterial (*build)(const ModelParameters&, const ConversionOptions&) = nullptr;  ///< the factory
};

/// Every model, in the order of the documentation.
const std::vector<MaterialModel>& material_models();

/// The row named `name`; throws mdr::InvalidInput(`model`, "name", "unknown model; one of ...").
const MaterialModel& material_model(const std::string& name);

/// `parameters` with each number `model` defaults that is not given set to its default (ModelParameter::
/// default_value); throws mdr::InvalidInput `key = (missing): is required` for a required key not given.
ModelParameters with_defaults(const MaterialModel& model, const ModelParameters& parameters);

/// Builds the material of `model` from `parameters`: checks that every required key is given, then calls the
/// factory. Errors name the key as in a shear table (the caller prefixes its table).
ModelMaterial build_material(const MaterialModel& model, const ModelParameters& parameters,
                             const ConversionOptions& options = {});

/// `name (key = value unit, ...)` for the values given; the one-line description of a model's parameters. `rename`
/// gives a key as the table writes it (a bulk table: K for G); none: the registry's names. `unit_names` prints
/// the units in the case's system; empty: the registry's (SI).
std::string describe_model(const MaterialModel& model, const ModelParameters& parameters,
                           std::string (*rename)(const std::string&) = nullptr, const UnitNames& unit_names = {});

/// The description of a certificate: `as N Prony terms, error E over t = a .. b s`, then `and at omega = w1, w2
/// rad/s` when it certifies frequencies; `unit_names` as for describe_model.
std::string describe_certificate(const Certificate& certificate, std::size_t terms, const UnitNames& unit_names = {});

}  // namespace mdr::rheology
