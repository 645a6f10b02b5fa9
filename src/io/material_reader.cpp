#include "material_reader.hpp"

#include "mdr/error.hpp"

namespace mdr::io {
namespace {

// The key as a table of `modulus` writes it: K for the leading G of a bulk table (G_inf -> K_inf).
std::string table_key(const std::string& key, bool bulk) {
    std::string renamed = key;
    if (bulk && !renamed.empty() && renamed[0] == 'G') renamed[0] = 'K';
    return renamed;
}

std::string bulk_key(const std::string& key) { return table_key(key, true); }

}  // namespace

MaterialSpec read_material(TableReader& table, const std::string& modulus, const std::vector<std::string>& extra_keys) {
    MaterialSpec spec;
    spec.prefix = table.key_path("");
    spec.bulk = modulus == "K";
    const std::string name = table.string("model");
    try {
        spec.model = &rheology::material_model(name);
    } catch (const InvalidInput& error) {
        throw error.with_prefix(spec.prefix);
    }
    std::vector<std::string> known{"model"};
    for (const auto& parameter : spec.model->parameters) known.push_back(table_key(parameter.key, spec.bulk));
    if (spec.model->needs_window) known.emplace_back("tolerance");
    known.insert(known.end(), extra_keys.begin(), extra_keys.end());
    table.reject_unknown(known);
    for (const auto& parameter : spec.model->parameters) {
        const std::string key = table_key(parameter.key, spec.bulk);
        if (!table.has(key)) continue;  // required keys are checked when built, in the order of the row
        switch (parameter.kind) {
            case rheology::ParameterKind::number: spec.parameters.numbers[parameter.key] = table.number(key); break;
            case rheology::ParameterKind::pairs: {
                const std::string first = table_key(parameter.pair_names.first, spec.bulk);
                spec.parameters.pairs[parameter.key] = table.pairs(key, first.c_str(), parameter.pair_names.second.c_str());
                break;
            }
            case rheology::ParameterKind::numbers: spec.parameters.arrays[parameter.key] = table.numbers(key); break;
            case rheology::ParameterKind::text: spec.parameters.texts[parameter.key] = table.string(key); break;
        }
    }
    if (spec.model->needs_window) spec.tolerance = table.optional_number("tolerance");
    // A missing required key is reported now, with its full name, rather than after the rest of the case.
    for (const auto& parameter : spec.model->parameters) {
        if (parameter.required && !spec.parameters.has(parameter.key)) {
            throw InvalidInput(table.key_path(table_key(parameter.key, spec.bulk)), "(missing)", "is required");
        }
    }
    return spec;
}

double* material_number(MaterialSpec& spec, const std::string& name, const std::vector<std::size_t>& indices) {
    for (const auto& parameter : spec.model->parameters) {
        if (table_key(parameter.key, spec.bulk) != name) continue;
        auto& values = spec.parameters;
        if (parameter.kind == rheology::ParameterKind::number && indices.empty()) {
            const auto number = values.numbers.find(parameter.key);
            return number == values.numbers.end() ? nullptr : &number->second;
        }
        if (parameter.kind == rheology::ParameterKind::numbers && indices.size() == 1) {
            const auto array = values.arrays.find(parameter.key);
            if (array == values.arrays.end() || indices[0] >= array->second.size()) return nullptr;
            return &array->second[indices[0]];
        }
        if (parameter.kind == rheology::ParameterKind::pairs && indices.size() == 2 && indices[1] < 2) {
            const auto pairs = values.pairs.find(parameter.key);
            if (pairs == values.pairs.end() || indices[0] >= pairs->second.size()) return nullptr;
            auto& pair = pairs->second[indices[0]];
            return indices[1] == 0 ? &pair.first : &pair.second;
        }
        return nullptr;
    }
    return nullptr;
}

rheology::ModelMaterial build_material(const MaterialSpec& spec, const std::optional<rheology::TimeWindow>& window,
                                       const std::string& directory, const UnitSystem& units) {
    try {
        rheology::ConversionOptions options{window, spec.tolerance.value_or(rheology::default_material_tolerance),
                                            directory, unit_names(units)};
        rheology::ModelMaterial material = rheology::build_material(*spec.model, spec.parameters, options);
        if (spec.bulk) {
            material.origin.description =
                rheology::describe_model(*spec.model, spec.parameters, bulk_key, options.unit_names);
        }
        return material;
    } catch (const InvalidInput& error) {
        if (error.key().rfind(spec.prefix, 0) == 0) throw;
        throw InvalidInput(spec.prefix + table_key(error.key(), spec.bulk), error.value(), error.rule());
    }
}

}  // namespace mdr::io
