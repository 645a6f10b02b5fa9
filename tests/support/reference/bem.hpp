#pragma once
/// \file
/// Axisymmetric boundary-element solver for a rigid indenter on an incompressible viscoelastic half-space under
/// a prescribed depth history, with loading, unloading and re-loading. The cross-method oracle: it uses the
/// 3D elastic influence of pressure rings and the hereditary creep integral over the full pressure history, and
/// nothing of MDR.

#include <functional>
#include <vector>

#include "reference/piecewise_linear.hpp"

namespace mdr::reference {

/// Normal surface displacement [m] at radius r [m] of an incompressible half-space with unit shear modulus
/// (E* = 4) under unit uniform pressure on a disk of radius c [m] (Johnson, Contact Mechanics §3.4, with
/// (1 − ν²)/E = 1/(4G)): u = c E(r/c)/π for r ≤ c, u = r [E(c/r) − (1 − c²/r²) K(c/r)]/π for r > c.
double uniform_disk_displacement(double disk_radius, double r);

/// Discretisation of the BEM. Rings of uniform pressure on [(j)Δr, (j+1)Δr], Δr = domain_radius/rings,
/// collocation at the ring centres; uniform time steps with pressure linear in time over each step.
struct BemOptions {
    int rings = 400;             ///< number of rings
    int steps = 400;             ///< number of uniform time steps over [times.front(), times.back()]
    double domain_radius = 0.0;  ///< outer radius of the ring grid [m]; must exceed every contact radius
    /// Throws std::invalid_argument unless rings ≥ 2, steps ≥ 1 and domain_radius > 0.
    void validate() const;
};

/// History computed by the BEM at the step times (including the initial time, where everything is zero).
struct BemResult {
    std::vector<double> times;           ///< t_n [s]
    std::vector<double> depth;           ///< d(t_n) [m]
    std::vector<double> force;           ///< F(t_n) = Σ_j 2π r_j Δr p_j [N]
    std::vector<double> contact_radius;  ///< outer edge of the outermost ring in contact [m] (within Δr)
};

/// Solves the contact problem: u_i(t_n) = Σ_j C_ij ∫_0^{t_n} J(t_n − t') ṗ_j(t') dt' (C for unit modulus, p_j
/// piecewise linear in time, the integrals of J over each step by adaptive quadrature of `creep`), and at every
/// step the complementarity conditions u_i = d − f(r_i), p_i ≥ 0 in contact and p_i = 0, u_i ≥ d − f(r_i)
/// outside, by an active-set iteration on the dense system of the contact set. `gap` is f(r) [m], `creep` is
/// J(t) [1/Pa] for t ≥ 0, `depth` is d(t) [m]. Throws std::runtime_error if contact reaches the last ring or the
/// active set does not settle.
BemResult solve_axisymmetric_bem(const std::function<double(double)>& gap, const std::function<double(double)>& creep,
                                 const PiecewiseLinear& depth, const BemOptions& options);

}  // namespace mdr::reference
