#pragma once
/// \file
/// The element foundation of a depth-driven run with the elements that provably stay in contact summed instead of
/// stepped (internal to mdr_fit): the same elements, the same updates and the same forces as the drivers' element
/// model (foundation.hpp), at a cost of O(steps x (branches + elements near the contact edge)).
///
/// The bound that lets an element be summed (docs/performance.md, "Real curves"): an element of MDR profile g in
/// contact has w = d - g (eq. 13) and, per Prony branch k, the memory h_k (eq. 16), updated as h_k <- E_k h_k + B_k dd
/// (step_coefficients.hpp) while it follows the indenter; Q_k is the memory of an element that followed the indenter
/// from the undeformed state (the same update). A folded element keeps delta_k = h_k - Q_k, which only decays
/// (delta_k <- E_k delta_k), so from its fold on sigma = G_inf (d - g) + S + sum_k G_k delta_k >= G_inf (d - g) + S - m
/// with S = sum_k G_k Q_k and m = sum_k G_k max(-delta_k, 0) at the fold (G_k >= 0). The element stays in contact
/// while its floor G_inf g + m <= G_inf d + S at each step's end. The elements of a prefix [0, folded) are "folded":
/// all follow the indenter with the same increment, so their stresses add up to G_inf (n d - sum g) + sum_k G_k H_k
/// with H_k = sum h_k updated as one element. The folded prefix keeps the largest floor of its elements, so that it
/// unfolds from its end: a floor that no longer holds is first renewed from the element's decayed delta_k (a fold
/// afresh), and the element unfolded with its exact state, and stepped again, only if that floor fails too. The other
/// elements take the foundation's steps, entry and exit located inside the step as there.
///
/// The bound holds for every material the band model covers, with or without an equilibrium modulus. It replaced the
/// band g <= L(t) = D - (G(0)/G_inf)(D - d) (D the running maximum of d), which for a large G(0)/G_inf (a spring with
/// a springpot's series) unfolds nearly every element at each dip of a measured depth; the memory bound folds
/// about as many (the Prony fits of the examples: within 0.02 %) or far more (docs/performance.md).
///
/// Under force control (band_depths) each step's depth is solved as the drivers solve it (solve_force_balance on the
/// force of a trial step): a trial depth below the band of a folded element unfolds it in a copy, so that every
/// trial force is the element model's.

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "mdr/drivers/load_history.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::fit {

/// True when the band model covers this material: no parallel dashpot, G_inf >= 0, every Prony modulus >= 0 and
/// G(0) > 0.
bool band_model_applies(const rheology::Rheology& material);

/// True when the band model can start from a relaxed preload of this material (band_forces' `preloaded`): it
/// applies and G_inf > 0 (with G_inf = 0 no force holds a preload).
bool band_model_rests_preloaded(const rheology::Rheology& material);

/// What the band model gives for one depth history.
struct BandResponse {
    std::vector<double> force;       ///< F [N] at each time (eq. 21, both halves)
    std::size_t element_steps = 0;   ///< steps taken by single elements (the folded ones count nothing)
};

/// The force of the foundation of `count` elements of width `spacing` (x_i = (i + 1/2) spacing, as the drivers'
/// Foundation) under the depth history through (time[i], depth[i]) (linear between the points, times increasing;
/// the foundation undeformed before time[0], a first depth > 0 reached by a jump there), incompressible body of
/// `material`. nullopt when !band_model_applies, when the depth goes beyond the foundation (the last element's g,
/// or the end of a tabulated profile at the half-width: the drivers' Foundation then reports it), or when the
/// drivers' Foundation would refuse `count` elements as too many (its message then names the key).
/// `check_interrupt`, when set, is called every 4096 steps (it may throw mdr::Interrupted).
///
/// `preloaded`: a first depth d_0 = depth[0] > 0 is a relaxed preload instead of a jump (docs/theory.md §4d; nullopt
/// for G_inf = 0, which holds no preload): the foundation has rested under d_0 long enough for every branch to relax,
/// so each element with g < d_0 starts in contact at w = d_0 - g with h_k = 0 (stress G_inf w), and the force
/// returned is the change since time[0],
/// F(t) - G_inf F_el(d_0) = int_{t_0}^t G(t - s) dF_el(d(s)) while the contact grows (Lee-Radok, eq. 21), and the
/// foundation's own force less its preload once it shrinks. The memory bound holds from the start (h_k = 0 = Q_k).
std::optional<BandResponse> band_forces(const rheology::Rheology& material, const profile::Profile& indenter,
                                        double spacing, std::size_t count, const std::vector<double>& time,
                                        const std::vector<double>& depth,
                                        const std::function<void()>& check_interrupt = {}, bool preloaded = false);

/// What the band model gives for one force history.
struct BandCreep {
    std::vector<double> depth;       ///< d [m] at each node (where the force is 0: the deepest depth without force)
    std::size_t element_steps = 0;   ///< steps taken by single elements (the folded ones count nothing)
};

/// The depth of the foundation of band_forces under force control along `nodes` (indentation_grid of a
/// force-controlled case: the force max(value, 0) at each node, linear in time between nodes, the first node the
/// undeformed state): the drivers' run_indentation step by step, each depth solved to 1e-13 of the force from the
/// same extrapolated guess. Where the force is 0 the drivers show the touching depth instead (a tip riding on the
/// recovering surface); the depths at nodes with a force > 0 are theirs. nullopt where band_forces gives nullopt
/// (the drivers then run or report it). May throw what the drivers' depth solve throws.
std::optional<BandCreep> band_depths(const rheology::Rheology& material, const profile::Profile& indenter,
                                     double spacing, std::size_t count, const std::vector<drivers::GridNode>& nodes,
                                     const std::function<void()>& check_interrupt = {});

}  // namespace mdr::fit
