#include "mdr/drivers/controls.hpp"

#include "mdr/error.hpp"

namespace mdr::drivers {
namespace {

std::vector<ControlKind> rows() {
    return {
        {Control::displacement, "displacement", "the history prescribes the depth d(t); the force follows (eq. 16)",
         "d", {"load.history"}},
        {Control::force, "force",
         "the history prescribes the force F(t) >= 0; the depth is solved for at each step (eq. 19)", "F",
         {"load.history"}},
        {Control::impact, "impact",
         "a rigid indenter of mass m meets the surface at speed v0 at t = 0 and moves by m d'' = -F (eq. 37) until it "
         "leaves",
         "", {"load.velocity", "indenter.mass"}},
        {Control::spring, "spring",
         "the history prescribes the base z(t) of a spring k in series with the massless indenter: F = k (z - d)", "z",
         {"load.history", "load.spring_constant"}},
        // After "spring": control_kind(Control::spring) is the plain spring.
        {Control::spring, "shore",
         "a Shore A or D durometer (ASTM D2240, ISO 48-4): the standard's indenter pushed through its calibrated spring "
         "(spring control with a constant base); the reading H = 100 - d / 0.025 mm over time",
         "", {"load.scale"}},
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

const std::vector<ControlKind>& controls() {
    static const std::vector<ControlKind> table = rows();
    return table;
}

const ControlKind& control_named(const std::string& name) {
    std::string names;
    for (const ControlKind& kind : controls()) {
        if (kind.name == name) return kind;
        names += (names.empty() ? "" : ", ") + kind.name;
    }
    throw InvalidInput("control", "\"" + name + "\"", "unknown control; one of " + names);
}

const ControlKind& control_kind(Control control) {
    for (const ControlKind& kind : controls()) {
        if (kind.control == control) return kind;
    }
    throw InvalidInput("control", std::to_string(static_cast<int>(control)), "is not a control of the table");
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
