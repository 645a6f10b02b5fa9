#include "mdr/io/case_objects.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "indenter_reader.hpp"
#include "layer_reader.hpp"
#include "material_reader.hpp"
#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/control_end.hpp"
#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_assembly.hpp"
#include "mdr/io/units.hpp"
#include "part_numbers.hpp"
#include "toml_reader.hpp"

namespace mdr::io {
namespace {

// The parts of a case that a key rebuilds from its edited values; the others are given to assemble_case as they are.
enum class Part { other, material, indenter_material, indenter, history, layer, tangential };

// A case's parts as a sweep edits them: what assemble_case takes, and the values behind the parts built from them
// (the bodies' material tables, the indenter's shape, the history's points).
struct Edits {
    CaseParts parts;
    std::optional<MaterialSpec> half_space, second;  // the shear materials of `[material]`, `[indenter.material]`
    std::optional<profile::ProfileDefinition> indenter;
    std::vector<drivers::LoadPoint> history;
};

// Where a key's number lives: a real number, or a count (an integer >= 1), and the part it belongs to.
struct Slot {
    double* number = nullptr;
    std::size_t* count = nullptr;
    Part part = Part::other;
};

bool starts_with(const std::string& key, const std::string& prefix) { return key.rfind(prefix, 0) == 0; }

// The table of a body's shear material (`prefix` its dotted path): its model's definition, or the series' own.
MaterialSpec material_spec(const rheology::ModelMaterial& material, const std::string& prefix) {
    const rheology::ModelDefinition definition =
        material.definition ? *material.definition : rheology::series_definition(material.series);
    return MaterialSpec{&rheology::material_model(definition.model), definition.parameters, prefix, false,
                        definition.tolerance};
}

// The end of `base` as its parts give it: none when it is the default of its load (default_end_time), which then
// follows the load as it is changed, as a case file without `load.end`.
std::optional<double> given_end(const drivers::ContactCase& base) {
    if (!base.load.history) return base.end_time;
    if (base.end_time == default_end_time(base.load, drivers::ends_by_stop_rule(base.control), base.tangential)) {
        return std::nullopt;
    }
    return base.end_time;
}

Edits edits_of(const drivers::ContactCase& base) {
    Edits edits;
    CaseParts& parts = edits.parts;
    parts.title = base.title;
    parts.units = base.units;
    parts.indenter = drivers::brought_by(base.control).indenter ? nullptr : base.indenter;  // a durometer's standard
    parts.control = base.control;
    parts.load = base.load;
    parts.end = given_end(base);
    parts.snapshots = base.snapshots;
    parts.numerics = base.numerics;
    parts.tangential = base.tangential;
    parts.layer = base.layer;
    if (base.bodies) {
        edits.half_space = material_spec(base.bodies->half_space.shear, "material.");
        if (base.bodies->indenter) edits.second = material_spec(base.bodies->indenter->shear, "indenter.material.");
    }
    if (parts.indenter) edits.indenter = parts.indenter->definition();
    if (base.load.history) edits.history = base.load.history->points();
    return edits;
}

double* optional_number(std::optional<double>& value) { return value ? &*value : nullptr; }

// The number of `[numerics]` under `name` (`elements` and `output_every` are counts).
Slot numerics_slot(drivers::NumericsOptions& numerics, const std::string& name) {
    if (name == "elements") return {nullptr, numerics.elements ? &*numerics.elements : nullptr};
    if (name == "output_every") return {nullptr, &numerics.output_every};
    if (name == "time_step") return {optional_number(numerics.time_step)};
    if (name == "half_width") return {optional_number(numerics.half_width)};
    if (name == "max_element_steps") return {optional_number(numerics.max_element_steps)};
    if (name == "max_memory") return {optional_number(numerics.max_memory)};
    return {};
}

// The number of `[load] harmonic` under `name`.
Slot harmonic_slot(std::optional<drivers::HarmonicLoad>& harmonic, const std::string& name) {
    if (!harmonic) return {};
    if (name == "amplitude") return {&harmonic->amplitude};
    if (name == "frequency") return {&harmonic->frequency};
    if (name == "start") return {&harmonic->start};
    if (name == "end") return {&harmonic->end};
    return {};
}

// `history[i][j]`: the time (j = 0) or value (j = 1) of point i, under a control that takes a history.
Slot history_slot(Edits& edits, const std::string& name) {
    const auto split = split_indices(name);
    if (!split || split->first != "history" || split->second.size() != 2 || split->second[1] > 1 ||
        split->second[0] >= edits.history.size() || !drivers::control_kind(edits.parts.control).key_named("history")) {
        return {};
    }
    drivers::LoadPoint& point = edits.history[split->second[0]];
    return {split->second[1] == 0 ? &point.time : &point.value, nullptr, Part::history};
}

Slot snapshot_slot(std::vector<double>& snapshots, const std::string& name) {
    const auto split = split_indices(name);
    if (!split || split->first != "snapshots" || split->second.size() != 1 || split->second[0] >= snapshots.size()) {
        return {};
    }
    return {&snapshots[split->second[0]]};
}

// The number `key` names in the parts; an empty slot when the case has none there.
Slot slot(Edits& edits, const std::string& key) {
    CaseParts& parts = edits.parts;
    const auto rest = [&key](const std::string& prefix) { return key.substr(prefix.size()); };
    if (starts_with(key, "indenter.material.")) {
        if (!edits.second) return {};
        return {spec_number(*edits.second, rest("indenter.material.")), nullptr, Part::indenter_material};
    }
    if (starts_with(key, "material.")) {
        if (!edits.half_space) return {};
        return {spec_number(*edits.half_space, rest("material.")), nullptr, Part::material};
    }
    if (starts_with(key, "indenter.")) {
        if (!edits.indenter) return {};
        return {profile_number(*edits.indenter, rest("indenter.")), nullptr, Part::indenter};
    }
    if (starts_with(key, "load.harmonic.")) return harmonic_slot(parts.load.harmonic, rest("load.harmonic."));
    if (key == "load.end") return {optional_number(parts.end)};
    if (starts_with(key, "load.")) return history_slot(edits, rest("load."));
    if (starts_with(key, "numerics.")) return numerics_slot(parts.numerics, rest("numerics."));
    if (starts_with(key, "output.")) return snapshot_slot(parts.snapshots, rest("output."));
    if (key == "tangential.friction" && parts.tangential) return {&parts.tangential->friction, nullptr,
                                                                   Part::tangential};
    if (key == "layer.thickness" && parts.layer) return {&parts.layer->thickness, nullptr, Part::layer};
    return {};
}

// The window a varied body's model is converted over: its own certificate's (a model converted to a series).
std::optional<rheology::TimeWindow> conversion_window(const MaterialSpec& spec, const rheology::ModelMaterial& given) {
    if (!spec.model->needs_window || !given.origin.certificate) return std::nullopt;
    return given.origin.certificate->window;
}

}  // namespace

CaseObjects::CaseObjects(drivers::ContactCase base) : base_(std::move(base)) {
    if (!base_.bodies) {
        throw InvalidInput("case", "(no bodies)", "a case given as objects keeps its bodies (io::assemble_case)");
    }
}

bool CaseObjects::has_number(const std::string& key) const {
    Edits edits = edits_of(base_);
    const Slot found = slot(edits, key);
    return found.number != nullptr || found.count != nullptr;
}

std::string CaseObjects::numbers_rule() const {
    return "no such numeric key among those a case of objects sweeps (the numbers of its material and indenter "
           "definitions, load.history[i][j], load.harmonic.*, load.end, output.snapshots[i], tangential.friction of a "
           "[tangential] load (an oblique impact's is its control's), layer.thickness, numerics.*; a control's own "
           "keys, the bulk's and a converted model's tolerance are swept from the case file or dict)";
}

drivers::ContactCase CaseObjects::build(const std::vector<std::string>& keys, const std::vector<double>& values) const {
    if (keys.empty()) return base_;
    Edits edits = edits_of(base_);
    bool material = false, indenter_material = false, indenter = false, history = false, layer = false,
         tangential = false;
    for (std::size_t a = 0; a < keys.size(); ++a) {
        const Slot found = slot(edits, keys[a]);
        if (found.number == nullptr && found.count == nullptr) {  // CaseTemplate::set_number's rule
            throw InvalidInput(keys[a], "(missing)", "the case has no number under this key");
        }
        require_finite(keys[a], values[a]);
        if (found.count != nullptr) {  // TableReader::optional_count's rule
            if (!(values[a] >= 1.0 && values[a] < 0x1p53) || values[a] != std::floor(values[a])) {
                throw InvalidInput(keys[a], float_text(values[a]), "must be an integer >= 1");
            }
            *found.count = static_cast<std::size_t>(values[a]);
        } else {
            *found.number = values[a];
        }
        material = material || found.part == Part::material;
        indenter_material = indenter_material || found.part == Part::indenter_material;
        indenter = indenter || found.part == Part::indenter;
        history = history || found.part == Part::history;
        layer = layer || found.part == Part::layer;
        tangential = tangential || found.part == Part::tangential;
    }
    CaseParts& parts = edits.parts;
    // The rules of the parts rebuilt, as the case file's reader checks them before assembling the case.
    if (indenter) parts.indenter = build_indenter(*edits.indenter);
    if (history) parts.load.history = drivers::LoadHistory(edits.history, "load.history");
    if (tangential) drivers::validate(*parts.tangential);
    if (layer) {
        require_layer_thickness("layer.thickness", parts.layer->thickness, float_text(parts.layer->thickness));
    }
    const rheology::ContactBodies& given = *base_.bodies;
    const UnitSystem& units = unit_system(parts.units);
    return assemble_case(std::move(parts), [&](CaseParts&) {
        rheology::ContactBodies bodies = given;  // the parts not varied, as they are
        if (material) {
            bodies.half_space.shear = build_material(
                *edits.half_space, conversion_window(*edits.half_space, given.half_space.shear), "", units);
        }
        if (indenter_material) {
            bodies.indenter->shear = build_material(
                *edits.second, conversion_window(*edits.second, given.indenter->shear), "", units);
        }
        return bodies;
    });
}

}  // namespace mdr::io
