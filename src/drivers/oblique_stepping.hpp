#pragma once
// The tangential part of an oblique impact: the sphere's translation along x and its rotation, driven by the
// tangential layer beside the normal foundation (handbook section 6 with the equations of motion of the sphere).

#include <cstdint>
#include <span>
#include <vector>

#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/oblique_sphere.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/tangential_layer.hpp"

namespace mdr::drivers {

/// Integrates m v_t' = -F_x and I omega' = R F_x beside the normal impact. The contact point, R below the centre,
/// moves at v_c = v_t - R omega, so m_t v_c' = -F_x with 1/m_t = 1/m + R^2/I, and its displacement u drives the
/// tangential layer (eq. 41-51). The same trapezoidal rule as the normal motion (eq. 37), implicit in u and solved
/// on the layer each step after the normal step: u1 = u0 + (v_c0 + v_c1) dt/2, v_c1 = v_c0 - (F_x0 + F_x1) dt/(2 m_t),
/// i.e. F_x(u1) + (4 m_t/dt^2)(u1 - u0 - v_c0 dt) = -F_x0, monotone in u1. For an incompressible body the normal
/// problem does not see the tangential one; the two meet only in the friction limit mu F_N,i.
class ObliqueStepper {
public:
    /// `foundation` (the normal problem) must outlive the stepper; `mass` [kg] is the sphere's.
    ObliqueStepper(const ObliqueImpactLoad& load, const ObliqueSphere& sphere, double mass,
                   const rheology::Rheology& material, const foundation::Foundation& foundation);

    /// The tangential step of length `time_step` [s] after the foundation has advanced over it with `coefficients`.
    void step(const foundation::StepCoefficients& coefficients, double time_step);
    /// The last step of the impact, in which the normal contact ends at `fraction` (0..1) of it: the layer takes
    /// the step with every element free, and the impulse is F_x0 fraction dt / 2 (a linear decay, as the normal
    /// one).
    void finish(const foundation::StepCoefficients& coefficients, double time_step, double fraction);
    /// Appends u, F_x, c, v_t and omega of the current state to the result's rows.
    void record(IndentationResult& result) const;
    /// Fills the snapshot's shear stress tau_xz(r) (eq. 47).
    void add_shear_stress(Snapshot& snapshot) const;
    /// The outcome once the contact has ended, with the normal outcome `normal` (its rebound velocity and the
    /// normal kinetic energy lost, m (v0^2 - v(T)^2)/2, taken as the normal material dissipation).
    ObliqueOutcome outcome(const ImpactOutcome& normal, double approach) const;
    /// Kinetic energy lost [J] by the translation along x and the rotation: m (v_t0^2 - v_t^2)/2 + I (w0^2 - w^2)/2.
    double kinetic_energy_lost() const;

private:
    double solve_increment(double spring, double anchor, double time_step, std::span<const double> q,
                           std::span<const double> contact) const;
    void take_impulse(double impulse);
    /// The foundation's line loads q_z,i [N/m] of the elements it has touched, into loads_ (no allocation).
    std::span<const double> normal_line_loads();

    const ObliqueImpactLoad& load_;
    double radius_;   ///< R [m], the lever of the tangential force
    double inertia_;  ///< I [kg m^2]
    double mass_;
    double reduced_mass_;  ///< m_t
    const foundation::Foundation& foundation_;
    foundation::TangentialLayer layer_;
    std::vector<double> loads_;  ///< q_z,i of the normal foundation after its step
    double displacement_ = 0.0;  ///< u of the contact point [m]
    double velocity_;            ///< v_t [m/s]
    double spin_;                ///< omega [rad/s]
    double force_ = 0.0;         ///< F_x [N]
    double stick_radius_ = 0.0;
    double impulse_ = 0.0;       ///< int F_x dt [N s]
    double material_work_ = 0.0;
    double friction_work_ = 0.0;
    double max_force_ = 0.0;
    bool slid_throughout_ = true;
};

}  // namespace mdr::drivers
