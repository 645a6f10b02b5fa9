#include "mdr/fitcase/fit_case.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "fitcase/fit_candidates_reader.hpp"
#include "fitcase/fit_data_reader.hpp"
#include "io/case_reader.hpp"
#include "io/toml_reader.hpp"
#include "mdr/drivers/material_window.hpp"
#include "mdr/error.hpp"
#include "mdr/fit/curve_window.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/free_key_units.hpp"
#include "mdr/io/free_number_case.hpp"
#include "mdr/io/units.hpp"

namespace mdr::fitcase {

using io::TableReader;

namespace {

// A placeholder history `duration` [s] long: each curve replaces the load (fit::run_curve).
std::string placeholder_load(double duration) {
    return fmt::format("control = \"displacement\"\nhistory = [[0.0, 0.0], [{}, 0.0]]\n", duration);
}

std::vector<std::string> free_keys(const toml::table& fit, bool optional) {
    const auto* array = fit["free"].as_array();
    if (array == nullptr && optional && !fit["free"]) return {};
    const std::string rule = "an array of dotted keys of the case, e.g. [\"material.G\"]";
    if (!fit["free"]) throw InvalidInput("fit.free", "(missing)", "is required: " + rule);
    if (array == nullptr) throw InvalidInput("fit.free", TableReader(fit, "fit").text("free"), "must be " + rule);
    std::vector<std::string> keys;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const auto key = (*array)[i].value<std::string>();
        if (!key) throw InvalidInput(fmt::format("fit.free[{}]", i), "(not a string)", "must be a dotted key");
        keys.push_back(*key);
    }
    return keys;
}

// Per-key numbers of `fit.bounds` or `fit.start`: the table's keys are free keys (quoted in TOML).
const toml::node* per_key(const toml::table& fit, const char* table, const std::string& key) {
    const auto* entries = fit[table].as_table();
    return entries == nullptr ? nullptr : entries->get(key);
}

void check_per_key_tables(const toml::table& fit, const std::vector<std::string>& keys) {
    for (const char* table : {"bounds", "start"}) {
        const auto* entries = fit[table].as_table();
        if (fit[table] && entries == nullptr) {
            throw InvalidInput(fmt::format("fit.{}", table), "(not a table)", "must be a table keyed by free keys");
        }
        if (entries == nullptr) continue;
        for (const auto& [name, node] : *entries) {
            if (std::string_view(table) == "bounds" && name.str() == "contact_point") continue;  // contact_bounds
            if (std::find(keys.begin(), keys.end(), std::string(name.str())) == keys.end()) {
                throw InvalidInput(fmt::format("fit.{}.{}", table, name.str()), "", "is not a key of fit.free");
            }
        }
    }
}

// On a [layer] a viscoelastic compressible body keeps the constant Poisson ratio its kernel needs (docs/theory.md
// eq. L20, K(t) = c G(t)) only with its moduli and times as given: a free key of [material] alone would change
// K(t)/G(t) in time at the first trial value. An elastic G beside an elastic K keeps it for any values.
void check_layer_poisson_ratio_kept(const drivers::ContactCase& model, const std::vector<std::string>& keys) {
    if (!model.layer || !model.bulk_material || model.bulk_material->is_time_independent()) return;
    for (const auto& key : keys) {
        if (key.rfind("material.", 0) == 0) {
            throw InvalidInput("fit.free", key,
                               "cannot be free on a [layer] with a viscoelastic bulk part: the layer needs K(t)/G(t) "
                               "constant in time (its kernel depends on the Poisson ratio), which one free modulus or "
                               "time would change; fix the material (layer.thickness may be free), or give an elastic "
                               "G with K");
        }
    }
}

fit::FreeParameter read_parameter(const toml::table& fit, const io::CaseTemplate& model, const std::string& key) {
    if (key.rfind("material.", 0) != 0 && key.rfind("indenter.", 0) != 0 && key != "layer.thickness") {
        throw InvalidInput("fit.free", key, "must name a number of [material] or [indenter], or layer.thickness");
    }
    if (!model.has_number(key)) throw InvalidInput("fit.free", key, "the case has no number under this key");
    // Its coordinate left unset: the rule fit::fitted_on_logarithm, on the bounds below.
    fit::FreeParameter parameter{.name = key,
                                 .start = model.number(key),
                                 .domain_upper = io::free_key_upper_limit(model, key),
                                 .domain_lower = 0.0};
    // The numbers of a TOML case's rules (TableReader: finite, an integer exactly a double).
    if (per_key(fit, "start", key)) parameter.start = TableReader(*fit["start"].as_table(), "fit.start").number(key);
    require_finite(key, parameter.start);
    if (per_key(fit, "bounds", key)) {
        TableReader bounds(*fit["bounds"].as_table(), "fit.bounds");
        const std::vector<double> pair = bounds.numbers(key);
        if (pair.size() != 2) throw InvalidInput("fit.bounds." + key, bounds.text(key), "must be [lower, upper]");
        parameter.lower = pair[0];
        parameter.upper = pair[1];
    } else if (parameter.start > 0.0) {
        // Four decades either side of the start, within the key's physical domain (0, limit) of its registry row:
        // the lower bound keeps 1e-4 of the start's distance to 0, the upper 1e-4 of its distance to a finite limit
        // (an exponent 0.2 of a power law: [2e-5, 0.99992], not [2e-5, 2000]).
        const double limit = parameter.domain_upper;
        parameter.lower = parameter.start * 1e-4;
        parameter.upper = parameter.start * 1e4;
        if (std::isfinite(limit)) parameter.upper = std::min(parameter.upper, limit - (limit - parameter.start) * 1e-4);
    } else {
        throw InvalidInput("fit.bounds." + key, "(missing)",
                           fmt::format("is required: the start value {} is not > 0", format_value(parameter.start)));
    }
    return parameter;
}

// `fit.bounds.contact_point = [lower, upper]`, in the data's depth (the case's length unit): FitSettings.
std::optional<std::array<double, 2>> contact_bounds(const toml::table& fit) {
    if (!per_key(fit, "bounds", "contact_point")) return std::nullopt;
    TableReader bounds(*fit["bounds"].as_table(), "fit.bounds");
    const std::vector<double> pair = bounds.numbers("contact_point");
    if (pair.size() != 2) {
        throw InvalidInput("fit.bounds.contact_point", bounds.text("contact_point"), "must be [lower, upper]");
    }
    return std::array<double, 2>{pair[0], pair[1]};
}

}  // namespace

FitCase parse_fit_case(std::string_view toml_text, const std::string& source,
                       const std::filesystem::path& case_directory) {
    return parse_fit_case(io::CaseTemplate(toml_text, source), case_directory);
}

FitCase parse_fit_case(io::CaseTemplate model, const std::filesystem::path& case_directory) {
    const std::string source = model.source();
    if (!model.has_table("fit")) throw InvalidInput("fit", "(missing)", "a fit case needs a [fit] table");
    const toml::table fit_table = io::parse_toml(model.take_table("fit"), source);
    TableReader fit(fit_table, "fit");
    fit.reject_unknown({"free", "bounds", "start", "fitted", "contact_point", "baseline", "max_iterations", "elements", "data",
                        "candidates", "spectrum"});

    FitCase fit_case{std::move(model), {}, {}, {}, false, read_candidates(fit), {}, {}, {}};
    fit_case.settings.fitted = read_fitted(fit, fit::Fitted::force);
    const std::string fitted = fit_case.settings.fitted == fit::Fitted::force ? "force" : "depth";
    const std::string contact = choice(fit, "contact_point", {"fit", "estimate", "fixed"}, "fit");
    fit_case.settings.contact_point = contact == "fit"        ? fit::ContactPointMode::fit
                                      : contact == "estimate" ? fit::ContactPointMode::estimate
                                                              : fit::ContactPointMode::fixed;
    const std::string baseline = choice(fit, "baseline", {"fit", "estimate", "fixed", "constant", "line"}, "constant");
    fit_case.settings.baseline = baseline == "fit"        ? fit::BaselineMode::fit
                                 : baseline == "estimate" ? fit::BaselineMode::estimate
                                 : baseline == "constant" ? fit::BaselineMode::constant
                                 : baseline == "line"     ? fit::BaselineMode::line
                                                          : fit::BaselineMode::fixed;
    fit_case.settings.contact_point_bounds = contact_bounds(fit_table);
    if (auto iterations = fit.optional_count("max_iterations")) fit_case.settings.max_iterations = *iterations;
    fit_case.settings.elements = fit.optional_count("elements");

    // The load: the curves drive the model; a given [load] must agree with what is fitted.
    fit_case.had_load = fit_case.model.has_table("load");
    if (fit_case.had_load) {
        const std::string expected = fitted == "force" ? "displacement" : "force";
        const std::string load = fit_case.model.take_table("load");
        const toml::table load_table = io::parse_toml(load, source);
        const auto control = load_table["control"].value<std::string>();
        if (control && *control != expected) {
            throw InvalidInput("load.control", "\"" + *control + "\"",
                               fmt::format("must be \"{}\" when fit.fitted = \"{}\" (the measured {} drives the model)",
                                           expected, fitted, fitted == "force" ? "depth" : "force"));
        }
        fit_case.model.set_table("load", load);
    } else {
        fit_case.model.set_table("load", placeholder_load(1.0));
    }
    const drivers::ContactCase built = fit_case.model.build();  // the model's own rules
    fit_case.units = built.units;                                 // its unit system
    const io::UnitSystem& units = io::unit_system(fit_case.units);

    const auto keys = free_keys(fit_table, !fit_case.model_choice.empty());
    check_candidate_free_keys(fit_case.model_choice, keys);
    check_layer_poisson_ratio_kept(built, keys);
    check_per_key_tables(fit_table, keys);
    for (const auto& key : keys) fit_case.parameters.push_back(read_parameter(fit_table, fit_case.model, key));

    // The curves may also come as arrays from a caller (fit::validate requires at least one).
    const auto* data = fit_table["data"].as_array();
    if (fit_table["data"] && data == nullptr) {
        throw InvalidInput("fit.data", "(not an array of tables)", "give each curve as a [[fit.data]] table");
    }
    for (std::size_t i = 0; data != nullptr && i < data->size(); ++i) {
        const auto* table = (*data)[i].as_table();
        const std::string path = fmt::format("fit.data[{}]", i);
        if (table == nullptr) throw InvalidInput(path, "(not a table)", "must be a [[fit.data]] table");
        TableReader reader(*table, path);
        if (choice(reader, "kind", {"curve", "rebound"}, "curve") == "rebound") {
            fit_case.rebounds.push_back(read_rebound_data(reader, case_directory, units));
            fit_case.rebound_keys.push_back(path);
        } else {
            fit_case.data.push_back(read_fit_data(reader, case_directory, units));
            fit_case.data_keys.push_back(path);
        }
    }
    return fit_case;
}

FitCase load_fit_case(const std::filesystem::path& path) {
    return parse_fit_case(io::read_case_text(path), path.string(), path.parent_path());
}

io::CaseTemplate converting_model(const FitCase& fit_case, const std::vector<fit::Curve>& curves) {
    io::CaseTemplate model = fit_case.model;
    const drivers::ContactCase built = model.build();
    if (!drivers::converted_model(built.material_origin) || curves.empty()) return model;
    rheology::TimeWindow window = fit::curves_window(curves, fit_case.settings.fitted, built);
    // The model's own load, which the case's rules check too: the case's [load], or a placeholder as long as the
    // longest run.
    if (!fit_case.had_load) model.set_table("load", placeholder_load(window.longest));
    const rheology::TimeWindow own = drivers::material_window(model.build());
    window.shortest = std::min(window.shortest, own.shortest);
    window.longest = std::max(window.longest, own.longest);
    window.frequencies = own.frequencies;
    model.set_conversion_window(std::move(window));
    return model;
}

fit::ModelBuilder model_builder(const FitCase& fit_case, const std::vector<fit::Curve>& curves) {
    io::CaseTemplate model = converting_model(fit_case, curves);
    if (fit_case.parameters.empty()) {  // nothing varies (a model choice with no indenter key free): built once
        return [built = model.build()](const std::vector<double>&) { return built; };
    }
    std::vector<std::string> keys;
    for (const auto& parameter : fit_case.parameters) keys.push_back(parameter.name);
    // Built once; each evaluation rebuilds only the material, indenter or layer the free keys touch.
    return [free = io::FreeNumberCase(model, std::move(keys))](const std::vector<double>& values) {
        return free.build(values);
    };
}

io::CaseTemplate fitted_model(const FitCase& fit_case, const std::vector<double>& values) {
    io::CaseTemplate copy = fit_case.model;
    for (std::size_t j = 0; j < fit_case.parameters.size(); ++j) copy.set_number(fit_case.parameters[j].name, values[j]);
    return copy;
}

}  // namespace mdr::fitcase
