#pragma once
/// \file
/// The tangential degree of freedom of the MDR foundation's elements with local Coulomb friction (handbook
/// section 6, eq. 41-51).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mdr/foundation/entry_shares.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {

/// Tangential state of an element after a step.
enum class TangentialState : std::uint8_t {
    free,   ///< out of contact (or entering it in this step): force-free, relaxing
    stick,  ///< in contact, moved with the indenter (eq. 50, first case)
    slip,   ///< in contact, at the friction limit |F_x| = mu F_N (eq. 50, second case; also when held there)
};

/// Tangential elements beside a normal Foundation, at the same x_i = (i + 1/2) dx. Element i has the material's
/// rheology with tangential stiffness k_x(t) = (8/3) G(t) dx (eq. 11, 41-43). State: the element's tangential
/// displacement u_i [m] (eq. 42's u1D), one memory variable per relaxation branch (exact exponential update of
/// step_coefficients.hpp) and its TangentialState. The element "stress" t_i = G_inf u + eta u' + sum_k G_k h_k
/// [Pa] gives F_x,i = (8/3) dx t_i.
///
/// Rule of a step in which the indenter moves tangentially by du (eq. 50): an element in normal contact at the end
/// of the step first sticks (u_i += du); if then |F_x,i| > mu F_N,i it slips and F_x,i = mu F_N,i with the sign of
/// its trial force (the sign of du for an element at rest), u_i solved from that force. An element entering contact
/// was force-free, so it carries no tangential force at entry and takes only the part of du after its entry,
/// (1 - fraction) du with the fraction of the Foundation's Entry (the motion linear over the step); without the
/// entries the rule takes the entry at the start of the step (first order in du for the elements entering while
/// the indenter moves tangentially). Elements out of contact
/// at the end of the step are force-free and keep relaxing (t_i = 0 solved each step). The dashpot of a material
/// with eta > 0 sees the step's secant rate (exact for sticking elements under a linear motion, first order in
/// dt for free and slipping ones).
class TangentialLayer {
public:
    /// `count` elements of width `spacing` [m] of material `material` (copied), friction coefficient `friction` (mu).
    TangentialLayer(const rheology::Rheology& material, double friction, double spacing, std::size_t count);

    /// Prepares a step of the given coefficients from the current state (call before trial_force/advance), with
    /// the elements that enter normal contact inside it (Foundation::entries after its step).
    void begin_step(const StepCoefficients& coefficients, std::span<const Entry> entries = {});
    /// Prepares a step of no time against a parallel dashpot (a normal force jump, Foundation::jump; call after it,
    /// in place of begin_step, then trial_force/sliding_force/sliding_increment/advance as for a step): a dashpot
    /// does not move in no time, so every u_i and h_{k,i} stays and only the rates jump (docs/theory.md section 4b,
    /// eq. T1). The increment those take is then not a displacement but the stress eta du' [Pa] the indenter's rate
    /// change du' adds to each element in contact: t_i' = clamp(t_i + increment, +-mu F_N,i') in contact, 0 out of
    /// it (rule 50 with the new normal loads, from the stress t_i before the jump, its dashpot's part included).
    /// Needs a material with a parallel dashpot (eta > 0).
    void begin_jump();
    /// Total tangential force [N] (eq. 46, both halves) the layer would carry after the prepared step with the
    /// indenter moving by `increment` [m]; `normal_line_loads` q_z,i = F_N,i/dx [N/m] and `contact` are those of
    /// the normal foundation at the end of the step, of the same length, at most size(): the elements from there
    /// on are out of contact (pass at least the elements the foundation has ever touched, and never fewer than
    /// before). The state is not changed.
    double trial_force(double increment, std::span<const double> normal_line_loads,
                       std::span<const double> contact) const;
    /// The largest |F_x| [N] the contact can carry at the end of the prepared step: mu F_N (gross sliding beyond).
    double sliding_force(std::span<const double> normal_line_loads, std::span<const double> contact) const;
    /// The smallest increment [m] in the direction `direction` (+1 or -1) that puts every element in contact at its
    /// friction limit (the onset of gross sliding) in the prepared step; 0 when nothing is in contact.
    double sliding_increment(double direction, std::span<const double> normal_line_loads,
                             std::span<const double> contact) const;
    /// Number of elements.
    std::size_t size() const { return displacement_.size(); }
    /// Doubles of the state that persists between steps (saved by save_state) for `count` elements and `branches`
    /// relaxation branches: 2 + count (branches + 4).
    static std::size_t state_size(std::size_t count, std::size_t branches) { return 2 + count * (branches + 4); }
    /// Writes the persistent state (force, touched elements; u_i, t_i, state, limit, h_{k,i}) into `out`; the
    /// untouched elements are left as they are there.
    void save_state(std::span<double> out) const;
    /// Replaces the state with one written by save_state (or zeros) by a layer of the same size and material. Call
    /// begin_step after it.
    void load_state(std::span<const double> in);
    /// Advances the state over the prepared step (arguments as for trial_force).
    void advance(double increment, std::span<const double> normal_line_loads, std::span<const double> contact);

    /// Total tangential force F_x [N] after the last step (eq. 46, both halves).
    double total_force() const { return total_force_; }
    /// Work [J] of the element forces on the element displacements over the last step (both halves), exact for u_i
    /// linear in time over the step: int t du = du [G_inf (u0 + u1)/2 + eta du/dt + sum_k G_k (B_k h_k0 +
    /// du (1 - B_k) tau_k/dt)] from h_k' = u' - h_k/tau_k. What the material stores and dissipates.
    double material_work() const { return material_work_; }
    /// Work [J] of the element forces on the slip of the last step (both halves): for each element in contact at
    /// the end, the mean of its start and end force times increment - du_i. What friction dissipates.
    double friction_work() const { return friction_work_; }
    /// dF_x/du [N/m] of the prepared step over the elements that stuck in the last step.
    double stick_slope() const;
    /// Number of elements that stuck in the last step (0: every element in contact slipped).
    std::size_t sticking_count() const { return sticking_; }
    /// Stick radius c [m] (eq. 51): the edge of the stick zone around the centre, between the last sticking
    /// element and the first slipping one, where the friction limit mu F_N(x) (linear between the two centres)
    /// equals the sticking element's force. `contact_radius` when no element in contact slips, 0 when the centre
    /// element slips or nothing is in contact.
    double stick_radius(double contact_radius) const;
    /// Tangential line load q_x,i = F_x,i / dx = (8/3) t_i [N/m] (eq. 45).
    std::vector<double> line_loads() const;
    /// Tangential element displacements u_i [m].
    std::span<const double> displacements() const { return displacement_; }
    /// State of each element after the last step.
    std::span<const TangentialState> states() const { return state_; }

private:
    double limit(double normal_line_load) const;

    rheology::Rheology material_;  // a copy: the caller's material may be a temporary
    double per_load_;                       ///< mu / (8/3): the friction limit [Pa] per unit line load [N/m]
    double spacing_;
    std::vector<double> displacement_;      ///< u_i
    std::vector<double> stress_;            ///< t_i at the end of the last step
    std::vector<double> memory_;            ///< h_{k,i}, branch-major: memory_[k * n + i]
    std::vector<TangentialState> state_;
    std::vector<double> relaxed_;           ///< G_inf u_i + sum_k G_k E_k h_{k,i} for the prepared step
    std::vector<double> limit_;             ///< mu F_N,i / ((8/3) dx) at the end of the last step [Pa]
    EntryShares share_;                     ///< part of the prepared step's increment each element takes
    std::vector<double> increment_;         ///< du_i of the step being taken
    std::vector<double> work_;              ///< int t_i du_i over it [Pa m]: the element's material work / ((8/3) dx)
    std::vector<double> slip_work_;         ///< friction's work on the element over it / ((8/3) dx) [Pa m]
    std::vector<double> contact_mask_;      ///< 1 for an element in contact in the step being taken, else 0
    std::vector<double> rate_gain_;         ///< (1 - B_k) tau_k / dt of the prepared step, one per branch
    StepCoefficients step_;
    bool jump_ = false;                     ///< the prepared step is a jump (begin_jump): no element moves
    std::size_t touched_ = 0;               ///< elements [touched_, n) have never been in contact: u = h = 0
    std::size_t high_water_ = 0;            ///< the largest touched_ any loaded or stepped state had
    std::size_t sticking_ = 0;              ///< elements that stuck in the last step
    double total_force_ = 0.0;
    double material_work_ = 0.0;
    double friction_work_ = 0.0;
};

}  // namespace mdr::foundation
