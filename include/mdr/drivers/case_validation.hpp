#pragma once
/// \file
/// The rules of a contact problem, checked in the library: a ContactCase built in C++ gets the same
/// `key = value: rule` errors (mdr::InvalidInput, keys named as in the case file) as the command line.

#include <string>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/tangential_load.hpp"

namespace mdr::drivers {

/// Checks a tangential load: friction finite and >= 0 (`tangential.friction`); exactly one of a history (starting
/// at 0, without jumps) or a harmonic (finite amplitude, frequency > 0, end after start).
void validate(const TangentialLoad& load);

/// Checks a harmonic load: finite amplitude, frequency > 0, finite start and an end after it; keys are named
/// `prefix` + field (`tangential.`, `load.harmonic.`).
void validate(const HarmonicLoad& harmonic, const std::string& prefix);
/// The tangential velocity [m/s] of an impact at normal speed `velocity` [m/s] whose velocity makes `incidence_deg`
/// with the surface normal: velocity tan(incidence). Throws mdr::InvalidInput (`load.incidence_deg`) outside
/// [0, 90).
double incidence_velocity(double velocity, double incidence_deg);

/// Checks a contact problem: an indenter and a load history, then the rules of its control type (LoadControl, each
/// type's own, src/drivers/control_traits.hpp; a value of another control cannot be written): for an impact a mass and an
/// approach speed > 0 and no tangential load; for an oblique impact friction >= 0, finite tangential velocity and spin,
/// a sphere, a positive moment of inertia when one is given, one incompressible body (tangential_exact); under force
/// control no negative force; under displacement control no jump against a dashpot; an end after the first history time
/// (finite unless an impact); snapshots within the simulated time; positive numerics. A normal harmonic (not with an
/// impact): amplitude > 0, starting no earlier than the history, and under force control no larger than the smallest
/// history force during it. Spring control: a spring constant > 0, a base history starting at or above the surface (z
/// <= 0) without jumps; force pauses (a spring without durometer) in time order and apart, each starting after the
/// history's first time, ending after its start and by the end, and not overlapping a harmonic. A Shore test: a
/// duration > 0, spring control with the durometer's spring, no harmonic and no tangential load. A model converted to
/// a series (certificate kind "model": a power law, a springpot) certified over the case's lags and harmonic
/// frequencies (require_certified_over of material_window; key `material`). Called by resolve_numerics, so every
/// driver runs only valid problems.
void validate(const ContactCase& contact_case);

}  // namespace mdr::drivers
