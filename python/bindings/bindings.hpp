#pragma once
// One binding function per area; module.cpp calls them. No logic lives in the bindings.

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "mdr/rheology/approximation.hpp"
#include "mdr/rheology/material_models.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::python {

/// What the factories of a model converted to a Prony series (power law, springpots, table) build: the series
/// and the certificate of the conversion, and the model's definition, which stands for it in a case given as a dict
/// (converted again over the case's window and harmonic frequencies, as for the same [material] table).
struct ConvertedMaterial : rheology::Rheology {
    rheology::Certificate certificate;
    rheology::ModelDefinition definition;  ///< the model and the values given to its factory (a file: absolute)
    bool times_from_conversion = false;    ///< rheology::MaterialOrigin::times_from_conversion of the conversion

    /// What the series stands for in a drivers::ContactCase: the model described with the units `unit_names` of
    /// the case (rheology::describe_model of its parameters with their defaults, as a case file's reader describes
    /// it), the certificate and whether its times come from the conversion (the model's functions are not kept).
    rheology::MaterialOrigin origin(const rheology::UnitNames& unit_names) const {
        const rheology::MaterialModel& registered = rheology::material_model(definition.model);
        return {rheology::describe_model(registered, rheology::with_defaults(registered, definition.parameters),
                                         nullptr, unit_names),
                certificate, {}, times_from_conversion};
    }
};

/// A material as Python holds it: an mdr.ConvertedMaterial for a series converted from a model (its certificate
/// and definition: a factory's, or a case body's as the reader built it), else an mdr.Material, its series.
pybind11::object material_object(rheology::ModelMaterial material);

/// The [material] table of a model's definition (model, parameters, tolerance): what a case builds (converts) again.
pybind11::dict model_table(const rheology::ModelDefinition& definition);
/// The definition of a model_table (a pickle's), its inverse; mdr::InvalidInput for a key its model lacks.
rheology::ModelDefinition model_definition(const pybind11::dict& table);

/// mdr.Material: the canonical rheology and its factories.
void bind_rheology(pybind11::module_& module);
/// The factories of mdr.Material, one per registered material model, and its material_* properties (None).
void bind_material_models(pybind11::class_<rheology::Rheology>& material);
/// mdr.ConvertedMaterial: an mdr.Material with the error, window and frequencies of its conversion.
void bind_converted_material(pybind11::module_& module);
/// _mdr._material_models(): the registry as data (stubs and docs are checked against it).
void bind_material_registry(pybind11::module_& module);
/// mdr.ContactCase and the load programme's classes (controls, harmonic, numerics, tangential load, layer).
void bind_contact_case(pybind11::module_& module);
/// mdr.run and mdr.check: cases from TOML text, a dict tree or an mdr.ContactCase; results as numpy arrays.
void bind_run(pybind11::module_& module);
/// mdr.Indenter: the profiles and their g(x), its factories from the registry of shapes, and _mdr._shapes().
void bind_profile(pybind11::module_& module);
/// _mdr._controls(): the registry of controls as data (the docs are checked against it).
void bind_control_registry(pybind11::module_& module);
/// The class of each type of drivers::LoadControl (mdr.DisplacementControl, ...), from its declared fields; the
/// classes of the parts its fields hold (mdr.ShoreTest, mdr.ObliqueImpact) are bound before.
void bind_controls(pybind11::module_& module);
/// mdr.sweep: a case over a grid of numeric keys.
void bind_sweep(pybind11::module_& module);
/// mdr.distributed: result directories with the rules of --out, for the files Python writes.
void bind_result_directory(pybind11::module_& module);

/// mdr.Curve and _mdr._read_curves: the curves of AFM instrument files (docs/instrument-files.md).
void bind_instrument(pybind11::module_& module);

/// mdr.fit: fit cases from TOML text, curves from files or arrays.
void bind_fit(pybind11::module_& module);

/// `_mdr.__all__`: every name of the module not starting with `_` (its public classes), in the order bound; the
/// `mdr` package exports them (`from ._mdr import *`), so a new class needs no edit there. Called last.
void list_public_names(pybind11::module_& module);

/// mdr.fit_map of an instrument map file: _mdr._fit_map_file (mdr/fitcase/map_fit.hpp, as `mdr fit --map`).
void bind_map_fit(pybind11::module_& module);
/// _mdr._to_json: the one JSON writer of results (io::to_json) for files and messages written from Python.
void bind_document(pybind11::module_& module);
}  // namespace mdr::python
