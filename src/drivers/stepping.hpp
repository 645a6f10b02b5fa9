#pragma once
// Pieces the drivers share: cached step coefficients, the depth solve on the foundation, and snapshots.

#include "mdr/drivers/indentation.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::drivers {

/// Step coefficients, recomputed only when the step length changes.
class CoefficientCache {
public:
    explicit CoefficientCache(const rheology::Rheology& material) : material_(material) {}
    /// The coefficients of a step of length `time_step`.
    const foundation::StepCoefficients& get(double time_step);

private:
    rheology::Rheology material_;  // a copy: the caller's material may be a temporary
    foundation::StepCoefficients coefficients_;
    bool valid_ = false;
};

/// The depth d at the end of the prepared step with F(d) + spring (d - anchor) = target, F the foundation's
/// force for a depth going linearly from `depth_start` to d (eq. 19 solved on the foundation itself; the spring
/// term carries the inertia of an impact), by solve_force_balance (depth_solve.hpp) from `guess` in steps of
/// `scale`.
double solve_depth(const foundation::Foundation& foundation, double depth_start, double guess, double scale,
                   double target, double spring, double anchor);

/// A snapshot at `time` [s] with its contact radius a [m] and radii (no profiles yet): 100 from 0 across the contact
/// and 101 from a to min(2a, `range`) [m] (the range itself without contact).
Snapshot snapshot_radii(double time, double contact_radius, double range);

/// Pressure (eq. 23) and surface displacement at `time` from the foundation's current state.
Snapshot take_snapshot(const foundation::Foundation& foundation, const profile::Profile& indenter, double time);

}  // namespace mdr::drivers
