#pragma once
// An impact's step by the trapezoidal rule (eq. 37), the end of its contact (eq. 39) and its normal outcome: one rule
// for the half-space (ImpactStepping) and the layer (LayerImpactStepping, LayerCellsImpactStepping).

#include "mdr/drivers/indentation.hpp"

namespace mdr::drivers {

/// The trapezoidal rule of eq. 37 for m d'' = -F over a step dt, d1 = d0 + (v0 + v1) dt/2, v1 = v0 - (F0 + F1)
/// dt/(2m), solved as F(d1) + k (d1 - d0 - v0 dt) = -F0: its inertial stiffness k = 4m/dt^2 [N/m].
inline double inertial_stiffness(double mass, double time_step) { return 4.0 * mass / (time_step * time_step); }

/// The same rule's velocity at the step's end, v1 = 2 (d1 - d0)/dt - v0 [m/s].
inline double trapezoidal_velocity(double depth, double new_depth, double velocity, double time_step) {
    return 2.0 * (new_depth - depth) / time_step - velocity;
}

/// Throws mdr::InvalidInput (key `load.end`) when an impact at `time` [s] has reached `time_limit` [s] (the latest end,
/// ResolvedNumerics::time_limit) still in contact, the indenter at `velocity` [m/s].
void require_before_end(double time, double time_limit, double velocity);

/// The part of an impact done at `time` [s] (StepState::fraction, its progress reports): 1 once it has `ended`;
/// before, 0.9 of it over the expected end of contact (ResolvedNumerics::expected_end) and the rest from there to the
/// time limit, so that it keeps moving, and stays below 1, in a contact that lasts longer than expected.
double impact_progress(double time, bool ended, const ResolvedNumerics& numerics);

/// The step of an impact in which its last contact was lost.
struct ImpactEnd {
    double mass = 0.0;       ///< m [kg]
    double approach = 0.0;   ///< v0 [m/s], the velocity at first contact
    double time = 0.0;       ///< when the step began [s]
    double time_step = 0.0;  ///< the step's length [s]
    double velocity = 0.0;   ///< v at the step's start [m/s], positive into the surface
    double force = 0.0;      ///< F at the step's start [N]
    double fraction = 0.0;   ///< where in the step the last contact was lost, 0..1
};

/// The normal outcome of the impact that ended in `end`: the impulse of the step's part in contact taken as a linear
/// decay of the force, v(T) = v - F fraction dt / (2m) (the trapezoidal rule of eq. 37 up to the loss); the contact
/// time T = time + fraction dt, the rebound velocity -v(T), the restitution e = -v(T)/v0 and the kinetic energy lost
/// m (v0^2 - v(T)^2)/2 (eq. 39). Throws std::runtime_error when e lies outside [0, 1] beyond round-off: a passive body
/// returns at most the energy it was given and the indenter leaves, so anything else is a failure of the numerics.
ImpactOutcome impact_outcome(const ImpactEnd& end);

}  // namespace mdr::drivers
