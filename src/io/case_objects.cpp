#include "mdr/io/case_objects.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>

#include "indenter_reader.hpp"
#include "layer_reader.hpp"
#include "material_reader.hpp"
#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/control_parts.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_assembly.hpp"
#include "mdr/io/units.hpp"
#include "part_numbers.hpp"
#include "toml_reader.hpp"

namespace mdr::io {
namespace {

// A body's materials as a sweep edits them (`prefix` its table's dotted path: `material.`, `indenter.material.`): its
// shear table, and a compressible body's bulk part, an elastic modulus (`K`) or a table (`bulk.`); each rebuilt when a
// key names one of its numbers.
struct BodyEdits {
    std::string prefix;
    MaterialSpec shear;
    std::optional<double> bulk_modulus;
    std::optional<MaterialSpec> bulk;
    bool shear_changed = false, bulk_changed = false;
};

// A case's parts as a sweep edits them: what assemble_case takes, and the values behind the parts built from them
// (the bodies' material tables, the indenter's shape, the history's points), with a flag for each of those set.
struct Edits {
    CaseParts parts;
    std::optional<BodyEdits> half_space, second;  // `[material]`, `[indenter.material]`
    std::optional<profile::ProfileDefinition> indenter;
    std::vector<drivers::LoadPoint> history, tangential_history;
    bool indenter_changed = false, history_changed = false, tangential_changed = false,
         tangential_history_changed = false, layer_changed = false;
};

// Where a key's number lives: a real number, or a count (an integer >= 1), and the flag of the part it rebuilds (none:
// a part that assemble_case takes as it is and checks, as the control, the load's harmonic or the numerics).
struct Slot {
    double* number = nullptr;
    std::size_t* count = nullptr;
    bool* changed = nullptr;
};

bool starts_with(const std::string& key, const std::string& prefix) { return key.rfind(prefix, 0) == 0; }

// The table of a body's material (`prefix` its dotted path; `bulk`: a bulk table, K for G): its model's
// definition, or the series' own.
MaterialSpec material_spec(const rheology::ModelMaterial& material, const std::string& prefix, bool bulk) {
    const rheology::ModelDefinition definition =
        material.definition ? *material.definition : rheology::series_definition(material.series);
    return MaterialSpec{&rheology::material_model(definition.model), definition.parameters, prefix, bulk,
                        definition.tolerance};
}

// True when a bulk part is an elastic modulus as `K` gives it (compressible_body: an exact elastic series, no model);
// a `[bulk]` table's material keeps its model's definition.
bool is_bulk_modulus(const rheology::ModelMaterial& bulk) {
    return !bulk.definition && bulk.series.terms().empty() && bulk.series.viscosity() == 0.0;
}

BodyEdits body_edits(const rheology::Body& body, const std::string& prefix) {
    BodyEdits edits{prefix, material_spec(body.shear, prefix, false), std::nullopt, std::nullopt};
    if (body.bulk && is_bulk_modulus(*body.bulk)) {
        edits.bulk_modulus = body.bulk->series.equilibrium_modulus();
    } else if (body.bulk) {
        edits.bulk = material_spec(*body.bulk, prefix + "bulk.", true);
    }
    return edits;
}

Edits edits_of(const drivers::ContactCase& base) {
    Edits edits;
    edits.parts = case_parts(base);
    const CaseParts& parts = edits.parts;
    if (base.bodies) {
        edits.half_space = body_edits(base.bodies->half_space, "material.");
        if (base.bodies->indenter) edits.second = body_edits(*base.bodies->indenter, "indenter.material.");
    }
    if (parts.indenter) edits.indenter = parts.indenter->definition();
    if (base.load.history) edits.history = base.load.history->points();
    if (parts.tangential && parts.tangential->load.history) {
        edits.tangential_history = parts.tangential->load.history->points();
    }
    return edits;
}

double* optional_number(std::optional<double>& value) { return value ? &*value : nullptr; }

// The number of `[numerics]` under `name` (`elements`, `layer_cells` and `output_every` are counts).
Slot numerics_slot(drivers::NumericsOptions& numerics, const std::string& name) {
    if (name == "elements") return {nullptr, numerics.elements ? &*numerics.elements : nullptr};
    if (name == "layer_cells") return {nullptr, numerics.layer_cells ? &*numerics.layer_cells : nullptr};
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

// `history[i][j]` of `points`: the time (j = 0) or value (j = 1) of point i, a change flagged in `changed`.
Slot point_slot(std::vector<drivers::LoadPoint>& points, const std::string& name, bool& changed) {
    const auto split = split_indices(name);
    if (!split || split->first != "history" || split->second.size() != 2 || split->second[1] > 1 ||
        split->second[0] >= points.size()) {
        return {};
    }
    drivers::LoadPoint& point = points[split->second[0]];
    return {split->second[1] == 0 ? &point.time : &point.value, nullptr, &changed};
}

// `load.history[i][j]`, under a control that takes a history.
Slot history_slot(Edits& edits, const std::string& name) {
    if (!drivers::control_kind(edits.parts.control).key_named("history")) return {};
    return point_slot(edits.history, name, edits.history_changed);
}

// `tangential.KEY` of a `[tangential]` load: its friction, its history's points or its harmonic's numbers (written in
// the table itself: `tangential.amplitude`).
Slot tangential_slot(Edits& edits, const std::string& name) {
    if (!edits.parts.tangential) return {};
    drivers::TangentialLoad& tangential = *edits.parts.tangential;
    if (name == "friction") return {&tangential.friction, nullptr, &edits.tangential_changed};
    if (tangential.load.history) return point_slot(edits.tangential_history, name, edits.tangential_history_changed);
    Slot found = harmonic_slot(tangential.load.harmonic, name);
    found.changed = &edits.tangential_changed;
    return found;
}

Slot snapshot_slot(std::vector<double>& snapshots, const std::string& name) {
    const auto split = split_indices(name);
    if (!split || split->first != "snapshots" || split->second.size() != 1 || split->second[0] >= snapshots.size()) {
        return {};
    }
    return {&snapshots[split->second[0]]};
}

template <class Value>
constexpr bool has_fields = requires { Value::fields(); };

template <class Field>
constexpr bool is_part = false;
template <class Control, class Value>
constexpr bool is_part<drivers::ControlPart<Control, Value>> = true;

// True when `data` holds a part that the case brings (drivers::ControlPart: a Shore test), whose fields are then the
// only keys of the control (a durometer's spring constant is the standard's, not a number of the case file).
template <class Data>
bool brings_part(const Data& data) {
    bool brought = false;
    std::apply(
        [&](const auto&... field) {
            ((brought = brought || [&](const auto& one) {
                 if constexpr (is_part<std::remove_cvref_t<decltype(one)>>) return (data.*one.member).has_value();
                 else return false;
             }(field)),
             ...);
        },
        Data::fields());
    return brought;
}

// The number under `key` of the declared fields of `data` (a control, or a part of one: drivers::ControlField, its
// case file key): a number, an optional number that is given, `KEY[i][j]` of a list of pauses; a part that is given,
// by its own fields; with a part the case brings, that part's only. With `keys` (not null) every key is listed there
// too (the rule's message names them).
template <class Data>
Slot field_slot(Data& data, const std::string& key, std::vector<std::string>* keys = nullptr) {
    Slot found;
    const bool brought = brings_part(data);
    std::apply(
        [&](const auto&... field) {
            (
                [&](const auto& one) {
                    auto& value = data.*one.member;
                    using Value = std::remove_cvref_t<decltype(value)>;
                    const bool open = !brought || is_part<std::remove_cvref_t<decltype(one)>>;
                    if constexpr (std::is_same_v<Value, double>) {
                        if (keys) keys->push_back(one.key);
                        if (open && key == one.key) found = {&value};
                    } else if constexpr (std::is_same_v<Value, std::optional<double>>) {
                        if (keys) keys->push_back(one.key);
                        if (open && key == one.key && value) found = {&*value};
                    } else if constexpr (std::is_same_v<Value, std::vector<drivers::ForcePause>>) {
                        if (keys) keys->push_back(std::string(one.key) + "[i][j]");
                        const auto split = split_indices(key);
                        if (open && split && split->first == one.key && split->second.size() == 2 &&
                            split->second[0] < value.size() && split->second[1] < 2) {
                            drivers::ForcePause& pause = value[split->second[0]];
                            found = {split->second[1] == 0 ? &pause.start : &pause.end};
                        }
                    } else if constexpr (has_fields<typename Value::value_type>) {  // an optional part
                        if (keys) {
                            typename Value::value_type part{};
                            field_slot(part, key, keys);
                        }
                        if (open && value && !found.number) found = field_slot(*value, key);
                    }
                }(field),
                ...);
        },
        Data::fields());
    return found;
}

// The number `key` names in the declared fields of the case's control.
Slot control_slot(drivers::LoadControl& control, const std::string& key) {
    return std::visit([&key](auto& data) { return field_slot(data, key); }, control);
}

// The case file keys that the controls' declared fields give numbers under, each once, in the controls' order.
std::vector<std::string> control_keys() {
    std::vector<std::string> keys;
    const auto add = [&keys](auto data) {
        std::vector<std::string> more;
        field_slot(data, "", &more);
        for (auto& key : more) {
            if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(std::move(key));
        }
    };
    [&add]<class... Controls>(std::type_identity<std::variant<Controls...>>) {
        (add(Controls{}), ...);
    }(std::type_identity<drivers::LoadControl>{});
    return keys;
}

// The number `name` (below the body's table) of a body's materials: `K`, `bulk.KEY`, `tolerance` (of a model
// converted to a series that gives one; so `bulk.tolerance`), else its shear table's.
Slot body_slot(BodyEdits& body, const std::string& name) {
    const auto tolerance = [](MaterialSpec& spec) -> double* {
        return spec.model->needs_window && spec.tolerance ? &*spec.tolerance : nullptr;
    };
    if (name == "K") return {optional_number(body.bulk_modulus), nullptr, &body.bulk_changed};
    if (starts_with(name, "bulk.")) {
        if (!body.bulk) return {};
        const std::string rest = name.substr(5);
        return {rest == "tolerance" ? tolerance(*body.bulk) : spec_number(*body.bulk, rest), nullptr,
                &body.bulk_changed};
    }
    return {name == "tolerance" ? tolerance(body.shear) : spec_number(body.shear, name), nullptr,
            &body.shear_changed};
}

// The number `key` names in the parts; an empty slot when the case has none there.
Slot slot(Edits& edits, const std::string& key) {
    CaseParts& parts = edits.parts;
    const auto rest = [&key](const std::string& prefix) { return key.substr(prefix.size()); };
    if (const Slot found = control_slot(parts.control, key); found.number) return found;
    if (starts_with(key, "indenter.material.")) {
        if (!edits.second) return {};
        return body_slot(*edits.second, rest("indenter.material."));
    }
    if (starts_with(key, "material.")) {
        if (!edits.half_space) return {};
        return body_slot(*edits.half_space, rest("material."));
    }
    if (starts_with(key, "indenter.")) {
        if (!edits.indenter) return {};
        return {profile_number(*edits.indenter, rest("indenter.")), nullptr, &edits.indenter_changed};
    }
    if (starts_with(key, "load.harmonic.")) return harmonic_slot(parts.load.harmonic, rest("load.harmonic."));
    if (key == "load.end") return {optional_number(parts.end)};
    if (starts_with(key, "load.")) return history_slot(edits, rest("load."));
    if (starts_with(key, "numerics.")) return numerics_slot(parts.numerics, rest("numerics."));
    if (starts_with(key, "output.")) return snapshot_slot(parts.snapshots, rest("output."));
    if (starts_with(key, "tangential.")) return tangential_slot(edits, rest("tangential."));
    if (key == "layer.thickness" && parts.layer) return {&parts.layer->thickness, nullptr, &edits.layer_changed};
    return {};
}

// The window a varied body's model is converted over: its own certificate's (a model converted to a series).
std::optional<rheology::TimeWindow> conversion_window(const MaterialSpec& spec, const rheology::ModelMaterial& given) {
    if (!spec.model->needs_window || !given.origin.certificate) return std::nullopt;
    return given.origin.certificate->window;
}

// `given` with the materials a key changed built again from their edited tables (a model converted to a series over
// its own certificate's window, with its tolerance) or bulk modulus (compressible_body's rule).
rheology::Body edited_body(const BodyEdits& edits, const rheology::Body& given, const UnitSystem& units) {
    rheology::Body body = given;
    if (edits.shear_changed) {
        body.shear = build_material(edits.shear, conversion_window(edits.shear, given.shear), "", units);
    }
    if (edits.bulk_changed && edits.bulk_modulus) {
        body.bulk = compressible_body(body.shear, edits.bulk_modulus, std::nullopt, edits.prefix).bulk;
    } else if (edits.bulk_changed) {
        body.bulk = build_material(*edits.bulk, conversion_window(*edits.bulk, *given.bulk), "", units);
    }
    return body;
}

}  // namespace

CaseParts case_parts(const drivers::ContactCase& contact_case) {
    CaseParts parts;
    parts.title = contact_case.title;
    parts.units = contact_case.units;
    // A durometer's standard indenter is brought again by its control.
    parts.indenter = drivers::brought_by(contact_case.control).indenter ? nullptr : contact_case.indenter;
    parts.control = contact_case.control;
    parts.load = contact_case.load;
    if (contact_case.end_given) parts.end = contact_case.end_time;  // else the default end, which follows the load
    parts.snapshots = contact_case.snapshots;
    parts.numerics = contact_case.numerics;
    parts.tangential = contact_case.tangential;
    parts.layer = contact_case.layer;
    return parts;
}

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
    std::string controls;
    for (const std::string& key : control_keys()) controls += (controls.empty() ? "" : ", ") + key;
    return "no such numeric key among those a case of objects sweeps (the numbers of its material and indenter "
           "definitions, a body's K, bulk.* and a converted model's tolerance where given, its control's (" +
           controls +
           ") where its control has them, load.history[i][j], load.harmonic.*, load.end where given, "
           "output.snapshots[i], a [tangential] load's tangential.friction, tangential.history[i][j] or "
           "tangential.amplitude, frequency, start and end, layer.thickness, numerics.*)";
}

drivers::ContactCase CaseObjects::build(const std::vector<std::string>& keys, const std::vector<double>& values) const {
    if (keys.empty()) return base_;
    Edits edits = edits_of(base_);
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
        if (found.changed != nullptr) *found.changed = true;
    }
    CaseParts& parts = edits.parts;
    // The rules of the parts rebuilt, as the case file's reader checks them before assembling the case.
    if (edits.indenter_changed) parts.indenter = build_indenter(*edits.indenter);
    if (edits.history_changed) parts.load.history = drivers::LoadHistory(edits.history, "load.history");
    if (edits.tangential_history_changed) {
        parts.tangential->load.history = drivers::LoadHistory(edits.tangential_history, "tangential.history");
    }
    if (edits.tangential_changed || edits.tangential_history_changed) drivers::validate(*parts.tangential);
    if (edits.layer_changed) {
        require_layer_thickness("layer.thickness", parts.layer->thickness, float_text(parts.layer->thickness));
    }
    const rheology::ContactBodies& given = *base_.bodies;
    const UnitSystem& units = unit_system(parts.units);
    return assemble_case(std::move(parts), [&](CaseParts&) {
        rheology::ContactBodies bodies = given;  // the parts not varied, as they are
        bodies.half_space = edited_body(*edits.half_space, given.half_space, units);
        if (edits.second) bodies.indenter = edited_body(*edits.second, *given.indenter, units);
        return bodies;
    });
}

}  // namespace mdr::io
