#pragma once
/// \file
/// The elastic contact of a rigid axisymmetric indenter with a layer on a rigid substrate: the MDR line load q(x)
/// solves a Fredholm equation of the second kind over the contact (docs/theory.md, "Layers", eq. L3 to L6).

#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/numerics/gauss_rule.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::contact {

/// Gauss-Legendre nodes on the contact [0, a] when `[numerics] elements` is not given: the line load is smooth, and
/// the force with 48 nodes (4 per thickness beyond a/h = 12) is within 1e-7 of 512 nodes' for a/h up to 9
/// (tests/verification/test_layer_contact.cpp, ForceConvergesInTheNumberOfNodes).
inline constexpr std::size_t default_layer_nodes = 48;
/// Gauss-Legendre nodes per thickness of the contact radius at least (the kernel's width is h): a contact wider than
/// default_layer_nodes / 4 thicknesses takes more than the default nodes. The Nystroem solution converges spectrally
/// in them: at a/h 64 (bonded, incompressible) the depth at a radius is 1.8e-4 off with 3, 9e-8 with 4, 2.5e-10 with 5
/// (tests/verification/test_layer_contact.cpp, ThinFilmConvergesInTheNodesPerThickness): 4, the force 1.1e-8 off.
inline constexpr std::size_t nodes_per_thickness = 4;

/// A run's `[numerics] elements` raises the Gauss nodes (LayerNodes::capped) to at most this many times the default
/// rule's at the contact's radius (default_layer_nodes, nodes_per_thickness a thickness beyond): the Nystroem solution
/// converges spectrally in the nodes, and twice the rule's reaches the kernel table's floor, within 3.3e-11 of the
/// depth and force of 10 nodes a thickness at a/h 0.5 to 64 where the rule is 9.0e-8 off
/// (tests/verification/test_layer_contact.cpp, NodesCappedAtTwiceTheDefaultRuleMeetTheConvergedSolution); a
/// creep-recovery at a/h up to 0.56 and 6.7 runs within 4e-14 and 7e-13 of 512 nodes' depth at 48 nodes and every
/// count above. More only cost time (a solve is O(n^3)): 400 nodes took 120 times the 48 nodes' time for the same
/// result to round-off (docs/performance.md, "A layer's `elements`").
inline constexpr std::size_t most_nodes_over_default = 2;

/// How LayerContact takes its Gauss-Legendre nodes over a contact of radius a on a layer of thickness h.
struct LayerNodes {
    /// At least this many at every radius (a run's `[numerics] elements`), and nodes_per_thickness ceil(a/h).
    std::size_t least = default_layer_nodes;
    /// Where true (a run), `least` counts up to most_nodes_over_default times the default rule's at the radius,
    /// max(default_layer_nodes, nodes_per_thickness ceil(a/h)); false (as given) for a study of the convergence in
    /// the nodes.
    bool capped = false;
};

/// The Gauss-Legendre nodes LayerContact takes by `nodes` over a contact of `thicknesses` = ceil(a/h) layer
/// thicknesses: max(least, nodes_per_thickness ceil(a/h)), `least` capped as LayerNodes says (the kernel's width is
/// h).
std::size_t layer_gauss_points(std::size_t thicknesses, const LayerNodes& nodes);

/// The contact radius on a layer exceeds the half-space's at the same depth by at most 3 pi / 4 (a cone on a thin
/// bonded incompressible layer, whose displaced volume stays under the indenter; a sphere: 2, docs/theory.md eq.
/// L8): the margin by which a run or a fit prepares the widest contact beyond the half-space's radius.
inline constexpr double layer_radius_margin = 3.0;

/// Contacts wider than this many thicknesses are refused (key `layer.thickness`): they need too many Gauss nodes
/// (4 per thickness, each solve O(n^3)).
inline constexpr double max_layer_radius_over_thickness = 100.0;

/// Throws mdr::InvalidInput (key `layer.thickness`) unless `largest_radius` [m], the widest contact a run or a fit
/// prepares, is at most max_layer_radius_over_thickness times the layer's thickness.
void check_layer_contact_radius(const Layer& layer, double largest_radius);

/// One elastic equilibrium on the layer with unit plane-strain modulus E* = 1 (force and line load scale with E*).
struct LayerContactState {
    double contact_radius = 0.0;  ///< a [m]
    double depth = 0.0;           ///< d [m]
    double force = 0.0;           ///< F / E* [m^2] (eq. L5)
    double stiffness = 0.0;       ///< dF/dd / E* [m]: 2 int_0^a q_d, the unit depth's force at this contact (eq. L5;
                                  ///< the force-free edge's move changes F only at second order, eq. L6)
};

/// One elastic equilibrium's line loads and surface (E* = 1) at chosen points x >= 0 (LayerContact::profile).
struct LayerContactProfile {
    std::vector<double> load;        ///< q(x) / E* [m] (eq. L3): d q_d - q_g on [0, a], 0 beyond
    /// q_d(x) / E*, the unit depth's line load on the fixed contact [0, a] (0 beyond): dq/dd at a fixed radius (the
    /// edge's move adds nothing where q(a) = 0, eq. L6), the shape of a parallel dashpot's part (eq. L11)
    std::vector<double> unit_depth_load;
    /// w1(x) [m], the transformed surface displacement: d - g(x) on [0, a], and beyond, where q = 0, eq. L3 at any x
    /// (E* w1 = q - K q): -(1/pi) int_0^a [K(x - s) + K(x + s)] q(s) ds / E*
    std::vector<double> surface;
};

/// The elastic layer problem for one indenter: q(x) - (1/pi) int_0^a [K(x - s) + K(x + s)] q(s) ds = E* (d - g(x))
/// (eq. L3) by the Nystroem method on Gauss-Legendre nodes; F = 2 int_0^a q (eq. L5); a smooth indenter's contact
/// edge is force-free, q(a) = 0 (eq. L6), a flat punch's is its radius. Valid for contact radii up to
/// max_contact_radius. h -> infinity gives the half-space's MDR exactly (K = 0).
class LayerContact {
public:
    /// Throws mdr::InvalidInput (key `layer.thickness`) unless h > 0 is finite; `nodes.least` >= 2.
    LayerContact(const Layer& layer, double poisson_ratio, std::shared_ptr<const profile::Profile> indenter,
                 double max_contact_radius, const LayerNodes& nodes);
    /// As above with at least `nodes` Gauss nodes, as given (LayerNodes::capped false).
    LayerContact(const Layer& layer, double poisson_ratio, std::shared_ptr<const profile::Profile> indenter,
                 double max_contact_radius, std::size_t nodes = default_layer_nodes)
        : LayerContact(layer, poisson_ratio, std::move(indenter), max_contact_radius, LayerNodes{nodes, false}) {}

    /// The equilibrium with contact radius 0 < a <= max_contact_radius (a flat punch: its radius, at depth 1), on
    /// about layer_gauss_points Gauss-Legendre nodes (the kernel's width is h), in panels split at the indenter's
    /// kinks (contact_quadrature).
    LayerContactState at_radius(double contact_radius) const;
    /// The equilibrium at depth d (d <= 0: no contact): the contact radius solved from depth(a) = d (increasing in
    /// a; depth to 1e-8 of d) by numerics::monotone_root, bracketed from `near` (a nearby solution, such as the
    /// previous step's; none: from max_contact_radius / 2). Throws mdr::InvalidInput (key `layer`) when the
    /// contact would grow beyond max_contact_radius.
    LayerContactState at_depth(double depth, const LayerContactState& near) const;
    /// As above, from the equilibria `nearby` solved before (such as the last steps', or the loading steps around
    /// d; their order the caller's, the last preferred): the start is a^2 interpolated in d through up to four of
    /// them with distinct depths (one: a^2 ~ d, a sphere's), so that one solve often meets the tolerance; then the
    /// secant through the start and the one nearest in depth, then regula falsi. Where d lies amid four of them (a
    /// receding step's Ting depth amid the loading steps) and the cubic interpolants of a^2, F and dF/dd agree with
    /// their quadratics well within the solve's tolerance, the interpolated equilibrium is returned without a solve.
    LayerContactState at_depth(double depth, std::span<const LayerContactState> nearby) const;
    /// As above, near the solution whose contact radius is `radius_hint` (> 0; else from max_contact_radius / 2).
    LayerContactState at_depth(double depth, double radius_hint = 0.0) const;
    /// The line loads and the transformed surface of `state` (an equilibrium of at_radius or at_depth: its contact
    /// radius and depth) at each of `points` (0 <= x <= 2 max_contact_radius - a [m], the kernel's range), by the
    /// Nystroem interpolation of eq. L3 from the Gauss nodes of at_radius (the solve repeated: O(n^3), then O(n) a
    /// point).
    LayerContactProfile profile(const LayerContactState& state, std::span<const double> points) const;
    /// The largest contact radius the kernel was tabulated for [m].
    double max_contact_radius() const { return max_contact_radius_; }
    /// dF/dd / E* [m] as the indenter touches: the unit-depth force (eq. L5) of its flat end's contact (a flat punch,
    /// a flat-tipped table: profile::Profile::flat_radius), 0 for a profile that touches at a point.
    double touch_stiffness() const;

private:
    struct Solution;  // the Nystroem solution on [0, a] (layer_contact.cpp)
    Solution solve(double contact_radius) const;
    // K(x - s) + K(x + s) (eq. L4: K(y) = k(y/h)/h).
    double kernel_sum(double x, double s) const;
    /// Gauss-Legendre nodes over a contact of radius a: layer_gauss_points with nodes_.
    std::size_t points_at(double contact_radius) const;

    Layer layer_;
    std::shared_ptr<const profile::Profile> indenter_;
    double max_contact_radius_;
    LayerNodes nodes_;
    std::vector<double> kinks_;  ///< the indenter's (profile::Profile::kinks): the quadrature's panels end there
    /// rules_[k]: the k-point Gauss-Legendre rule for every k = points_at(a) and, with kinks, for each panel's k up to
    /// the largest points_at (empty elsewhere)
    std::vector<numerics::GaussRule> rules_;
    LayerKernel kernel_;
};

}  // namespace mdr::contact
