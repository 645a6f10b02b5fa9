#pragma once
// The coupled time-stepping of a viscoelastic layer of constant Poisson ratio whose contact may grow again after it
// shrank (docs/theory.md, "Layers", eq. L16 to L19): the MDR line load q and the transformed surface displacement w1
// on uniform cells of [0, X], coupled in space by (I - K) q = Q (eq. L3 for any q vanishing beyond the contact) and
// in time, cell by cell, by Q = 4 int_0^t G(t - t') dw1(x, t'), each Prony branch updated exactly (G the effective
// shear modulus, eq. 56); the contact set by complementarity each step.

#include <cstddef>
#include <utility>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::drivers {

/// Cells on the contact's widest range when `[numerics] elements` is not given: the force within ~4e-5 of the peak
/// with the contact over a third of the range (second order in the cell; tests/verification/test_layer_regrowing.cpp,
/// tests/python/test_layer_unloading.py).
inline constexpr std::size_t default_layer_cells = 400;

/// The state after a step of LayerCells.
struct LayerCellState {
    double depth = 0.0;           ///< d [m]: prescribed, or solved (force and spring control)
    double force = 0.0;           ///< F = 2 dx sum q_i [N] (eq. L5, midpoint rule)
    double contact_radius = 0.0;  ///< a [m], located between the outermost cell in contact and its free neighbour
    bool touching = false;        ///< the axis in contact (docs/theory.md eq. L19: the edge function at x = 0)
    /// The part [first, second] (fractions 0..1) of the last step with the axis in contact: a loss or a regain
    /// located inside the step where the edge function at the axis crosses zero (linear over the step).
    std::pair<double, double> touching_part{0.0, 0.0};
};

/// A layer of constant Poisson ratio (E* = 4G, G the effective shear modulus of eq. 56) under a rigid axisymmetric
/// indenter, any depth history: the contact may shrink and grow again any number of times (Ting 1968's general case
/// on a layer).
class LayerCells {
public:
    /// `cells` (>= 2) uniform cells on [0, width] (width > 0 [m], at least the widest contact; a flat punch: its
    /// radius), the layer's kernel of the body's constant Poisson ratio (layer_poisson_ratio; `material` is then the
    /// effective shear material, E* = 4 G) tabulated on [0, 2 width / h] and I - K factored once (Cholesky: its
    /// leading blocks factor every contact set).
    LayerCells(const rheology::Rheology& material, const contact::Layer& layer, double poisson_ratio,
               const profile::Profile& indenter, double width, std::size_t cells);
    /// Steps by `time_step` >= 0 [s] with the depth linear over it to `depth` [m]. Throws mdr::InvalidInput (key
    /// `layer`) when the contact would reach the last cell (a smooth indenter's contact outgrowing the range).
    LayerCellState step(double time_step, double depth);
    /// Steps by `time_step` >= 0 [s] to the depth at which F(d) + k d = `right_side` [N], k = `spring_constant` >= 0
    /// [N/m]: force control (k = 0, the force), or spring control (k z, z = `base` [m], where the indenter hangs
    /// without contact). Under force control at zero force the indenter rests on the free surface at the axis.
    LayerCellState step_loaded(double time_step, double right_side, double spring_constant, double base);

private:
    // One step: `depth_for(m)` gives the depth for the contact set [0, m); `needs_contact`: a force without contact.
    template <class DepthRule>
    LayerCellState advance(double time_step, const DepthRule& depth_for, bool needs_contact);
    // q of the contact set [0, contact) for the step's coefficients and depth, and w1 of the first `free_cells`
    // free cells beyond (O(m^2) for m cells in contact, and O(m) a free cell).
    void solve(std::size_t contact, double depth, std::size_t free_cells);
    // The two parts of solve: q on the contact set, then w1 (d - g inside).
    void solve_load(std::size_t contact, double depth);
    void free_surface(std::size_t contact, double depth, std::size_t free_cells);

    const rheology::Rheology* material_;
    bool flat_punch_;
    double spacing_;
    std::size_t cells_;
    std::vector<double> centre_, profile_;  // x_i, g(x_i)
    std::vector<double> operator_, factor_; // I - K (midpoint rule) and its Cholesky factor L, row-major
    std::vector<double> factor_transposed_; // L^T, row-major (the back substitution reads rows)
    std::vector<double> displacement_;      // w1_i, committed
    std::vector<double> branches_;          // h_ki, per cell its branches together
    std::size_t contact_ = 0;               // committed contact cells
    double axis_weight_ = 0.0;              // lambda: the axis from the two innermost cells, linear in g
    double axis_ = 0.0;                     // the committed edge function at the axis (> 0: touching)
    // The step being solved: coefficients, the relaxed part of Q/4 per cell, the trial q and w1.
    foundation::StepCoefficients coefficients_;
    std::vector<double> relaxed_, trial_load_, trial_displacement_;
};

}  // namespace mdr::drivers
