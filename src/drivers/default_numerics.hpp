#pragma once
// The pieces of the default numerics (resolve_numerics, contact_case.hpp) that the ControlTraits of the controls
// (control_traits.hpp) use: internal to the drivers.

#include <functional>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::drivers {

/// The largest contact radius [m] under force control at a force [N]: the elastic radius with the softest modulus
/// 1/J(t_end - t_start), 25% margin; 0 without a force.
using ForceRadiusBound = std::function<double(double force)>;

/// The largest contact radius [m] of a history-driven control whose history (its harmonic added) peaks at `peak`,
/// given the force-control bound; 0 when none is known (the indenter's radius is taken).
using ContactRadiusBound = std::function<double(double peak, const ForceRadiusBound& force_bound)>;

/// The default numerics of a history-driven control (resolve_numerics): steps graded after the start and fast load
/// changes when `graded` (a control that solves for the depth: its creep is singular there), towards each zero of a
/// falling force when `graded_towards_zeros` (force control: the contact ends there; ResolvedNumerics::
/// zero_grading_exponent), the half-width from `largest_contact_radius` unless the indenter is a flat punch or
/// `[numerics] half_width` is given.
ResolvedNumerics resolve_history_numerics(const ContactCase& contact_case, bool graded, bool graded_towards_zeros,
                                          const ContactRadiusBound& largest_contact_radius);

/// The shortest material time (relaxation or retardation) that is at least `floor` [s]; infinity if none.
double shortest_time_above(const rheology::Rheology& material, double floor);

}  // namespace mdr::drivers
