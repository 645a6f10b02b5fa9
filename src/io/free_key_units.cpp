#include "mdr/io/free_key_units.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "mdr/error.hpp"
#include "mdr/profile/shapes.hpp"
#include "mdr/rheology/material_models.hpp"

namespace mdr::io {
namespace {

/// `material.terms[0][1]` split: the table ("material"), the key's name ("terms") and its indices ([0, 1]).
struct KeyParts {
    std::string table;
    std::string name;
    std::vector<std::size_t> indices;
};

std::optional<KeyParts> split_key(const std::string& key) {
    const std::size_t bracket = key.find('[');
    const std::size_t dot = key.rfind('.', bracket == std::string::npos ? std::string::npos : bracket);
    if (dot == std::string::npos) return std::nullopt;
    KeyParts parts{key.substr(0, dot), key.substr(dot + 1, bracket == std::string::npos ? std::string::npos
                                                                                          : bracket - dot - 1),
                   {}};
    for (std::size_t open = bracket; open != std::string::npos; open = key.find('[', open + 1)) {
        parts.indices.push_back(std::stoul(key.substr(open + 1)));
    }
    return parts;
}

/// The `j`-th of the units of a pair's row, "Pa, s" (j = 1: "s").
std::string pair_unit(const std::string& unit, std::size_t j) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < j; ++i) {
        start = unit.find(", ", start);
        if (start == std::string::npos) return "";
        start += 2;
    }
    return unit.substr(start, unit.find(", ", start) - start);
}

// A free key's row: in rheology::material_models() or in profile::shapes() (at most one is set).
struct RegistryEntry {
    const rheology::ModelParameter* material = nullptr;
    const profile::ShapeParameter* shape = nullptr;
};

const rheology::ModelParameter* material_parameter(const std::string& model_name, const KeyParts& parts, bool bulk) {
    std::string name = parts.name;
    if (bulk && !name.empty() && name[0] == 'K') name[0] = 'G';  // a bulk table writes K for the leading G
    const rheology::MaterialModel* model = nullptr;
    try {
        model = &rheology::material_model(model_name);
    } catch (const InvalidInput&) {
        return nullptr;
    }
    for (const auto& parameter : model->parameters) {
        if (parameter.key == name) return &parameter;
    }
    return nullptr;
}

const profile::ShapeParameter* shape_parameter(const std::string& shape_name, const KeyParts& parts) {
    for (const auto& shape : profile::shapes()) {
        if (shape.name != shape_name) continue;
        for (const auto& parameter : shape.parameters) {
            if (parameter.key == parts.name) return &parameter;
        }
    }
    return nullptr;
}

// The row that defines the key `parts` of `model` (neither: no registry defines it).
RegistryEntry registry_entry(const CaseTemplate& model, const KeyParts& parts) {
    if (const auto model_name = model.string_at(parts.table + ".model")) {
        const std::string bulk_suffix = ".bulk";
        const bool bulk = parts.table.size() > bulk_suffix.size() &&
                          parts.table.compare(parts.table.size() - bulk_suffix.size(), bulk_suffix.size(),
                                              bulk_suffix) == 0;
        return {material_parameter(*model_name, parts, bulk), nullptr};
    }
    if (parts.table == "indenter") {
        if (const auto shape = model.string_at("indenter.shape")) return {nullptr, shape_parameter(*shape, parts)};
    }
    return {};
}

}  // namespace

std::string free_key_unit(const CaseTemplate& model, const std::string& key) {
    const auto parts = split_key(key);
    if (!parts) return "";
    const RegistryEntry entry = registry_entry(model, *parts);
    if (entry.shape != nullptr) return entry.shape->unit;
    if (entry.material == nullptr) return "";
    if (entry.material->kind != rheology::ParameterKind::pairs) return entry.material->unit;
    return parts->indices.size() == 2 ? pair_unit(entry.material->unit, parts->indices[1]) : "";
}

double free_key_upper_limit(const CaseTemplate& model, const std::string& key) {
    const auto parts = split_key(key);
    const RegistryEntry entry = parts ? registry_entry(model, *parts) : RegistryEntry{};
    if (entry.shape != nullptr) return entry.shape->upper_limit;
    if (entry.material != nullptr) return entry.material->upper_limit;
    return std::numeric_limits<double>::infinity();
}

}  // namespace mdr::io
