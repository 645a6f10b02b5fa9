#pragma once
/// \file
/// From the 1D foundation back to the 3D half-space: pressure (eq. 23) or shear stress (eq. 47) from a line load,
/// and surface displacement from the 1D displacements (the Abel transform of eq. 10).

#include <span>
#include <vector>

namespace mdr::contact {

/// Stress of the 3D contact from a line load q(x) given at element centres x_i = (i + 1/2) spacing,
/// i = 0 .. q.size()-1, all inside the contact radius: s(r) = -(1/pi) int_r^a q'(x) / sqrt(x^2 - r^2) dx
/// (eq. 23 for q_z -> p, eq. 47 for q_x -> tau_xz). q is taken piecewise linear between the centres, constant on
/// [0, x_0] (q is even), and linear from the last centre to `edge_value` at x = contact_radius, then 0 beyond
/// (a jump there, edge_value != 0, gives the square-root singularity of a flat punch). Each segment's integral
/// is done in closed form. Returns s at each of `radii`; 0 for r >= contact_radius.
std::vector<double> stress_from_line_load(double spacing, std::span<const double> q, double contact_radius,
                                          double edge_value, std::span<const double> radii);

/// Normal surface displacement of the half-space w(r) = (2/pi) int_0^r w1D(x) / sqrt(r^2 - x^2) dx from the 1D
/// displacements w1D at element centres x_i = (i + 1/2) spacing (piecewise linear between centres, constant on
/// [0, x_0], w1D = 0 beyond the last centre). Exact for compact contacts; inside the contact it returns d - f(r).
std::vector<double> surface_displacement(double spacing, std::span<const double> w1d, std::span<const double> radii);

}  // namespace mdr::contact
