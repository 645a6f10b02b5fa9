#pragma once
/// \file
/// Oblique impact of a rigid sphere with spin on an elastic incompressible half-space with local Coulomb friction,
/// from the Hertz and Mindlin–Deresiewicz/Jäger theory, without the MDR foundation or tangential layer.

namespace mdr::reference {

/// The sphere and the impact.
struct ObliqueHertzCase {
    double shear_modulus;        ///< G [Pa] (incompressible: E* = 4 G, G* = 8 G / 3)
    double radius;               ///< R [m]
    double mass;                 ///< m [kg]
    double moment_of_inertia;    ///< I [kg m^2]
    double friction;             ///< mu
    double normal_velocity;      ///< v_n0 > 0 [m/s]
    double tangential_velocity;  ///< v_t0 [m/s] of the centre
    double spin;                 ///< omega0 [rad/s]; the contact point moves at v_t - R omega
};

/// Outcome at the end of contact.
struct ObliqueHertzResult {
    double restitution;              ///< -v_n(T) / v_n0
    double tangential_restitution;   ///< -v_c(T) / v_c0, v_c = v_t - R omega
    double tangential_velocity;      ///< v_t(T) [m/s]
    double spin;                     ///< omega(T) [rad/s]
    double impulse_ratio;            ///< int F_x dt / int F_N dt
    double contact_time;             ///< T [s]
};

/// The impact integrated in time with `steps` steps of the Hertz contact time (velocity Verlet, second order; the
/// default gives the tangential restitution to ~1e-7, the cost grows as steps^2 where annuli stick).
/// Normal: F_N = (16/3) G sqrt(R) d^{3/2} (Hertz). Tangential (Mindlin–Deresiewicz for an arbitrary history, in
/// Jäger's form): the traction is carried by the annuli of contact; the annulus that entered contact at depth
/// g = r^2/R... described here by its depth of entry g in [0, d], holds a tangential displacement s(g) with
/// |s(g)| <= (3/2) mu (d - g) (Coulomb at every radius of a Hertz contact, G*/E* = 2/3); while |s| is below the
/// bound it moves with the contact point (stick), else it is held at the bound (slip); an annulus entering contact
/// enters with s = 0. F_x = (8/3) G sqrt(R) int_0^d s(g) g^{-1/2} dg. s(g) stays piecewise linear in g over any
/// history (stick shifts a piece, slip puts it on the linear bound), so it is held exactly as nodes, and the
/// integral is exact per piece. Within a step the depth and the contact-point displacement are taken linear in
/// time, for which the update of s (shift, then clamp to the bound at the step's end) is exact.
ObliqueHertzResult oblique_hertz_impact(const ObliqueHertzCase& impact, double steps = 5000.0);

}  // namespace mdr::reference
