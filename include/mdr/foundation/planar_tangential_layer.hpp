#pragma once
/// \file
/// The tangential degrees of freedom of the MDR foundation's elements in the plane of the contact: two components
/// per element with local, isotropic Coulomb friction (handbook section 6, eq. 41-51, with the element's force a
/// vector in the tangent plane).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mdr/foundation/entry_shares.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {

/// A vector in the tangent plane of a contact [m] or [N]: components along the contact frame's two axes.
using PlanarVector = std::array<double, 2>;

/// Tangential elements beside a normal Foundation, at x_i = (i + 1/2) dx, each with a displacement vector u_i in
/// the tangent plane. Element i has the material's rheology in each direction, stiffness k_x(t) = (8/3) G(t) dx
/// (eq. 11, 41-43); the element "stress" t_i = G_inf u_i + eta u_i' + sum_k G_k h_k,i [Pa] (one memory vector per
/// relaxation branch, exact exponential update of step_coefficients.hpp) gives F_i = (8/3) dx t_i.
///
/// Rule of a step in which the indenter moves by du (a vector, eq. 50 with the friction limit a circle): an element
/// in normal contact at the end of the step first sticks, t_i = relaxed_i + k du; if then |t_i| > mu q_z,i / (8/3)
/// it slips, t_i = that limit along its trial, u_i solved from it. An element entering contact takes the part of du
/// after its entry (as TangentialLayer); out of contact an element is force-free and relaxes. For a motion along
/// one fixed direction this is TangentialLayer's rule operation for operation (the same forces to round-off); for
/// a motion that turns, each element keeps its own force direction (Mindlin-Deresiewicz's memory of the path).
class PlanarTangentialLayer {
public:
    /// `count` elements of width `spacing` [m] of material `material` (copied), friction coefficient `friction` (mu).
    PlanarTangentialLayer(const rheology::Rheology& material, double friction, double spacing, std::size_t count);

    /// Prepares a step of the given coefficients from the current state, with the elements that enter normal
    /// contact inside it (Foundation::entries after its step). The coefficients must be this layer's material's
    /// (step_coefficients): they are copied only when the time step changes.
    void begin_step(const StepCoefficients& coefficients, std::span<const Entry> entries = {});
    /// Total tangential force [N] (eq. 46, both halves) the layer would carry after the prepared step with the
    /// indenter moving by `increment` [m]; `normal_line_loads` q_z,i [N/m] and `contact` as for
    /// TangentialLayer::trial_force. The state is not changed.
    PlanarVector trial_force(PlanarVector increment, std::span<const double> normal_line_loads,
                             std::span<const double> contact) const;
    /// Advances the state over the prepared step (arguments as for trial_force).
    void advance(PlanarVector increment, std::span<const double> normal_line_loads,
                 std::span<const double> contact);
    /// Total tangential force [N] after the last step (eq. 46, both halves).
    PlanarVector total_force() const { return total_force_; }
    /// Whether every element in normal contact stuck in the last advance (none slipped, eq. 50).
    bool stuck() const { return stuck_; }
    /// Number of elements.
    std::size_t size() const { return count_; }
    /// Elements [0, touched()) have been in normal contact during a step; the others have u = h = 0.
    std::size_t touched() const { return touched_; }

    /// Doubles of the state that persists between steps for `count` elements and `branches` relaxation branches:
    /// 3 + count (2 branches + 2) (force, touched elements; u_i and h_{k,i}, two components each, component by
    /// component; the element stresses t_i are recomputed by every step, not kept).
    static std::size_t state_size(std::size_t count, std::size_t branches) { return 3 + count * (2 * branches + 2); }
    /// Offset in the state of the number of touched elements (an integer in [0, size()]).
    static constexpr std::size_t touched_offset = 2;
    /// Writes the persistent state into `out`; the untouched elements are left as they are there.
    void save_state(std::span<double> out) const;
    /// Replaces the state with one written by save_state (or zeros) by a layer of the same size and material; the
    /// caller has checked the touched count. Call begin_step after it.
    void load_state(std::span<const double> in);
    /// Steps the state in place in `state` (state_size doubles written by this layer's steps, save_state or zeros;
    /// the caller has checked the touched count) instead of the layer's own buffers: the elements' displacements and
    /// memories are read and written there, and every advance writes the force and the touched count back, until
    /// the next attach or load_state. No copy in or out. Call begin_step after it; `state` must outlive the steps.
    void attach(std::span<double> state);

private:
    // u_i and h_{k,i}: the attached state's, else the layer's own (found per call, so that a copy of the layer
    // never points into the original's buffers).
    double* displacements() { return header_ != nullptr ? header_ + 3 : displacement_.data(); }
    const double* displacements() const { return header_ != nullptr ? header_ + 3 : displacement_.data(); }
    double* memories() { return header_ != nullptr ? header_ + 3 + 2 * count_ : memory_.data(); }
    const double* memories() const { return header_ != nullptr ? header_ + 3 + 2 * count_ : memory_.data(); }

    // Structure of arrays: component c of element i at [c * n + i]; memory branch-major, memory_[k * 2 n + c n + i].
    rheology::Rheology material_;  // a copy: the caller's material may be a temporary
    double per_load_;              ///< mu / (8/3): the friction limit [Pa] per unit line load [N/m]
    double spacing_;
    std::size_t count_;
    std::vector<double> displacement_;  ///< u_i when no state is attached
    std::vector<double> stress_;        ///< t_i of the step being taken (not part of the state)
    std::vector<double> memory_;        ///< h_{k,i} when no state is attached
    double* header_ = nullptr;          ///< the attached state (force, touched count, u_i, h_{k,i}), else null
    std::vector<double> weight_;        ///< G_k E_k of the prepared step: h_k's share of the relaxed stress
    EntryShares share_;                 ///< part of the prepared step's increment each element takes
    StepCoefficients step_;
    bool prepared_ = false;             ///< step_ and weight_ hold a step's (begin_step)
    bool stuck_ = false;                ///< no element in contact slipped in the last advance
    std::size_t touched_ = 0;           ///< elements [touched_, n) have never been in contact: u = h = 0
    std::size_t high_water_ = 0;        ///< the largest touched_ any loaded or stepped state had
    PlanarVector total_force_{0.0, 0.0};
};

}  // namespace mdr::foundation
