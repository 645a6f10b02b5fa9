#pragma once
/// \file
/// How the normal load of a ContactCase is prescribed: a closed set of control types, one std::variant. Each type
/// holds exactly the data of its control, so a value of another control's (a spring constant under force control,
/// a velocity without an impact) cannot be written; each validates its own rules (drivers::validate, per type).

#include <optional>
#include <tuple>
#include <variant>
#include <vector>

#include "mdr/drivers/control_field.hpp"
#include "mdr/drivers/force_pause.hpp"
#include "mdr/drivers/shore.hpp"

namespace mdr::drivers {

/// Every control type declares `static constexpr auto fields()`: a std::tuple of its ControlField and ControlPart
/// values (control_field.hpp), in the order of its Python keywords (none: an empty tuple); so does a part that holds
/// numbers of the case file (ObliqueImpactLoad, ShoreTest), for their keys.

/// The history prescribes the depth d(t); the force follows (eq. 16).
struct DisplacementControl {
    static constexpr auto fields() { return std::tuple{}; }  ///< none
};

/// The history prescribes the force F(t) >= 0; the depth is solved for each step (eq. 19).
struct ForceControl {
    static constexpr auto fields() { return std::tuple{}; }  ///< none
};

/// The history prescribes the base z(t) of a linear spring k acting on the massless rigid indenter: F = k (z - d),
/// the spring unloaded at first contact; d is solved for each step.
struct SpringControl {
    double spring_constant = 0.0;  ///< k [N/m] > 0
    /// `load.force_pauses`: the instrument's feedback holds the force over each (ForcePause).
    std::vector<ForcePause> force_pauses{};
    /// A Shore durometer test (the durometer's spring and base history, a step at t = 0 and a stop at the full
    /// extension); the readings are measured (IndentationResult::shore). spring_constant is the durometer's.
    std::optional<ShoreTest> shore{};

    /// spring_constant and force_pauses; shore, the part a Shore test brings.
    static constexpr auto fields() {
        return std::tuple{
            control_field("spring_constant", &SpringControl::spring_constant, "N/m", "k > 0", "load.spring_constant"),
            control_field("force_pauses", &SpringControl::force_pauses, "s",
                          "pauses (start, end) over which the instrument's feedback holds the force",
                          "load.force_pauses"),
            control_part("shore", &SpringControl::shore, "", "the Shore test of a durometer's spring, or None")};
    }
};

/// The tangential part of an oblique impact of a rigid sphere (`[load] tangential_velocity`, `spin`,
/// `[indenter] moment_of_inertia`, `[tangential] friction`). The contact point, R below the centre, slides along x
/// at v_t - R omega.
struct ObliqueImpactLoad {
    double friction = 0.0;             ///< mu >= 0 (local Coulomb friction, eq. 48-50)
    double tangential_velocity = 0.0;  ///< v_t0 [m/s] of the centre along x at first contact
    double spin = 0.0;                 ///< omega0 [rad/s] at first contact
    /// I [kg m^2] about the centre; absent: a solid sphere's 2/5 m R^2 (oblique_sphere). The lever R is the
    /// indenter's: an oblique impact needs a sphere (drivers::validate).
    std::optional<double> moment_of_inertia{};

    /// Its numbers and their keys (not its Python class's: mdr.ObliqueImpact is bound by hand).
    static constexpr auto fields() {
        return std::tuple{
            control_field("friction", &ObliqueImpactLoad::friction, "", "mu >= 0", "tangential.friction"),
            control_field("tangential_velocity", &ObliqueImpactLoad::tangential_velocity, "m/s",
                          "v_t0 of the centre at first contact", "load.tangential_velocity"),
            control_field("spin", &ObliqueImpactLoad::spin, "rad/s", "omega0 at first contact", "load.spin"),
            control_field("moment_of_inertia", &ObliqueImpactLoad::moment_of_inertia, "kg m^2",
                          "I about the centre", "indenter.moment_of_inertia")};
    }
};

/// A rigid indenter of given mass and approach speed hits the surface at t = 0 (eq. 37); the case's history is
/// the single point (0, 0) and its end_time the latest end allowed.
struct ImpactControl {
    double mass = 0.0;      ///< m [kg] of the rigid indenter
    double velocity = 0.0;  ///< approach speed v0 [m/s] > 0 at first contact, t = 0
    std::optional<ObliqueImpactLoad> oblique{};  ///< an oblique impact: its tangential part

    /// mass, velocity and oblique.
    static constexpr auto fields() {
        return std::tuple{control_field("mass", &ImpactControl::mass, "kg", "m of the rigid indenter", "indenter.mass"),
                          control_field("velocity", &ImpactControl::velocity, "m/s",
                                        "the approach speed v0 > 0 at first contact", "load.velocity"),
                          control_field("oblique", &ImpactControl::oblique, "",
                                        "the tangential part of an oblique impact", "")};
    }
};

/// What the load prescribes: one of the controls, in the order of the table of controls (controls.hpp). Adding a
/// control is one new type here (its fields() make its Python class), its drivers' side (its ControlTraits: stepping,
/// rules, numerics, rows of the table, its run on a [layer]) and its reader's row (src/io/control_readers.cpp):
/// docs/architecture.md, "How to add a control"; docs/extending.md, "A control".
using LoadControl = std::variant<DisplacementControl, ForceControl, ImpactControl, SpringControl>;

}  // namespace mdr::drivers
