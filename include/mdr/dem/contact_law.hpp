#pragma once
/// \file
/// The MDR contact of two viscoelastic spheres as a contact law for time-stepping (DEM) codes: the state of each
/// contact lives in the caller's memory; the law steps it with the library's own Foundation and TangentialLayer.

#include <cstddef>
#include <span>

#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/foundation/tangential_layer.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::dem {

/// The contact law of one kind of contact (two sphere types, one time step). Sphere-sphere contact maps onto a rigid
/// sphere of the equivalent radius R = R1 R2 / (R1 + R2) on a half-space with the combined creep function
/// J = J1 + J2 (eq. 8; both bodies incompressible). The law owns a workspace — one Foundation (section 5) and one
/// TangentialLayer (section 6) of N elements on the half-width L — and no contact's state: a contact's state is
/// state_size() doubles in the caller's memory (a pair style's per-contact history, say), zeroed by initialise()
/// at first touch. A step of one contact:
///
///     law.begin(state);                      // the contact's state into the workspace
///     law.normal_trial(overlap);             // optional: F_N for a trial overlap (an implicit integrator's solve)
///     law.advance_normal(overlap);           // the new normal overlap (eq. 13-22)
///     law.tangential_trial(displacement);    // optional: F_x for a trial tangential displacement
///     law.advance_tangential(displacement);  // the new tangential displacement of the contact point (eq. 41-51)
///     law.end(state);                        // the workspace back into the state
///
/// or law.advance(state, overlap, displacement) for the four calls without trials. Between begin and end the
/// overlap and the displacement go linearly in time over the step (the elements' updates are exact for that); a
/// dashpot sees the secant rate. Nothing allocates after construction. One law per thread (the workspace is its).
class ContactLaw {
public:
    /// `material` the combined rheology, `radius` R [m] the equivalent radius, `friction` mu >= 0, `elements` N on
    /// the half-width `half_width` L [m] (it must cover the largest contact radius, sqrt(R d_max) for a sphere),
    /// `time_step` dt [s] > 0 of every step. Throws mdr::InvalidInput for values out of range.
    ContactLaw(const rheology::Rheology& material, double radius, double friction, std::size_t elements,
               double half_width, double time_step);

    /// Doubles of one contact's state for N elements and M relaxation branches: 6 + N (2 M + 7).
    static std::size_t state_size(std::size_t elements, std::size_t branches);
    /// state_size for this law's N and M.
    std::size_t state_size() const { return state_size_; }
    /// Zeroes a contact's state at first touch (state_size() doubles).
    void initialise(std::span<double> state) const;

    /// Loads a contact's state into the workspace and prepares its step.
    void begin(std::span<const double> state);
    /// Total normal force [N] if the step ended at `overlap` [m]; the state is not changed.
    double normal_trial(double overlap) const;
    /// Advances the normal problem to `overlap` [m] over the step.
    void advance_normal(double overlap);
    /// Total tangential force [N] if the step ended at tangential displacement `displacement` [m] of the contact
    /// point (after advance_normal); the state is not changed.
    double tangential_trial(double displacement) const;
    /// Advances the tangential problem to `displacement` [m] (after advance_normal).
    void advance_tangential(double displacement);
    /// Writes the workspace back into the contact's state.
    void end(std::span<double> state) const;
    /// begin, advance_normal, advance_tangential, end.
    void advance(std::span<double> state, double overlap, double displacement);

    /// Normal force F_N [N] (eq. 21) of the workspace after the last advance_normal.
    double normal_force() const { return foundation_.total_force(); }
    /// Tangential force F_x [N] (eq. 46) of the workspace after the last advance_tangential: the force on the
    /// second body along the displacement; the first feels -F_x.
    double tangential_force() const { return layer_.total_force(); }
    /// Where inside the last normal step (0..1) the last element to leave contact left; 0 when none left.
    double latest_exit() const { return foundation_.latest_exit(); }
    /// Number of elements in normal contact after the last advance_normal (0: the contact has ended).
    std::size_t contact_count() const { return foundation_.contact_count(); }

    /// Normal force [N] stored in a contact's state (after end()).
    double normal_force(std::span<const double> state) const { return state[normal_offset + 1]; }
    /// Tangential force [N] stored in a contact's state.
    double tangential_force(std::span<const double> state) const { return state[tangential_offset_]; }
    /// Overlap [m] and tangential displacement [m] stored in a contact's state.
    double overlap(std::span<const double> state) const { return state[normal_offset]; }
    double displacement(std::span<const double> state) const { return state[0]; }

private:
    static constexpr std::size_t normal_offset = 1;  ///< state[0] holds the tangential displacement
    std::span<const double> loads() const;

    foundation::Foundation foundation_;
    foundation::TangentialLayer layer_;
    foundation::StepCoefficients coefficients_;
    std::vector<double> loads_;  ///< q_z,i of the last normal step
    std::size_t tangential_offset_;
    std::size_t state_size_;
    double displacement_ = 0.0;  ///< tangential displacement at the start of the step
    double overlap_ = 0.0;       ///< overlap at the start of the step
};

}  // namespace mdr::dem
