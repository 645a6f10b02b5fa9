// The factories of mdr.Material, one per row of the registry of material models (rheology/material_models.hpp):
// positional arguments in the row's order, keywords by the row's keys; a model converted to a series also takes
// `window=(t_min, t_max)` and `tolerance`.

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>

#include "bindings.hpp"
#include "mdr/error.hpp"
#include "mdr/rheology/material_models.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace mdr::python {
namespace {

using rheology::MaterialModel;
using rheology::ParameterKind;

void put(rheology::ModelParameters& parameters, const rheology::ModelParameter& parameter, const py::handle& value) {
    try {
        switch (parameter.kind) {
            case ParameterKind::number: parameters.numbers[parameter.key] = value.cast<double>(); break;
            case ParameterKind::pairs:
                parameters.pairs[parameter.key] = value.cast<std::vector<std::pair<double, double>>>();
                break;
            case ParameterKind::numbers: parameters.arrays[parameter.key] = value.cast<std::vector<double>>(); break;
            case ParameterKind::text: parameters.texts[parameter.key] = value.cast<std::string>(); break;
        }
    } catch (const py::cast_error&) {  // a wrong type is a TypeError in Python, as for any function
        const char* expected = parameter.kind == ParameterKind::number    ? "a number"
                               : parameter.kind == ParameterKind::pairs   ? "a sequence of pairs"
                               : parameter.kind == ParameterKind::numbers ? "a sequence of numbers"
                                                                          : "a string";
        throw py::type_error(parameter.key + " = " + py::repr(value).cast<std::string>() + ": must be " + expected);
    }
}

rheology::Rheology build(const MaterialModel& model, const py::args& args, const py::kwargs& kwargs) {
    rheology::ModelParameters parameters;
    rheology::ConversionOptions options;
    std::string valid;
    for (const auto& parameter : model.parameters) valid += (valid.empty() ? "" : ", ") + parameter.key;
    if (model.needs_window) valid += ", window, tolerance";
    if (args.size() > model.parameters.size()) {
        throw py::type_error(fmt::format("{}() takes at most {} positional arguments ({}), {} given", model.name,
                                         model.parameters.size(), valid, args.size()));
    }
    for (std::size_t i = 0; i < args.size(); ++i) put(parameters, model.parameters[i], args[i]);
    for (const auto& [name, value] : kwargs) {
        const auto key = name.cast<std::string>();
        if (model.needs_window && key == "window") {
            const auto window = value.cast<std::pair<double, double>>();
            options.window = rheology::TimeWindow{window.first, window.second};
            continue;
        }
        if (model.needs_window && key == "tolerance") {
            options.tolerance = value.cast<double>();
            continue;
        }
        const auto found = std::find_if(model.parameters.begin(), model.parameters.end(),
                                        [&](const auto& parameter) { return parameter.key == key; });
        if (found == model.parameters.end()) {
            throw py::type_error(fmt::format("{}() got an unexpected keyword argument '{}'; valid: {}", model.name,
                                             key, valid));
        }
        if (parameters.has(key)) {
            throw py::type_error(fmt::format("{}() got multiple values for argument '{}'", model.name, key));
        }
        put(parameters, *found, value);
    }
    for (const auto& parameter : model.parameters) {
        if (parameter.required && !parameters.has(parameter.key)) {
            throw py::type_error(
                fmt::format("{}() missing required argument '{}' (arguments: {})", model.name, parameter.key, valid));
        }
    }
    return rheology::build_material(model, parameters, options).series;
}

std::string docstring(const MaterialModel& model) {
    std::string text = model.documentation + ".\n\nParameters\n----------\n";
    for (const auto& parameter : model.parameters) {
        text += fmt::format("{} : {}\n    {} [{}]{}\n", parameter.key,
                            parameter.kind == ParameterKind::number ? "float" : "sequence", parameter.documentation,
                            parameter.unit, parameter.required ? "" : fmt::format(" (default {})", parameter.default_value));
    }
    if (model.needs_window) {
        text += "window : (float, float)\n    the lags (t_min, t_max) [s] over which the series is certified\n"
                "tolerance : float\n    relative error of G(t) and G^(omega) over the window (default 1e-4)\n";
    }
    return text + "\nReturns\n-------\nMaterial\n";
}

}  // namespace

void bind_material_models(py::class_<rheology::Rheology>& material) {
    for (const MaterialModel& model : rheology::material_models()) {
        material.def_static(
            model.name.c_str(), [&model](const py::args& args, const py::kwargs& kwargs) { return build(model, args, kwargs); },
            docstring(model).c_str());
        if (model.name == "table") {  // the name of the issue and of the docs: mdr.Material.from_table(...)
            material.def_static(
                "from_table", [&model](const py::args& args, const py::kwargs& kwargs) { return build(model, args, kwargs); },
                docstring(model).c_str());
        }
    }
}

void bind_material_registry(py::module_& module) {
    module.def(
        "_material_models",
        [] {
            py::list rows;
            for (const MaterialModel& model : rheology::material_models()) {
                py::list parameters;
                for (const auto& parameter : model.parameters) {
                    static const char* kinds[] = {"number", "pairs", "numbers", "text"};
                    py::dict row("key"_a = parameter.key, "kind"_a = kinds[static_cast<int>(parameter.kind)],
                                 "unit"_a = parameter.unit, "documentation"_a = parameter.documentation,
                                 "required"_a = parameter.required, "default"_a = parameter.default_value);
                    parameters.append(row);
                }
                rows.append(py::dict("name"_a = model.name, "documentation"_a = model.documentation,
                                     "parameters"_a = parameters, "needs_window"_a = model.needs_window));
            }
            return rows;
        },
        "The registry of material models (name, documentation, parameters), for the stubs and the docs.");
}

}  // namespace mdr::python
