#include "mdr/drivers/controls.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>
#include <variant>

#include "mdr/error.hpp"
#include "control_keys.hpp"
#include "every_control.hpp"

namespace mdr::drivers {

ControlKey history_key(const char* unit, const char* column) {
    return {"history", unit, std::string("the (t, ") + column + ") points of a piecewise-linear history", true};
}

ControlKey harmonic_key(const char* amplitude_unit) {
    std::string keys;
    for (const auto& key : harmonic_keys()) {
        keys += (keys.empty() ? "" : ", ") + key.key + " [" + (key.unit.empty() ? amplitude_unit : key.unit) + "]";
    }
    return {"harmonic", "", "{ " + keys + " }: a sine added to the history; its last full cycle is measured"};
}

ControlKey end_key() { return {"end", "s", "the last time simulated (default: the end of the history and harmonic)"}; }

namespace {

// The rows of the types of LoadControl (each its ControlTraits' rows), in the variant's order.
template <class... Control>
std::vector<ControlKind> rows_of(std::type_identity<std::variant<Control...>> /*types*/) {
    std::vector<ControlKind> table;
    const auto append = [&table](std::vector<ControlKind> rows) {
        for (ControlKind& row : rows) table.push_back(std::move(row));
    };
    (append(ControlTraits<Control>::rows()), ...);
    return table;
}

std::vector<TangentialControlKind> tangential_rows() {
    return {
        {TangentialControl::displacement, "displacement",
         "the history (or harmonic) prescribes the indenter's tangential displacement u(t); F_x follows (eq. 46)", "u"},
        {TangentialControl::force, "force",
         "the history (or harmonic) prescribes the tangential force F_x(t); u is solved for at each step", "Fx"},
    };
}

}  // namespace

const std::vector<ControlKey>& oblique_impact_keys() {
    static const std::vector<ControlKey> keys{
        {"tangential_velocity", "m/s", "an oblique impact: the centre's tangential speed at first contact"},
        {"incidence_deg", "deg", "an oblique impact: the angle of the velocity from the normal (instead of "
                                 "tangential_velocity)"},
        {"spin", "rad/s", "an oblique impact: the sphere's spin at first contact"},
    };
    return keys;
}

const std::vector<ControlKey>& harmonic_keys() {
    static const std::vector<ControlKey> keys{
        {"amplitude", "", "of the sine, amplitude sin(2 pi frequency (t - start)); > 0 in load.harmonic", true},
        {"frequency", "Hz", "> 0", true},
        {"start", "s", "the sine starts from 0 here", true},
        {"end", "s", "> start; the value reached is held after it", true},
    };
    return keys;
}

std::vector<std::string> harmonic_key_names() {
    std::vector<std::string> names;
    for (const auto& key : harmonic_keys()) names.push_back(key.key);
    return names;
}

const std::vector<ControlKind>& controls() {
    static const std::vector<ControlKind> table = rows_of(std::type_identity<LoadControl>{});
    return table;
}

const ControlKey* ControlKind::key_named(const std::string& key) const {
    for (const ControlKey& entry : keys) {
        if (entry.key == key) return &entry;
    }
    return nullptr;
}

std::vector<std::string> load_keys() {
    std::vector<std::string> names{"control"};
    for (const ControlKind& kind : controls()) {
        for (const ControlKey& entry : kind.keys) {
            if (std::find(names.begin(), names.end(), entry.key) == names.end()) names.push_back(entry.key);
        }
    }
    return names;
}

const ControlKind& control_named(const std::string& name) {
    std::string names;
    for (const ControlKind& kind : controls()) {
        if (kind.name == name) return kind;
        names += (names.empty() ? "" : ", ") + kind.name;
    }
    throw InvalidInput("control", "\"" + name + "\"", "unknown control; one of " + names);
}

const ControlKind& control_kind(const LoadControl& control) {
    return control_named(
        visit_control(control, [](auto traits, const auto& data) -> std::string { return traits.row_name(data); }));
}

}  // namespace mdr::drivers

namespace mdr::drivers {

const std::vector<TangentialControlKind>& tangential_controls() {
    static const std::vector<TangentialControlKind> table = tangential_rows();
    return table;
}

const TangentialControlKind& tangential_control_named(const std::string& name) {
    std::string names;
    for (const TangentialControlKind& kind : tangential_controls()) {
        if (kind.name == name) return kind;
        names += (names.empty() ? "" : ", ") + kind.name;
    }
    throw InvalidInput("tangential.control", "\"" + name + "\"", "unknown control; one of " + names);
}

const TangentialControlKind& tangential_control_kind(TangentialControl control) {
    for (const TangentialControlKind& kind : tangential_controls()) {
        if (kind.control == control) return kind;
    }
    throw InvalidInput("tangential.control", std::to_string(static_cast<int>(control)),
                       "is not a control of the table");
}

}  // namespace mdr::drivers
