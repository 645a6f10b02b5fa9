#pragma once
/// \file
/// The normal-contact driver: displacement, force or spring control along a piecewise-linear history with an
/// optional harmonic part (section 5).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/load_history.hpp"
#include "mdr/drivers/step_observer.hpp"

namespace mdr::drivers {

/// Pressure (eq. 23) and surface displacement (eq. 10 applied to w1D) of the 3D contact at one time.
struct Snapshot {
    double time = 0.0;                  ///< t [s]
    double contact_radius = 0.0;        ///< a [m]
    std::vector<double> radius;         ///< r [m], from 0 to 2a (or the half-width without contact)
    std::vector<double> pressure;       ///< p(r) [Pa]; 0 for r > a
    std::vector<double> displacement;   ///< normal surface displacement w(r) [m], positive into the body
    std::vector<double> shear_stress;   ///< tau_xz(r) [Pa] (eq. 47) with tangential loading, else empty
};

/// The tangential outcome of an oblique impact (handbook section 6 with m v_t' = -F_x, I omega' = R F_x). The
/// contact point slides at v_c = v_t - R omega.
struct ObliqueOutcome {
    double tangential_restitution = 0.0;       ///< -v_c(T) / v_c(0) (0 when v_c(0) = 0)
    double rebound_tangential_velocity = 0.0;  ///< v_t(T) [m/s] of the centre
    double rebound_spin = 0.0;                 ///< omega(T) [rad/s]
    double rebound_angle = 0.0;                ///< atan(v_t(T) / (-v(T))) [deg], from the normal
    double impulse_ratio = 0.0;                ///< tangential over normal impulse, int F_x dt / int F dt
    bool slid_throughout = false;              ///< every element in contact slipped at every step
    double max_tangential_force = 0.0;         ///< largest |F_x| [N]
    double material_dissipation = 0.0;         ///< work [J] of the normal and tangential forces on the elements
    double friction_dissipation = 0.0;         ///< work [J] of the element forces on the slip, sum mu F_N,i |slip_i|
};

/// The outcome of an impact (eq. 39).
struct ImpactOutcome {
    double restitution = 0.0;        ///< e = -v(T)/v0
    double contact_time = 0.0;       ///< T [s], when the axis leaves contact (the exits of the two innermost
                                     ///< elements extrapolated to it, Foundation::axis_weight)
    double rebound_velocity = 0.0;   ///< -v(T) [m/s], positive away from the surface
    double dissipated_energy = 0.0;  ///< kinetic energy lost [J]: m (v0^2 - v(T)^2) / 2, plus the tangential and
                                     ///< rotational part in an oblique impact
    std::optional<ObliqueOutcome> oblique{};  ///< oblique impact only
};

/// The outcome of a tangential loading (handbook section 6).
struct TangentialOutcome {
    double max_force = 0.0;                             ///< largest |F_x| [N] over the run
    std::optional<double> min_stick_radius;             ///< smallest stick radius c [m] (eq. 51) over the last full
                                                        ///< harmonic cycle
    std::optional<double> dissipated_energy_per_cycle;  ///< loop area of F_x du [J] over that cycle
    std::optional<double> sliding_from;                 ///< force control: time [s] from which |F_x| > mu F_N, the
                                                        ///< contact slides as a whole (gross sliding)
};

/// The response to a harmonic normal load over its last full cycle [t1, t1 + T], from the first harmonics
/// X = (2/T) int x(t) exp(-i omega (t - start)) dt of depth and force (trapezoidal rule on the uniform steps of the
/// cycle, exact for the sine), so that x ~ Re(X exp(i omega (t - start))) plus the mean and higher harmonics. The
/// complex contact stiffness is k = F / D = k' + i k'' (eq. 12 summed over the contact: 8 a G(omega) for a small
/// amplitude on an incompressible body).
struct HarmonicOutcome {
    double depth_amplitude = 0.0;              ///< |D| [m]
    double force_amplitude = 0.0;              ///< |F| [N]
    double phase = 0.0;                        ///< arg(F / D) [rad]: how far the force leads the depth
    std::optional<double> storage_stiffness;   ///< k' = Re(F / D) [N/m] (none when D = 0)
    std::optional<double> loss_stiffness;      ///< k'' = Im(F / D) [N/m] (none when D = 0)
    std::optional<double> loss_tangent;        ///< k'' / k' (none when k' = 0 or D = 0)
    double dissipated_energy = 0.0;            ///< the loop area, closed integral of F dd over the cycle [J]
    double contact_loss_fraction = 0.0;        ///< fraction of the cycle without any element in contact
};

/// What a run produced: one row per written step.
struct IndentationResult {
    std::vector<double> time;      ///< t [s]
    std::vector<double> depth;     ///< d [m]
    std::vector<double> force;     ///< F [N]
    std::vector<double> radius;    ///< a [m]
    std::vector<double> velocity;  ///< indenter velocity v = dd/dt [m/s] (impact only, else empty)
    std::vector<double> tangential_displacement;  ///< u [m] (tangential loading only, else empty)
    std::vector<double> tangential_force;         ///< F_x [N] (eq. 46; tangential loading only, else empty)
    std::vector<double> stick_radius;             ///< c [m] (eq. 51; tangential loading only, else empty)
    std::vector<double> base;                     ///< base displacement z [m] (spring control only, else empty)
    std::vector<double> shore;                    ///< Shore reading H (Shore test only, else empty)
    std::vector<double> tangential_velocity;      ///< v_t [m/s] of the centre (oblique impact only, else empty)
    std::vector<double> spin;                     ///< omega [rad/s] (oblique impact only, else empty)
    std::vector<Snapshot> snapshots;
    std::optional<ImpactOutcome> impact;  ///< impact only
    std::optional<TangentialOutcome> tangential;  ///< tangential loading only
    std::optional<HarmonicOutcome> harmonic;      ///< harmonic normal load with at least one full cycle only
    std::vector<ShoreReading> shore_readings;     ///< Shore test: the readings at shore_reading_times within it
    ResolvedNumerics numerics;     ///< what was used
    std::size_t steps = 0;         ///< time steps taken
    bool stopped = false;          ///< a StepObserver ended the run early (then without impact, tangential and
                                   ///< harmonic outcomes)
};

/// Called each time another hundredth of the run is done, with the fraction done (0..1, StepState::fraction); it may
/// throw to abandon the run.
using ProgressObserver = std::function<void(double fraction)>;

/// The time grid run_indentation steps a displacement-, force- or spring-controlled case along, with `numerics`
/// its resolve_numerics: make_time_grid with a node at every snapshot, tangential and harmonic breakpoint, Shore
/// reading and force pause, graded after fast load changes (grade_after_changes), the harmonic part added.
/// Throws mdr::InvalidInput for an impact, which has no history grid.
std::vector<GridNode> indentation_grid(const ContactCase& contact_case, const ResolvedNumerics& numerics);

/// Runs a case on the half-space under any control, each step by the control's stepping class in one loop:
/// - displacement, force or spring control along the history's grid (indentation_grid), with its tangential
///   loading when it has one (after each normal step the tangential layer takes the step's tangential increment);
/// - an impact (control = impact): m d'' = -F_N (eq. 37) with the trapezoidal rule, implicit in the depth and solved
///   on the foundation each step (second order, no stability limit), with its oblique part, until the last element
///   has left contact (eq. 39).
/// The state after every step goes to the standard observers, which fill the result, then to `observers`
/// (step_observer.hpp). Throws mdr::InvalidInput for problems found while running (the contact outgrowing the
/// foundation; key `tangential` when the tangential load changes while no element is in normal contact; key
/// `load.end` when an impact's contact does not end before `end_time`).
IndentationResult run_indentation(const ContactCase& contact_case, const ProgressObserver& progress = {},
                                  const StepObservers& observers = {});

/// Throws std::runtime_error naming the first value of `result` that is not finite (a column at a time, a snapshot,
/// one of its outcomes()), so that no NaN or infinity is ever reported as a result.
void require_finite_result(const IndentationResult& result);

/// Runs any case: run_layer_indentation for a case with a layer, run_indentation otherwise, with the caller's
/// `observers` after the standard ones; the result is checked with require_finite_result.
IndentationResult run_case(const ContactCase& contact_case, const ProgressObserver& progress = {},
                           const StepObservers& observers = {});

}  // namespace mdr::drivers
