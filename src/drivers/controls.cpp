#include "mdr/drivers/controls.hpp"

#include <algorithm>

#include "mdr/drivers/shore.hpp"
#include "mdr/error.hpp"

namespace mdr::drivers {
namespace {

// The keys several controls share.
ControlKey history(const char* unit, const char* column) {
    return {"history", unit, std::string("the (t, ") + column + ") points of a piecewise-linear history", true};
}
ControlKey harmonic(const char* amplitude_unit) {
    std::string keys;
    for (const auto& key : harmonic_keys()) {
        keys += (keys.empty() ? "" : ", ") + key.key + " [" + (key.unit.empty() ? amplitude_unit : key.unit) + "]";
    }
    return {"harmonic", "", "{ " + keys + " }: a sine added to the history; its last full cycle is measured"};
}
ControlKey end() { return {"end", "s", "the last time simulated (default: the end of the history and harmonic)"}; }

std::vector<ControlKind> rows() {
    return {
        {"displacement", "the history prescribes the depth d(t); the force follows (eq. 16)",
         "d", {history("s, m", "d"), harmonic("m"), end()}, {}},
        {"force",
         "the history prescribes the force F(t) >= 0; the depth is solved for at each step (eq. 19)", "F",
         {history("s, N", "F"), harmonic("N"), end()}, {}},
        {"impact",
         "a rigid indenter of mass m meets the surface at speed v0 at t = 0 and moves by m d'' = -F (eq. 37) until it "
         "leaves",
         "",
         {{"velocity", "m/s", "the approach speed v0 > 0 at first contact", true},
          {"end", "s", "the latest end (default: from the contact time's scales)"},
          oblique_impact_keys()[0], oblique_impact_keys()[1], oblique_impact_keys()[2]},
         {"indenter.mass"}},
        {"spring",
         "the history prescribes the base z(t) of a spring k in series with the massless indenter: F = k (z - d)", "z",
         {history("s, m", "z"),
          {"spring_constant", "N/m", "the spring's stiffness k > 0", true},
          harmonic("m"),
          {"force_pauses", "s", "[[start, end], ...]: the instrument's feedback holds the force over each"},
          end()},
         {}},
        {"shore",
         "a Shore A or D durometer (ASTM D2240, ISO 48-4): the standard's indenter pushed through its calibrated spring "
         "(spring control with a constant base); the reading H = 100 - d / 0.025 mm over time",
         "",
         {{"scale", "", "\"A\" (soft rubbers) or \"D\" (hard rubbers, plastics)", true},
          {"duration", "s",
           "how long the foot rests on the sample (default " + format_value(shore_default_duration) + ")"}},
         {}},
    };
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
    static const std::vector<ControlKind> table = rows();
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
    struct Name {
        const char* operator()(const DisplacementControl&) const { return "displacement"; }
        const char* operator()(const ForceControl&) const { return "force"; }
        const char* operator()(const SpringControl& spring) const { return spring.shore ? "shore" : "spring"; }
        const char* operator()(const ImpactControl&) const { return "impact"; }
    };
    return control_named(std::visit(Name{}, control));
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
