#pragma once
// The coupled time-stepping of a viscoelastic layer of constant Poisson ratio whose contact may grow again after it
// shrank (docs/theory.md, "Layers", eq. L16 to L19): the MDR line load q and the transformed surface displacement w1
// on uniform cells of [0, X], coupled in space by (I - K) q = Q (eq. L3 for any q vanishing beyond the contact) and
// in time, cell by cell, by Q = 4 int_0^t G(t - t') dw1(x, t'), each Prony branch updated exactly (G the effective
// shear modulus, eq. 56); the contact set by complementarity each step.

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"
#include "layer_operator.hpp"

namespace mdr::drivers {

/// The state after a step of LayerCells.
struct LayerCellState {
    double depth = 0.0;           ///< d [m]: prescribed, or solved (force and spring control)
    double force = 0.0;           ///< F = 2 dx sum q_i + the edge's and axis's corrections [N] (eq. L5, L19a)
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
    /// leading blocks factor every contact set; layer_operator, kept for the thread's next LayerCells on the same
    /// layer and cells).
    LayerCells(const rheology::Rheology& material, const contact::Layer& layer, double poisson_ratio,
               const profile::Profile& indenter, double width, std::size_t cells);
    /// Steps by `time_step` >= 0 [s] with the depth linear over it to `depth` [m]. A parallel dashpot (eq. L16 with
    /// eta) sees the indenter's trapezoidal rate 2 dd/dt - `start_rate` [m/s] (the prescribed depth's rate at the
    /// step's start, where the depth is not linear inside the step: a harmonic), else the secant rate (exact for a
    /// depth linear over the step). Throws mdr::InvalidInput (key `layer`) when the contact would reach the last
    /// cell (a smooth indenter's contact outgrowing the range).
    LayerCellState step(double time_step, double depth, std::optional<double> start_rate = std::nullopt);
    /// Steps by `time_step` >= 0 [s] to the depth at which F(d) + k d = `right_side` [N], k = `spring_constant` >= 0
    /// [N/m]: force control (k = 0, the force), or spring control (k z, z = `base` [m], where the indenter hangs
    /// without contact). Under force control at zero force the indenter rests on the free surface at the axis. A
    /// parallel dashpot in contact sees the indenter's trapezoidal rate, carried from step to step and across a ride
    /// at zero force (as on the half-space); a cell entering contact in the step sees its own
    /// (foundation::RateAtEntry::breaks: the massless indenter's rate breaks there), the trapezoidal rate of its own
    /// motion from its own start rate, the law it was stepped by while free, so that its line load grows from zero
    /// and F(d) is continuous; the rate carried on is then the one that keeps the force the contact's dashpots
    /// carried. Where no start rate is known (the first step from rest, the step after a spring's indenter hung
    /// free, after a jump onto the surface or to zero force) the step takes the indenter's secant rate in every
    /// cell. With a dashpot a
    /// step of no duration in contact (a jump of the force) keeps the depth and every cell's w1, only the rates jump:
    /// the cells staying in contact take the change at one change of the indenter's rate, and a jump down lets the
    /// contact recede at once to the cells that keep q >= 0 while the others rise no faster than the indenter (jump;
    /// to zero force: no contact). A jump onto the surface (nothing in contact before it) holds the depth with no
    /// cell in contact (a touch at a point), the next step carrying the force; under a flat end (its face meeting
    /// the surface at once) the cells at zero gap take it as a contact does (jump_onto_face), and where those are
    /// a ring, not a disc about the axis, it throws mdr::InvalidInput (key `material.eta`).
    LayerCellState step_loaded(double time_step, double right_side, double spring_constant, double base);
    /// Steps an indenter carried by its inertia (an impact) by `time_step` > 0 [s] to the depth at which F(d) + k d =
    /// `right_side` [N], k = `spring_constant` > 0 [N/m] (the trapezoidal rule's 4m/dt^2, eq. 37); without contact
    /// d = right side / k. A parallel dashpot sees the indenter's trapezoidal rate 2 dd/dt - `velocity` (its
    /// velocity at the step's start [m/s], the equation of motion's own), in every cell in contact at the step's end,
    /// one entering in the step too (foundation::RateAtEntry::continuous: the mass carries the rate).
    LayerCellState step_inertial(double time_step, double right_side, double spring_constant, double velocity);

    /// The cells' width dx [m]: cell i is centred at (i + 1/2) dx.
    double spacing() const { return spacing_; }
    /// The line load q_i [N/m] of the cells in contact after the last step (eq. L17; zero beyond them).
    std::span<const double> line_load() const { return {trial_load_.data(), contact_}; }
    /// The transformed surface displacement w1_i [m] of every cell after the last step (eq. L18). The cells left out
    /// of the stepping (beyond the contact's neighbour) are first stepped through the steps they missed (catch_up),
    /// and every cell is stepped from then on.
    std::span<const double> surface();

private:
    // One step: `load_for(m)` solves q on the contact set [0, m) (solve_load) and gives its depth; `rule`: the sets
    // the search may end on. `start_rate`: the indenter's rate at the step's start that its dashpot term takes
    // (trapezoidal), or none (the secant rate); `rate_at_entry`: what a cell entering contact in the step sees.
    // Which contact sets a step's search may end on: any, one with a cell (a force under force control), none (zero
    // force under force control).
    enum class ContactRule { any, needed, none };
    template <class LoadRule>
    LayerCellState advance(double time_step, const LoadRule& load_for, ContactRule rule,
                           std::optional<double> start_rate, foundation::RateAtEntry rate_at_entry);
    // step_loaded and step_inertial: the depth at which F(d) + k d = `right_side`, `base` without contact (k > 0);
    // the dashpots' start rate and what an entering cell sees as advance takes them.
    LayerCellState solve_loaded(double time_step, double right_side, double spring_constant, double base,
                                std::optional<double> start_rate, foundation::RateAtEntry rate_at_entry);
    // A jump of the force to `force` [N] at the committed depth against a parallel dashpot, from a contact
    // (step_loaded): up, the whole contact takes it; down, the contact recedes at once to the set that solves the
    // complementarity in the rates (docs/theory.md eq. L28 to L30). `from`: the cells [0, from) the indenter
    // touches before it, the committed contact, or a face's touching cells (jump_onto_face; q = 0 beyond contact_).
    LayerCellState jump(double force, std::size_t from);
    // A jump of the force to `force` > 0 [N] with nothing in contact under a flat end (step_loaded): the cells at
    // zero gap under the face (a disc [0, m), else mdr::InvalidInput naming `material.eta`) take it as jump does,
    // the indenter's rate before it their own free rate (docs/theory.md, "A jump of the force on the cells").
    LayerCellState jump_onto_face(double force);
    // eta times how much faster than the indenter cell `cell` (free after a jump) moves into the body, q the trial
    // line load on [0, contact) and the indenter's rate changed by `rate_change` [m/s] (eq. L29: >= 0 where it left).
    double leaving_rate_margin(std::size_t cell, std::size_t contact, double rate_change) const;
    // eta times the indenter's rate at the step's end, at the end depth `depth` (eq. L16 in contact: w1 = d - g).
    double dashpot_stress(double depth) const;
    // What the midpoint rule F = 2 dx sum q_i misses of F = 2 int_0^a q dx on a contact set of `contact` cells (eq.
    // L19a): the part of the edge cell in contact, from the edge function inside (`inside`, q_{m-1}/4) and outside
    // (`outside`, minus the free stiffness times the gap of cell m), and the axis's slope of q from `innermost`, the
    // first three cells' q. Zero where the edge is not between two cells (a flat punch, the last cell) or the
    // edge function does not fall across it.
    double edge_correction(std::size_t contact, double inside, double outside, const double* innermost) const;
    // Its derivative in the depth where inside, outside and the first three q are affine in it with these slopes.
    double edge_correction_slope(std::size_t contact, double inside, double outside, double inside_slope,
                                 double outside_slope, const double* innermost_slope) const;
    // The contact radius of a step's contact set of `contact` cells (0 < contact < cells; not a point contact with
    // a dashpot: dashpot_edge) at depth `depth`, the trial state solved with cells contact and contact + 1 free: the
    // zero of the edge function (eq. L19) interpolated between the two centres, or, with a dashpot, the nearer of the
    // zeros of q inside and of the gap outside, each extrapolated linearly in g from its two cells next to the edge
    // (eq. L19c).
    double edge_radius(std::size_t contact, double depth) const;
    // The zero of an edge function with the values `inside` at cell contact - 1 and `outside` at cell contact, each
    // taken at its bound (inside >= 0 >= outside), interpolated linearly between the two centres (eq. L19, L30).
    double interpolated_edge(std::size_t contact, double inside, double outside) const;
    // With a parallel dashpot q jumps at the edge (by 4 eta times the rate's jump there, eq. L16), so the midpoint
    // rule's error is first order in the edge's place: what F = 2 dx sum q_i misses is 2 (a - m dx) q_{m-1}, the edge
    // a where the indenter meets the free surface, g(a) = d - w1_m (`outside_displacement`, cell m's free w1), on g
    // linear between the centres (and the axis), within [x_{m-1}, x_m] ([0, x_1] for one cell) (eq. L19b). Returns
    // a and its derivative in d for a w1_m of slope `outside_slope` in d. Zero where corrects_dashpot_edge does not.
    std::pair<double, double> dashpot_edge(std::size_t contact, double depth, double outside_displacement,
                                           double outside_slope) const;
    // Whether dashpot_edge applies: a dashpot, an edge between two cells, not a flat punch.
    bool corrects_dashpot_edge(std::size_t contact) const;
    // Whether edge_correction applies: no dashpot (its line load jumps at a growing edge, which the correction's
    // linear edge does not describe; first order there as before), and an edge between two cells.
    bool corrects_edge(std::size_t contact) const;
    // eta dw1_i/dt at the committed node: Q_i/4 - (G_inf w1_i + sum_k G_k h_ki) (eq. L16).
    double committed_dashpot_stress(std::size_t i) const;
    // The rate [m/s] that, seen by every dashpot of the committed contact of `contact` cells, carries the force they
    // carry (their rates weighted by the line load per unit Q/4, unit_load: F = 2 dx sum_i u_i Q_i/4).
    double force_keeping_rate(std::size_t contact);
    // The fraction of a step of `time_step` [s] to `depth` [m] at which the axis touches again, the edge function at
    // the axis `axis` at its end (committed state: its start).
    double regain_fraction(double time_step, double depth, double axis) const;
    // q of the contact set [0, contact) for the step's coefficients and depth (O(m^2) for m cells in contact; zero
    // beyond), then w1 of the cells in contact (d - g) and of the first `free_cells` free cells beyond (O(m) each).
    void solve_load(std::size_t contact, double depth);
    void free_surface(std::size_t contact, double depth, std::size_t free_cells);
    // The relaxed parts of cell i's Q/4 for a step of coefficients E_k = `decay`, B_k = `gain` and eta/dt =
    // `dashpot` (relaxed_, free_relaxed_: eq. L16).
    void prepare_cell(std::size_t i, const double* decay, const double* gain, double dashpot);
    // Commits cell i's trial w1 and Q/4, its branches stepped by E_k = `decay`, B_k = `gain`.
    void commit_cell(std::size_t i, const double* decay, const double* gain);
    // Records a committed step (its coefficients, q on its `contact` cells) while cells are left out of the stepping.
    void record(std::size_t contact, double dashpot);
    // Steps the cells from kept_ up to `count` through the recorded steps, and keeps them (kept_ = count).
    void catch_up(std::size_t count);
    // catch_up, then the new kept cells' relaxed parts for the step being solved (eta/dt = `dashpot`).
    void keep(std::size_t count, double dashpot);
    // Overwrites the first `contact` values, a right side, with the solution of (I - K) q = it on the contact's cells.
    void solve_contact(std::size_t contact, double* values) const;
    // q for Q = 4 on the contact set [0, contact) (its line load per unit of Q/4), solved once per set.
    const std::vector<double>& unit_load(std::size_t contact);

    const rheology::Rheology* material_;
    const profile::Profile* indenter_;  // its g^-1 (contact_radius) for edge_radius
    bool flat_punch_;
    double spacing_;
    std::size_t cells_;
    std::vector<double> centre_, profile_;  // x_i, g(x_i)
    std::shared_ptr<const LayerOperator> operator_;  // I - K and its Cholesky factor
    std::vector<double> displacement_;      // w1_i, committed
    std::vector<double> branches_;          // h_ki, per cell its branches together
    std::vector<double> stress_;            // Q_i / 4 = ((I - K) q)_i / 4, committed (a free cell's dashpot rate)
    std::size_t contact_ = 0;               // committed contact cells
    double depth_ = 0.0;                    // d, committed
    // dd/dt the dashpots saw at the committed node (solved depths), the riding indenter's own at zero force; none
    // where not known (from rest, after a spring's free hang or a jump onto the surface or to zero force)
    std::optional<double> rate_;
    LayerCellState last_;                   // the state after the last step
    double axis_weight_ = 0.0;              // lambda: the axis from the two innermost cells, linear in g
    double axis_ = 0.0;                     // the committed edge function at the axis (> 0: touching)
    // The step being solved: coefficients, the relaxed part of Q/4 per cell without the dashpot (in contact) and
    // with it (free), the trial q, w1 and Q/4.
    foundation::StepCoefficients coefficients_;
    double springs_ = 0.0;         // G_inf + sum_k G_k B_k: Q/4 per w1 in contact, the dashpot apart
    double free_stiffness_ = 0.0;  // springs + 2 eta/dt: a free cell's Q/4 per w1 (trapezoidal rate)
    double free_compliance_ = 0.0; // 1 / free_stiffness
    double dashpot_gain_ = 0.0;    // eta/dt times 2 (trapezoidal) or 1 (secant): the contact's dashpot per dd
    double dashpot_offset_ = 0.0;  // -eta rate0 (trapezoidal) or 0
    // Cells [entering_from_, contact) of a trial set entered contact in the step and take the free law (their own
    // rate, RateAtEntry::breaks in a step with a start rate: the committed contact's count), else cells_.
    std::size_t entering_from_ = 0;
    std::vector<double> relaxed_, free_relaxed_, trial_load_, trial_displacement_, trial_stress_;
    std::vector<bool> tried_;                      // the contact sets tried in a step
    std::vector<std::vector<double>> unit_loads_;  // unit_load per contact set, empty until first needed
    // A free cell's surface changes nothing until the contact reaches it, or its neighbour: only the cells [0, kept_)
    // are stepped (kept_ >= the contact's cells + 1, and 2 for the axis), the others (at rest, free from the start)
    // are stepped through the record of the steps when the contact comes near (catch_up). Per step: E_k, B_k,
    // eta/dt and the free compliance; q of its contact's cells, from history_offsets_[t].
    std::size_t kept_ = 0;
    std::vector<double> history_steps_, history_loads_;
    std::vector<std::size_t> history_offsets_;
};

}  // namespace mdr::drivers
