#pragma once
/// \file
/// The quadrature over a layer's contact [0, a] (docs/theory.md section 4c, "Numerics"): Gauss-Legendre panels split
/// at the indenter's kinks, graded towards each kink so that the line load's sqrt(x - kink) is smooth in the variable.

#include <cstddef>
#include <vector>

#include "mdr/numerics/gauss_rule.hpp"

namespace mdr::contact {

/// Fewest Gauss nodes on a panel between kinks.
inline constexpr std::size_t min_panel_nodes = 4;

/// Nodes (ascending) and weights of a rule for int_0^a f(x) dx.
struct ContactQuadrature {
    std::vector<double> nodes;    ///< [m]
    std::vector<double> weights;  ///< [m]
    /// One Gauss-Legendre panel (no kink inside): nodes[n - 1 - i] = a - nodes[i] up to round-off, so that a
    /// difference kernel k(x_i - x_j) is persymmetric on them
    bool mirrored = false;
};

/// The rule over [0, contact_radius] with about `points` nodes: without a kink inside, `points` Gauss-Legendre nodes;
/// else the panels [0, k1], [k1, k2], ..., [km, a] between the kinks, each with
/// max(min_panel_nodes, ceil(points L / a)) nodes for its length L. A panel starting at a kink k is mapped by
/// x = k + L t^2: the line load there is smooth plus c sqrt(x - k) (eq. 9 and L3, the kernel being smooth), a smooth
/// function of t, so the rule converges fast instead of at first order with oscillations. `rules[k]`, where it has
/// nodes, is the k-point Gauss-Legendre rule (prepared once: making one costs about a solve); others are made here.
ContactQuadrature contact_quadrature(double contact_radius, const std::vector<double>& kinks, std::size_t points,
                                     const std::vector<numerics::GaussRule>& rules);

}  // namespace mdr::contact
