#pragma once
/// \file
/// How the normal load of a ContactCase is prescribed: a closed set of control types, one std::variant. Each type
/// holds exactly the data of its control, so a value of another control's (a spring constant under force control,
/// a velocity without an impact) cannot be written; each validates its own rules (drivers::validate, per type).

#include <optional>
#include <variant>
#include <vector>

#include "mdr/drivers/force_pause.hpp"
#include "mdr/drivers/shore.hpp"

namespace mdr::drivers {

/// The history prescribes the depth d(t); the force follows (eq. 16).
struct DisplacementControl {};

/// The history prescribes the force F(t) >= 0; the depth is solved for each step (eq. 19).
struct ForceControl {};

/// The history prescribes the base z(t) of a linear spring k acting on the massless rigid indenter: F = k (z - d),
/// the spring unloaded at first contact; d is solved for each step.
struct SpringControl {
    double spring_constant = 0.0;  ///< k [N/m] > 0
    /// `load.force_pauses`: the instrument's feedback holds the force over each (ForcePause).
    std::vector<ForcePause> force_pauses{};
    /// A Shore durometer test (the durometer's spring and base history, a step at t = 0 and a stop at the full
    /// extension); the readings are measured (IndentationResult::shore). spring_constant is the durometer's.
    std::optional<ShoreTest> shore{};
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
};

/// A rigid indenter of given mass and approach speed hits the surface at t = 0 (eq. 37); the case's history is
/// the single point (0, 0) and its end_time the latest end allowed.
struct ImpactControl {
    double mass = 0.0;      ///< m [kg] of the rigid indenter
    double velocity = 0.0;  ///< approach speed v0 [m/s] > 0 at first contact, t = 0
    std::optional<ObliqueImpactLoad> oblique{};  ///< an oblique impact: its tangential part
};

/// What the load prescribes: one of the controls, in the order of the table of controls (controls.hpp). Adding a
/// control is one new type here, its drivers' side (its ControlTraits: stepping, rules, numerics, rows of the table),
/// its reader's row (src/io/control_readers.cpp) and its Python class: docs/architecture.md, "How to add a control".
using LoadControl = std::variant<DisplacementControl, ForceControl, ImpactControl, SpringControl>;

}  // namespace mdr::drivers
