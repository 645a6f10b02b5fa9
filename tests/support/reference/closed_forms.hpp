#pragma once
/// \file
/// Closed-form and quadrature reference solutions of elastic and viscoelastic normal contact
/// (incompressible half-space, ν = 1/2, E* = 4G). Independent of the library's MDR code.

#include <functional>

#include "reference/indenter.hpp"
#include "reference/piecewise_linear.hpp"
#include "reference/prony_material.hpp"

namespace mdr::reference {

/// Hertz: force [N] of a sphere of radius R [m] pressed to depth d ≥ 0 [m] into an elastic half-space of shear
/// modulus G [Pa]: F = (16/3) G sqrt(R) d^{3/2} (E* = 4G; Johnson eq. 4.22).
double hertz_force(double radius, double shear_modulus, double depth);
/// Hertz contact radius a = sqrt(R d) [m] (eq. 31).
double hertz_contact_radius(double radius, double depth);
/// Hertz pressure [Pa] at radius r: p = p0 sqrt(1 − r²/a²) for r < a, else 0, with p0 = 8 G a /(π R).
double hertz_pressure(double radius, double shear_modulus, double depth, double r);

/// Sneddon cone (θ [rad] between flank and surface) at depth d: contact radius a = 2d/(π tanθ) [m] (eq. 26).
double cone_contact_radius(double slope_angle, double depth);
/// Sneddon cone force F = 2∫_0^a 4G (d − (π/2) tanθ x) dx = 8 G d² /(π tanθ) [N].
double cone_force(double slope_angle, double shear_modulus, double depth);

/// Truncated cone (flat tip of radius b [m], flanks at θ [rad] beyond: f = (r − b) tanθ) at contact radius a > b:
/// Sneddon's d = a ∫_0^a f'(r) / sqrt(a² − r²) dr = a tanθ acos(b/a) and
/// F = 8G ∫_0^a r² f'(r) / sqrt(a² − r²) dr = 8G tanθ [(a²/2) acos(b/a) + (b/2) sqrt(a² − b²)] [N].
double truncated_cone_depth(double slope_angle, double flat_radius, double contact_radius);
/// Force [N] of the truncated cone at depth d > 0 (the contact radius from d by bisection).
double truncated_cone_force(double slope_angle, double flat_radius, double shear_modulus, double depth);

/// Boussinesq flat punch of radius a [m] at depth d: F = 8 G a d [N].
double flat_punch_force(double punch_radius, double shear_modulus, double depth);

/// Power-law indenter f = c rⁿ at contact radius a [m]: F = 8 G κ_n c n a^{n+1}/(n+1) [N]; the matching depth
/// is PowerLawIndenter::depth_at_radius(a) = κ_n c aⁿ.
double power_law_force(const PowerLawIndenter& indenter, double shear_modulus, double contact_radius);

/// Handbook eq. (28): cone, d = v0 t, standard solid (G∞, G1, τ1):
/// F(t) = (8 v0² /(π tanθ)) [G∞ t² + 2 G1 τ1 t − 2 G1 τ1² (1 − exp(−t/τ1))] [N]. Derived independently from
/// F = 8 v0 ∫_0^{a(t)} Φ(t − t_c(x)) dx with Φ(s) = ∫_0^s G, x = 2 v0 t_c /(π tanθ); the restatement holds.
double cone_ramp_force_standard_solid(double slope_angle, double speed, double G_inf, double G1, double tau1,
                                      double t);

/// Handbook eq. (33): Kelvin–Voigt (G, η) sphere under a force F0 applied at t = 0:
/// a(t) = [(3 F0 R /(16 G)) (1 − exp(−t G/η))]^{1/3} [m].
double kelvin_voigt_sphere_creep_radius(double radius, double shear_modulus, double viscosity, double force,
                                        double t);

/// Lee–Radok force [N] at time t for a non-decreasing piecewise-linear depth d(t) with d(times.front()) = 0:
/// F(t) = η dF1/dt + ∫ G(t − t') dF1(d(t')), F1 the elastic force at unit modulus, dF1 = 8 a dd (contact
/// stiffness 8Ga). Integrated per piece over the contact radius a (smooth integrand, dF1 = 8 n κ_n c aⁿ da) by
/// adaptive Gauss–Kronrod to 1e-13 relative. Throws std::invalid_argument if d decreases anywhere.
double lee_radok_force(const PowerLawIndenter& indenter, const PronyMaterial& material, const PiecewiseLinear& depth,
                       double t);

/// Handbook eq. (34) for the sphere (radius R [m]) and any creep function J [1/Pa]: the depth d(t) [m] under a
/// force rising linearly from 0 at t = 0 to F0 [N] at t = `ramp` [s] and held after (ramp = 0: a step at 0), from
/// (16 sqrt(R)/3) d^(3/2) = int_0^t J(t - t') dF(t'), valid while the contact grows. The integral of J by adaptive
/// quadrature.
double sphere_creep_depth(const std::function<double(double)>& creep, double radius, double force, double ramp,
                          double t);

/// Elastic impact of a rigid cone (θ [rad] between flank and surface, mass m [kg], speed v0 [m/s]) on a half-space
/// of shear modulus G [Pa]: with F = k d², k = 8G/(π tanθ) (Sneddon), the energy balance gives
/// d_max³ = 3 m v0² / (2k) and the contact time T = 2 ∫_0^d_max dd / v = (2/3) B(1/3, 1/2) d_max / v0 [s].
double cone_impact_time(double slope_angle, double shear_modulus, double mass, double velocity);

/// A cone (θ [rad] between flank and surface) on a standard solid (G∞, G1, τ1) under a force ramp from 0 at
/// t = 0 to F0 [N] at t1 [s], then released at once (F = 0 after t1): the depth [m] at which the force-free tip
/// rides on the recovering surface at t > t1, the surface displacement on the axis. Lee–Radok while loading,
/// d(s)² = (π tanθ / 8) ∫_0^s J(s − s') dF(s') with J of Table 1; the pressure's elastic axis displacement at unit
/// modulus U(s) = ∫_0^s G(s − s') dd(s') (the tip is in contact, u = d); after t1 the surface is traction-free, so
/// by the hereditary law u(0, t) = ∫_0^t1 J(t − s) dU(s) − J(t − t1) U(t1) = ∫_0^t1 J'(t − s) U(s) ds. Nested
/// adaptive quadrature (d ~ sqrt(s) at the start), ~1e-11 relative.
double cone_riding_depth(double slope_angle, double G_inf, double G1, double tau1, double force, double t1,
                         double t);

}  // namespace mdr::reference
