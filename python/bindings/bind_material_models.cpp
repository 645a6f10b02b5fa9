// The factories of mdr.Material, one per row of the registry of material models (rheology/material_models.hpp):
// positional arguments in the row's order, keywords by the row's keys; a model converted to a series also takes
// `window=(t_min, t_max)`, `frequencies` and `tolerance`, and comes back as an mdr.ConvertedMaterial (the series
// with the error of the conversion).

#include <pybind11/stl.h>

#include <fmt/format.h>

#include <algorithm>

#include "bindings.hpp"
#include "mdr/error.hpp"
#include "mdr/rheology/material_models.hpp"
#include "number.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace mdr::python {
namespace {

using rheology::MaterialModel;
using rheology::ParameterKind;

void put(rheology::ModelParameters& parameters, const rheology::ModelParameter& parameter, const py::handle& value) {
    try {
        switch (parameter.kind) {
            // Numbers as a case file takes them: a bool refused (Number).
            case ParameterKind::number: parameters.numbers[parameter.key] = value.cast<Number>(); break;
            case ParameterKind::pairs: {
                auto& pairs = parameters.pairs[parameter.key];
                pairs.clear();
                for (const auto& [first, second] : value.cast<std::vector<std::pair<Number, Number>>>()) {
                    pairs.emplace_back(first, second);
                }
                break;
            }
            case ParameterKind::numbers: {
                auto& numbers = parameters.arrays[parameter.key];
                numbers.clear();
                for (const Number number : value.cast<std::vector<Number>>()) numbers.push_back(number);
                break;
            }
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

// The row's parameter `key`, or nullptr for a key the model does not have.
const rheology::ModelParameter* find_parameter(const MaterialModel& model, const std::string& key) {
    const auto found = std::find_if(model.parameters.begin(), model.parameters.end(),
                                    [&](const auto& parameter) { return parameter.key == key; });
    return found == model.parameters.end() ? nullptr : &*found;
}

py::object build(const MaterialModel& model, const py::args& args, const py::kwargs& kwargs) {
    rheology::ModelParameters parameters;
    rheology::ConversionOptions options;
    std::vector<double> frequencies;
    std::string valid;
    for (const auto& parameter : model.parameters) valid += (valid.empty() ? "" : ", ") + parameter.key;
    if (model.needs_window) valid += ", window, frequencies, tolerance";
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
        if (model.needs_window && key == "frequencies") {
            frequencies = value.cast<std::vector<double>>();
            continue;
        }
        if (model.needs_window && key == "tolerance") {
            options.tolerance = value.cast<double>();
            continue;
        }
        const rheology::ModelParameter* found = find_parameter(model, key);
        if (found == nullptr) {
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
    if (options.window) {
        std::sort(frequencies.begin(), frequencies.end());
        options.window->frequencies = std::move(frequencies);
    }
    return material_object(rheology::build_material(model, parameters, options));
}

// The models whose factory returns an mdr.ConvertedMaterial: those converted to a series over a window, and tables.
bool converted(const MaterialModel& model) { return model.needs_window || model.name == "table"; }

std::string docstring(const MaterialModel& model) {
    std::string text = model.documentation + ".\n\nParameters\n----------\n";
    for (const auto& parameter : model.parameters) {
        text += fmt::format("{} : {}\n    {} [{}]{}\n", parameter.key,
                            parameter.kind == ParameterKind::number ? "float" : "sequence", parameter.documentation,
                            parameter.unit, parameter.required ? "" : fmt::format(" (default {})", parameter.default_value));
    }
    if (model.needs_window) {
        text += "window : (float, float)\n    the lags (t_min, t_max) [s] over which the series is certified\n"
                "frequencies : sequence of float, optional\n    angular frequencies [rad/s] at which G^(omega) is "
                "certified too, inside or outside the window (a harmonic load's 2 pi f)\n"
                "tolerance : float\n    relative error of G(t) and G^(omega) over the window (default 1e-4)\n";
    }
    std::string keywords;
    for (const auto& parameter : model.parameters) keywords += fmt::format("{}{}=...", keywords.empty() ? "" : ", ", parameter.key);
    const char* returns = converted(model)
                              ? "ConvertedMaterial\n    a Material with material_error, material_window and "
                                "material_frequencies\n"
                              : "Material\n";
    return text + "\nReturns\n-------\n" + returns + "\nExamples\n--------\n" +
           fmt::format("``mdr.Material.{}({})``, or in a case file ``[material]`` with ``model = \"{}\"`` and the keys "
                       "above (docs/case-format.md, Material models).\n",
                       model.name, keywords, model.name);
}

}  // namespace

py::dict model_table(const rheology::ModelDefinition& definition) {
    py::dict table;
    table["model"] = definition.model;
    for (const auto& [key, value] : definition.parameters.numbers) table[key.c_str()] = value;
    for (const auto& [key, value] : definition.parameters.pairs) {
        py::list pairs;
        for (const auto& [a, b] : value) pairs.append(py::make_tuple(a, b));
        table[key.c_str()] = pairs;
    }
    for (const auto& [key, value] : definition.parameters.arrays) table[key.c_str()] = value;
    for (const auto& [key, value] : definition.parameters.texts) table[key.c_str()] = value;
    if (definition.tolerance) table["tolerance"] = *definition.tolerance;
    return table;
}

rheology::ModelDefinition model_definition(const py::dict& table) {
    const MaterialModel& model = rheology::material_model(table["model"].cast<std::string>());
    rheology::ModelDefinition definition;
    definition.model = model.name;
    for (const auto& [name, value] : table) {
        const auto key = name.cast<std::string>();
        if (key == "tolerance") {
            definition.tolerance = value.cast<double>();
        } else if (key != "model") {
            const rheology::ModelParameter* parameter = find_parameter(model, key);
            if (parameter == nullptr) throw InvalidInput(key, "(given)", "not a key of model " + model.name);
            put(definition.parameters, *parameter, value);
        }
    }
    return definition;
}

namespace {
// The [material] table of a converted material's model (ConvertedMaterial::_definition, its pickle).
py::dict definition_table(const ConvertedMaterial& material) { return model_table(material.definition); }
}  // namespace

py::object material_object(rheology::ModelMaterial material) {
    if (!material.origin.certificate || !material.definition) return py::cast(std::move(material.series));
    return py::cast(ConvertedMaterial{std::move(material.series), std::move(*material.origin.certificate),
                                      std::move(*material.definition), material.origin.times_from_conversion});
}

void bind_material_models(py::class_<rheology::Rheology>& material) {
    // A Material that is its own series (no conversion): None; mdr.ConvertedMaterial gives the values.
    const auto none = [](const rheology::Rheology&) { return py::none(); };
    material.def_property_readonly("material_error", none,
                                   "float or None: the largest relative error of the series against its model (a "
                                   "table: the largest relative fit residual); None for a Material that is its own "
                                   "Prony series.");
    material.def_property_readonly("material_window", none,
                                   "(float, float) or None: the lags (t_min, t_max) [s] where material_error holds.");
    material.def_property_readonly("_definition", none,
                                   "None: a Material that is its own series stands for itself in a case (its "
                                   "Prony table, python/mdr/_case_tree.py).");
    material.def_property_readonly("material_frequencies", none,
                                   "list of float or None: the angular frequencies [rad/s] where G^(omega) is "
                                   "certified besides the window.");
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

void bind_converted_material(py::module_& module) {
    using rheology::Certificate;
    const auto state = [](const ConvertedMaterial& m) {
        std::vector<std::pair<double, double>> terms;
        for (const auto& term : m.terms()) terms.emplace_back(term.modulus, term.relaxation_time);
        const Certificate& c = m.certificate;
        return py::make_tuple(m.equilibrium_modulus(), m.viscosity(), terms, c.error, c.window.shortest,
                              c.window.longest, c.window.frequencies, c.tolerance, c.kind, definition_table(m),
                              m.times_from_conversion);
    };
    const auto restore = [](const py::tuple& s) {
        constexpr std::size_t fields = 11;  // the tuple of `state`
        if (s.size() != fields) {
            throw py::value_error(fmt::format(
                "mdr.ConvertedMaterial pickle: {} fields, this mdr {} reads {}: a pickle is read by the version of mdr "
                "that wrote it (the state gains fields, as times_from_conversion); convert the model again",
                s.size(), MDR_VERSION, fields));
        }
        std::vector<rheology::RelaxationTerm> terms;
        for (const auto& [G, tau] : s[2].cast<std::vector<std::pair<double, double>>>()) terms.push_back({G, tau});
        rheology::TimeWindow window{s[4].cast<double>(), s[5].cast<double>(), s[6].cast<std::vector<double>>()};
        ConvertedMaterial material{
            rheology::Rheology(s[0].cast<double>(), s[1].cast<double>(), std::move(terms)),
            Certificate{s[3].cast<double>(), std::move(window), s[7].cast<double>(), s[8].cast<std::string>()},
            {}, s[10].cast<bool>()};
        material.definition = model_definition(s[9].cast<py::dict>());
        return material;
    };
    py::class_<ConvertedMaterial, rheology::Rheology>(module, "ConvertedMaterial",
                                                      R"doc(An mdr.Material converted to a Prony series from a model.

What the factories of the power law, the springpots and tables return: the series, which the solver uses, with the
error of the conversion. A derived Material (series, with_bulk) is a plain Material again.

Examples
--------
>>> cell = mdr.Material.power_law(G0=1e3, beta=0.2, window=(1e-3, 10.0), frequencies=[1e4])
>>> cell.material_error <= 1e-4, cell.material_window, cell.material_frequencies
(True, (0.001, 10.0), [10000.0])
)doc")
        .def_property_readonly(
            "material_error", [](const ConvertedMaterial& m) { return m.certificate.error; },
            "float: the largest relative error of G(t) over the window and of G^(omega) over 1/t of the window and "
            "at the frequencies (a table: the largest relative fit residual at its data).")
        .def_property_readonly(
            "material_window",
            [](const ConvertedMaterial& m) { return std::pair{m.certificate.window.shortest, m.certificate.window.longest}; },
            "(float, float): the lags (t_min, t_max) [s] where material_error holds (a table: its data's span).")
        .def_property_readonly(
            "material_frequencies", [](const ConvertedMaterial& m) { return m.certificate.window.frequencies; },
            "list of float: the angular frequencies [rad/s] where G^(omega) is certified besides the window, "
            "ascending (the factory's frequencies).")
        .def_property_readonly("_definition", &definition_table,
                               "dict: the model's [material] table, which stands for this material in a case (the "
                               "case converts it again over its own window, as for the same table given as a dict).")
        .def(py::pickle(state, restore))
        .def("__repr__", [](const ConvertedMaterial& m) {
            return fmt::format("ConvertedMaterial(G_inf={}, eta={}, branches={}, material_error={:.3g})",
                               m.equilibrium_modulus(), m.viscosity(), m.terms().size(), m.certificate.error);
        });
}

void bind_material_registry(py::module_& module) {
    module.def(
        "_material_table",
        [](const py::handle& material) {
            if (py::isinstance<ConvertedMaterial>(material)) {
                return definition_table(material.cast<const ConvertedMaterial&>());
            }
            return model_table(rheology::series_definition(material.cast<const rheology::Rheology&>()));
        },
        py::arg("material"),
        "The [material] table an mdr.Material stands for in a case dict (python/mdr/_case_tree.py): an "
        "mdr.ConvertedMaterial's model (its name, parameters and tolerance), which the case converts again over its "
        "own window; else the series as its own model (rheology::series_definition: elastic, viscous, kelvin_voigt "
        "or prony), the keys a sweep of an mdr.ContactCase names it by too.");
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
                                     "parameters"_a = parameters, "needs_window"_a = model.needs_window,
                                     "converted"_a = converted(model)));
            }
            return rows;
        },
        "The registry of material models (name, documentation, parameters), for the stubs and the docs.");
}

}  // namespace mdr::python
