#include "mdr/io/free_number_case.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

#include "body_reader.hpp"
#include "case_template_tables.hpp"
#include "indenter_reader.hpp"
#include "layer_reader.hpp"
#include "part_numbers.hpp"
#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/layer_indentation.hpp"
#include "mdr/drivers/material_window.hpp"
#include "mdr/error.hpp"
#include "mdr/rheology/contact_bodies.hpp"

namespace mdr::io {

namespace {

// The numbers free keys may change, as the case reader read them.
struct Editable {
    BodySpec half_space;
    std::optional<BodySpec> second;                       // `[indenter.material]`
    std::optional<profile::ProfileDefinition> indenter;   // absent when the control brings it (a durometer)
    std::optional<double> thickness;                      // `layer.thickness`
};

// The parts of a case a free key rebuilds.
enum class Part { material, indenter, layer };

// `K`, `bulk.KEY` or a key of the shear table.
double* body_number(BodySpec& body, const std::string& key) {
    if (key == "K") return body.bulk_modulus ? &*body.bulk_modulus : nullptr;
    if (key.rfind("bulk.", 0) == 0) return body.bulk ? spec_number(*body.bulk, key.substr(5)) : nullptr;
    return spec_number(body.shear, key);
}

bool starts_with(const std::string& key, const std::string& prefix) { return key.rfind(prefix, 0) == 0; }

// The number a free key names in the parts, or nullptr when it is not of a typed kind.
double* free_number(Editable& parts, const std::string& key) {
    if (key == "layer.thickness") return parts.thickness ? &*parts.thickness : nullptr;
    const std::string second = "indenter.material.", half_space = "material.", indenter = "indenter.";
    if (starts_with(key, second)) return parts.second ? body_number(*parts.second, key.substr(second.size())) : nullptr;
    if (starts_with(key, half_space)) return body_number(parts.half_space, key.substr(half_space.size()));
    if (starts_with(key, indenter)) {
        return parts.indenter ? profile_number(*parts.indenter, key.substr(indenter.size())) : nullptr;
    }
    return nullptr;
}

Part part_of(const std::string& key) {
    if (key == "layer.thickness") return Part::layer;
    return starts_with(key, "indenter.") && !starts_with(key, "indenter.material.") ? Part::indenter : Part::material;
}

}  // namespace

struct FreeNumberCase::Parts {
    Parts(const CaseTemplate& template_case, std::vector<std::string> free_keys)
        : model(template_case), keys(std::move(free_keys)), base(template_case.build()) {}

    CaseTemplate model;  // for the template path
    std::vector<std::string> keys;
    drivers::ContactCase base;  // built once
    bool typed = false;
    Editable editable{};
    bool material = false, indenter = false, layer = false;  // the parts the keys touch
    std::optional<rheology::TimeWindow> window{};  // as read_case takes it for the bodies
    std::string directory{};                       // where files a material names are found
};

FreeNumberCase::FreeNumberCase(const CaseTemplate& model, std::vector<std::string> keys) {
    auto parts = std::make_shared<Parts>(model, std::move(keys));
    for (const auto& key : parts->keys) {
        if (!model.has_number(key)) throw InvalidInput(key, "(missing)", "the case has no number under this key");
    }
    // The parts as read_case reads them (the case built, so every read succeeds).
    const toml::table& root_table = model.tables_->root;
    TableReader root(root_table, "");
    std::optional<TableReader> indenter = root.table("indenter");
    std::optional<TableReader> material = root.table("material");
    Editable& editable = parts->editable;
    editable.half_space = read_body(*material);
    if (indenter) {
        editable.indenter = read_indenter_definition(*indenter);
        if (auto second = indenter->table("material")) editable.second = read_body(*second);
    }
    if (parts->base.layer) editable.thickness = parts->base.layer->thickness;

    parts->typed = true;
    for (const auto& key : parts->keys) {
        parts->typed = parts->typed && free_number(editable, key) != nullptr;
        const Part part = part_of(key);
        parts->material = parts->material || part == Part::material;
        parts->indenter = parts->indenter || part == Part::indenter;
        parts->layer = parts->layer || part == Part::layer;
    }
    const drivers::ContactCase& base = parts->base;
    if (parts->typed && parts->material &&
        (editable.half_space.needs_window() || (editable.second && editable.second->needs_window()))) {
        parts->window = model.conversion_window() ? *model.conversion_window() : drivers::material_window(base);
    }
    const auto& source_path = root_table.source().path;
    parts->directory = source_path ? std::filesystem::path(*source_path).parent_path().string() : "";
    parts_ = std::move(parts);
}

bool FreeNumberCase::typed() const { return parts_->typed; }

drivers::ContactCase FreeNumberCase::build(const std::vector<double>& values) const {
    const Parts& parts = *parts_;
    bool finite = true;
    for (const double value : values) finite = finite && std::isfinite(value);
    if (!parts.typed || !finite) {  // a value that is not finite: the template's message, from where it reads it
        CaseTemplate copy = parts.model;
        for (std::size_t j = 0; j < parts.keys.size(); ++j) copy.set_number(parts.keys[j], values[j]);
        return copy.build();
    }
    Editable editable = parts.editable;
    for (std::size_t j = 0; j < parts.keys.size(); ++j) *free_number(editable, parts.keys[j]) = values[j];

    // The rules in read_case's order: the half-space's K, the indenter, the second body's K, the bodies (the second
    // first), the layer, then the case as a whole.
    drivers::ContactCase contact_case = parts.base;
    require_bulk_modulus(editable.half_space);
    if (parts.indenter) contact_case.indenter = build_indenter(*editable.indenter);
    if (editable.second) require_bulk_modulus(*editable.second);
    if (parts.material) {
        const UnitSystem& units = unit_system(contact_case.units);
        std::optional<rheology::Body> second;
        if (editable.second) second = build_body(*editable.second, parts.window, parts.directory, units);
        drivers::set_bodies(contact_case, {build_body(editable.half_space, parts.window, parts.directory, units),
                                           std::move(second)});
    }
    if (parts.layer) {
        require_layer_thickness("layer.thickness", *editable.thickness, float_text(*editable.thickness));
        contact_case.layer->thickness = *editable.thickness;
    }
    drivers::validate(contact_case);
    drivers::validate_layer(contact_case);
    return contact_case;
}

}  // namespace mdr::io
