#include "mdr/rheology/material_models.hpp"

#include <fmt/format.h>

#include "mdr/error.hpp"
#include "mdr/rheology/power_law.hpp"
#include "mdr/rheology/springpot.hpp"
#include "mdr/rheology/table_material.hpp"

#include <filesystem>
#include <limits>

namespace mdr::rheology {
namespace {
// A file named by a model's key: relative to a case's `directory` (ConversionOptions::directory; empty: the working
// directory).
std::filesystem::path found_path(const std::string& name, const std::string& directory) {
    const std::filesystem::path path = name;
    return path.is_relative() && !directory.empty() ? std::filesystem::path(directory) / path : path;
}

using Kind = ParameterKind;

ModelParameter modulus(std::string key, std::string documentation) {
    return {std::move(key), Kind::number, "Pa", std::move(documentation)};
}
ModelParameter viscosity(std::string documentation) { return {"eta", Kind::number, "Pa s", std::move(documentation)}; }
ModelParameter time(std::string key, std::string documentation) {
    return {std::move(key), Kind::number, "s", std::move(documentation)};
}

std::vector<RelaxationTerm> relaxation_terms(const ModelParameters& p) {
    std::vector<RelaxationTerm> terms;
    for (const auto& [G, tau] : p.pairs.at("terms")) terms.push_back({G, tau});
    return terms;
}

ModelMaterial build_power_law(const ModelParameters& p, const ConversionOptions& options) {
    const PowerLaw model{p.number("G0"), p.number("beta"), p.number("t0")};
    model.validate();
    Approximation approximation = approximate(model, *options.window, options.tolerance);
    return {std::move(approximation.series), {"", approximation.certificate, approximation.model, true}};
}

ModelParameter quasi_property() {
    return {"c", Kind::number, "Pa s^alpha", "springpot quasi-property (stress = c d^alpha strain / dt^alpha)"};
}
ModelParameter order() { return {"alpha", Kind::number, "1", "springpot order, 0 < alpha < 1", true, 0.0, {}, 1.0}; }

ModelMaterial fractional(FractionalModel model, const ConversionOptions& options) {
    model.validate();
    Approximation approximation = approximate(model, *options.window, options.tolerance);
    return {std::move(approximation.series), {"", approximation.certificate, approximation.model, true}};
}

ModelMaterial build_table(const ModelParameters& p, const ConversionOptions& options) {
    const auto given = [&](const char* key) { return p.has(key); };
    const int sources = (given("G") ? 1 : 0) + (given("J") ? 1 : 0) + (given("storage") || given("loss") ? 1 : 0) +
                        (given("file") ? 1 : 0);
    const char* rule = "give one of: t with G, t with J, omega with storage and loss, or file";
    if (sources != 1) throw InvalidInput("model", "\"table\"", rule);
    MaterialTable table;
    if (given("file")) {
        table = read_material_table(found_path(p.texts.at("file"), options.directory));
        for (const char* key : {"t", "omega"}) {
            if (given(key)) throw InvalidInput(key, "[...]", "not with file (the file holds the columns)");
        }
    } else {
        table.quantity = given("G") ? TableQuantity::relaxation : given("J") ? TableQuantity::creep : TableQuantity::dynamic;
        const auto array = [&](const char* key) {
            const auto found = p.arrays.find(key);
            if (found == p.arrays.end()) throw InvalidInput(key, "(missing)", rule);
            return found->second;
        };
        table.abscissa = array(table.abscissa_key());
        table.values = array(table.values_key());
        if (table.quantity == TableQuantity::dynamic) table.loss = array("loss");
        for (const char* key : {"t", "omega"}) {
            if (given(key) && std::string(key) != table.abscissa_key()) {
                throw InvalidInput(key, "[...]", std::string("not with ") + table.values_key());
            }
        }
    }
    Approximation approximation = fit_table(table);
    return {std::move(approximation.series), {"", approximation.certificate, approximation.model}};
}

std::vector<MaterialModel> rows() {
    return {
        {"elastic", "G(t) = G", {modulus("G", "shear modulus")}, false,
         [](const ModelParameters& p, const ConversionOptions&) {
             return exact_material(Rheology::elastic(p.number("G")));
         }},
        {"viscous", "G(t) = eta delta(t)", {viscosity("viscosity")}, false,
         [](const ModelParameters& p, const ConversionOptions&) {
             return exact_material(Rheology::viscous(p.number("eta")));
         }},
        {"kelvin_voigt", "G(t) = G + eta delta(t): a spring and a dashpot in parallel",
         {modulus("G", "spring modulus"), viscosity("dashpot viscosity")}, false,
         [](const ModelParameters& p, const ConversionOptions&) {
             return exact_material(Rheology::kelvin_voigt(p.number("G"), p.number("eta")));
         }},
        {"maxwell", "G(t) = G exp(-t/tau): a spring and a dashpot in series",
         {modulus("G", "spring modulus"), time("tau", "relaxation time")}, false,
         [](const ModelParameters& p, const ConversionOptions&) {
             return exact_material(Rheology::maxwell(p.number("G"), p.number("tau")));
         }},
        {"standard", "G(t) = G_inf + G1 exp(-t/tau1): the standard linear solid",
         {modulus("G_inf", "equilibrium modulus"), modulus("G1", "modulus of the Maxwell branch"),
          time("tau1", "relaxation time of the Maxwell branch")},
         false,
         [](const ModelParameters& p, const ConversionOptions&) {
             return exact_material(Rheology::standard(p.number("G_inf"), p.number("G1"), p.number("tau1")));
         }},
        {"prony", "G(t) = G_inf + eta delta(t) + sum G_k exp(-t/tau_k): a Prony series (generalised Maxwell)",
         {modulus("G_inf", "equilibrium modulus (0 for a fluid)"),
          {"terms", Kind::pairs, "Pa, s", "the branches [[G_1, tau_1], [G_2, tau_2], ...]", true, 0.0, {"G", "tau"}},
          {"eta", Kind::number, "Pa s", "viscosity of a dashpot in parallel", false, 0.0}},
         false,
         [](const ModelParameters& p, const ConversionOptions&) {
             return exact_material(Rheology(p.number("G_inf"), p.number("eta"), relaxation_terms(p)));
         }},
        {"power_law", "G(t) = G0 (t/t0)^(-beta): power-law rheology of cells and soft tissue, as a certified Prony series",
         {modulus("G0", "modulus at t = t0"),
          {"beta", Kind::number, "1", "exponent, 0 < beta < 1", true, 0.0, {}, 1.0},
          {"t0", Kind::number, "s", "reference time", false, 1.0}},
         true, build_power_law},
        {"springpot", "G(t) = c t^(-alpha) / Gamma(1 - alpha): a springpot (Scott Blair), as a certified Prony series",
         {quasi_property(), order()}, true,
         [](const ModelParameters& p, const ConversionOptions& options) {
             return fractional({0.0, std::numeric_limits<double>::infinity(), p.number("c"), p.number("alpha")}, options);
         }},
        {"fractional_kelvin_voigt", "G(t) = G + c t^(-alpha) / Gamma(1 - alpha): a spring and a springpot in parallel",
         {modulus("G", "spring modulus"), quasi_property(), order()}, true,
         [](const ModelParameters& p, const ConversionOptions& options) {
             return fractional({p.number("G"), std::numeric_limits<double>::infinity(), p.number("c"), p.number("alpha")},
                               options);
         }},
        {"fractional_maxwell", "G(t) = G E_alpha(-(t/tau)^alpha), tau^alpha = c/G: a spring and a springpot in series",
         {modulus("G", "spring modulus"), quasi_property(), order()}, true,
         [](const ModelParameters& p, const ConversionOptions& options) {
             require_positive("G", p.number("G"));
             return fractional({0.0, p.number("G"), p.number("c"), p.number("alpha")}, options);
         }},
        {"fractional_standard", "G(t) = G_inf + G1 E_alpha(-(t/tau)^alpha), tau^alpha = c/G1: the fractional standard solid",
         {modulus("G_inf", "equilibrium modulus"), modulus("G1", "spring of the fractional Maxwell branch"),
          quasi_property(), order()},
         true,
         [](const ModelParameters& p, const ConversionOptions& options) {
             require_positive("G_inf", p.number("G_inf"));
             require_positive("G1", p.number("G1"));
             return fractional({p.number("G_inf"), p.number("G1"), p.number("c"), p.number("alpha")}, options);
         }},
        {"table",
         "measured G(t), J(t) or G'(omega), G''(omega), as a Prony series fitted by non-negative least squares",
         {{"t", Kind::numbers, "s", "times of G or J, ascending", false},
          {"G", Kind::numbers, "Pa", "relaxation modulus at t", false},
          {"J", Kind::numbers, "1/Pa", "creep compliance at t", false},
          {"omega", Kind::numbers, "rad/s", "angular frequencies of storage and loss, ascending", false},
          {"storage", Kind::numbers, "Pa", "storage modulus G' at omega", false},
          {"loss", Kind::numbers, "Pa", "loss modulus G'' at omega", false},
          {"file", Kind::text, "path", "a CSV with the header t,G or t,J or omega,storage,loss (relative to the case)",
           false}},
         false, build_table},
    };
}

// A registry unit (SI symbols) as the case's system names it; as written without `unit_names`.
std::string in_system(const UnitNames& unit_names, const std::string& si_unit) {
    return unit_names ? unit_names(si_unit) : si_unit;
}

// The model as given, its files named absolutely (as found from the case's directory), so that it converts again
// from anywhere.
ModelDefinition definition_of(const MaterialModel& model, ModelParameters parameters,
                              const ConversionOptions& options) {
    for (const ModelParameter& parameter : model.parameters) {
        const auto name = parameters.texts.find(parameter.key);
        if (parameter.unit != "path" || name == parameters.texts.end()) continue;
        name->second = std::filesystem::absolute(found_path(name->second, options.directory)).string();
    }
    const auto tolerance = model.needs_window ? std::optional<double>(options.tolerance) : std::nullopt;
    return {model.name, std::move(parameters), tolerance};
}

}  // namespace

double ModelParameters::number(const std::string& key) const {
    const auto found = numbers.find(key);
    if (found == numbers.end()) throw InvalidInput(key, "(missing)", "is required");
    return found->second;
}

bool ModelParameters::has(const std::string& key) const {
    return numbers.contains(key) || pairs.contains(key) || arrays.contains(key) || texts.contains(key);
}

const std::vector<MaterialModel>& material_models() {
    static const std::vector<MaterialModel> table = rows();
    return table;
}

const MaterialModel& material_model(const std::string& name) {
    std::string names;
    for (const MaterialModel& model : material_models()) {
        if (model.name == name) return model;
        names += (names.empty() ? "" : ", ") + model.name;
    }
    throw InvalidInput("model", "\"" + name + "\"", "unknown model; one of " + names);
}

ModelParameters with_defaults(const MaterialModel& model, const ModelParameters& parameters) {
    ModelParameters complete = parameters;
    for (const ModelParameter& parameter : model.parameters) {
        if (complete.has(parameter.key)) continue;
        if (parameter.required) throw InvalidInput(parameter.key, "(missing)", "is required");
        if (parameter.kind == Kind::number) complete.numbers[parameter.key] = parameter.default_value;
    }
    return complete;
}

ModelMaterial build_material(const MaterialModel& model, const ModelParameters& parameters,
                             const ConversionOptions& options) {
    const ModelParameters complete = with_defaults(model, parameters);
    if (model.needs_window) {
        if (!options.window) {
            throw InvalidInput("window", "(missing)",
                               "model \"" + model.name + "\" is converted to a series over a time window; give one");
        }
        validate(*options.window);
    }
    ModelMaterial material = model.build(complete, options);
    material.origin.description = describe_model(model, complete, nullptr, options.unit_names);
    material.definition = definition_of(model, parameters, options);
    return material;
}

ModelMaterial exact_material(Rheology series) {
    const bool timeless = series.terms().empty() && series.viscosity() == 0.0;
    return {std::move(series), {.times_from_conversion = timeless}};
}

ModelDefinition series_definition(const Rheology& series) {
    const double G = series.equilibrium_modulus(), eta = series.viscosity();
    ModelParameters parameters;
    if (series.terms().empty()) {
        const char* model = eta == 0.0 ? "elastic" : G == 0.0 ? "viscous" : "kelvin_voigt";
        if (eta == 0.0 || G != 0.0) parameters.numbers["G"] = G;
        if (eta != 0.0) parameters.numbers["eta"] = eta;
        return {model, std::move(parameters), std::nullopt};
    }
    parameters.numbers["G_inf"] = G;
    if (eta > 0.0) parameters.numbers["eta"] = eta;
    auto& terms = parameters.pairs["terms"];
    for (const RelaxationTerm& term : series.terms()) terms.emplace_back(term.modulus, term.relaxation_time);
    return {"prony", std::move(parameters), std::nullopt};
}

std::string describe_model(const MaterialModel& model, const ModelParameters& parameters,
                           std::string (*rename)(const std::string&), const UnitNames& unit_names) {
    std::string list;
    for (const ModelParameter& parameter : model.parameters) {
        const std::string key = rename ? rename(parameter.key) : parameter.key;
        std::string item;
        if (const auto number = parameters.numbers.find(parameter.key); number != parameters.numbers.end()) {
            item = fmt::format("{} = {}", key, format_value(number->second));
            if (parameter.unit != "1") {  // two appends: GCC 12 warns falsely (-Wrestrict) on " " + string
                item += ' ';
                item += in_system(unit_names, parameter.unit);
            }
        } else if (const auto pairs = parameters.pairs.find(parameter.key); pairs != parameters.pairs.end()) {
            item = fmt::format("{} {}", pairs->second.size(), key);
        } else if (const auto array = parameters.arrays.find(parameter.key); array != parameters.arrays.end()) {
            item = fmt::format("{} values of {}", array->second.size(), key);
        } else if (const auto text = parameters.texts.find(parameter.key); text != parameters.texts.end()) {
            item = fmt::format("{} = \"{}\"", key, text->second);
        }
        if (!item.empty()) list += (list.empty() ? "" : ", ") + item;
    }
    return model.name + " (" + list + ")";
}

std::string describe_certificate(const Certificate& certificate, std::size_t terms, const UnitNames& unit_names) {
    std::string text = fmt::format("as {} Prony terms, {} {:.2g} over t = {:.3g} .. {:.3g} {}", terms,
                                   certificate.kind == "model" ? "relative error" : "fit residual", certificate.error,
                                   certificate.window.shortest, certificate.window.longest,
                                   in_system(unit_names, "s"));
    const auto& frequencies = certificate.window.frequencies;
    for (std::size_t i = 0; i < frequencies.size(); ++i) {
        text += fmt::format("{}{:.4g}", i == 0 ? " and at omega = " : ", ", frequencies[i]);
    }
    return frequencies.empty() ? text : text + " " + in_system(unit_names, "rad/s");
}

}  // namespace mdr::rheology
