#pragma once
/// \file
/// The 1D viscoelastic foundation of the MDR (handbook section 4, Fig. 1; section 5, eq. 13-22).

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {

/// Most elements a foundation may have: beyond, the state would need more memory than the machines we target.
inline constexpr std::size_t max_elements = std::size_t{1} << 28;

/// Throws mdr::InvalidInput naming `key` unless 1 <= `count` <= max_elements (`numerics.elements`, `fit.elements`).
void require_element_count(const std::string& key, std::size_t count);

/// Whether the state of `count` elements with `branches` relaxation branches fits the memory we allow: at most
/// max_elements elements and count (branches + 9) doubles of state at most 4 max_elements (the drivers' Foundation
/// and the fit's band model both refuse a larger one).
bool state_fits(std::size_t count, std::size_t branches);

/// The deepest depth (m) a foundation on the half-width [0, `half_width`] (m) under `profile` takes: the equivalent
/// profile g just beyond the half-width, or at it where a tabulated profile ends there (g is +infinity beyond, where
/// nothing is known). A flat punch keeps its rigid wall (+infinity) beyond its radius.
double deepest_depth(const profile::Profile& profile, double half_width);

/// What the indenter's rate does where an element enters contact inside a step; it decides what that element's
/// parallel dashpot sees (Foundation::begin_step).
enum class RateAtEntry {
    continuous,  ///< the depth is given, or carried by the indenter's inertia (displacement control, a DEM overlap,
                 ///< an impact): the force steps by the entering element's dashpot
    breaks,      ///< a massless indenter under a force that is given or follows the depth (force and spring control):
                 ///< the force is continuous and the rate breaks, the dashpots in contact sharing the force
};

/// An element that came into contact inside the last step, and where (eq. 14).
struct Entry {
    std::size_t element;  ///< its index i
    double fraction;      ///< where inside the step (0..1) it entered
};

/// A row of independent viscoelastic elements at x_i = (i + 1/2) dx, i = 0 .. n-1, on the half-width [0, L]
/// (the foundation is symmetric; totals count both halves). Each element has the rheology of the material with
/// normal stiffness k_z(t) = 4 G(t) dx (eq. 11). State per element: displacement w_i (positive into the body),
/// one memory variable per relaxation branch, a contact flag and the last "stress" sigma_i (force / (4 dx)).
///
/// An element in contact follows the indenter, w = d - g(x) (eq. 13); it leaves contact when holding it would
/// need a tensile force (eq. 20) and is then force-free: it keeps creeping back, and re-enters when the indenter
/// reaches its current surface position (eq. 14). Between steps the depth is linear in time, so every update is
/// exact; the instants of entry and exit are located inside the step by linear interpolation of the crossing
/// quantity and the element's update is split there (second order in the time step).
class Foundation {
public:
    /// `count` elements of width `spacing` [m] under the MDR profile of `profile`, material `material` (copied;
    /// the profile is only read here).
    /// Throws mdr::InvalidInput (key `numerics.elements`) when the state would not fit in memory.
    Foundation(const rheology::Rheology& material, const profile::Profile& profile, double spacing,
               std::size_t count);

    /// Number of elements on the half-width.
    std::size_t size() const { return equivalent_.size(); }
    /// Element width dx [m].
    double spacing() const { return spacing_; }
    /// Half-width L = n dx [m].
    double half_width() const { return spacing_ * static_cast<double>(size()); }
    /// Centre x_i [m] of element i.
    double position(std::size_t i) const { return (static_cast<double>(i) + 0.5) * spacing_; }

    /// Prepares a step of the given coefficients from the current state (call before trial_force/advance).
    /// `indenter_rate` is dd/dt at the start of the step when the depth is solved (impact, force control): a
    /// dashpot in contact then sees the trapezoidal end rate 2 (d1 - d0)/dt - rate (second order). Without it
    /// it sees the step's secant rate, exact for a prescribed piecewise-linear depth. Force-free elements always
    /// take the trapezoidal rate from their own start rate.
    /// An element entering contact inside the step follows the indenter's rate at once where the rate is `continuous`
    /// (exact: the force steps by its dashpot's). Where it `breaks`, the entering element's dashpot sees the rate of
    /// its own motion over the step by the indenter's rule: with `indenter_rate` the trapezoidal 2 (w1 - w0)/dt minus
    /// its free start rate -(G_inf w0 + sum G_k h_k)/eta, without it the secant (w1 - w_e)/dt + f w'_e (f the entry's
    /// fraction of the step, w_e and w'_e the free element's displacement and rate there). At an entry at the step's
    /// very end that is the free element's end rate, so its force grows from zero and the total force is continuous
    /// in the end depth (the balance has a root), and the dashpots in contact together carry the rate's break at the
    /// entry (docs/theory.md section 3).
    void begin_step(const StepCoefficients& coefficients, std::optional<double> indenter_rate = std::nullopt,
                    RateAtEntry rate_at_entry = RateAtEntry::continuous);
    /// The total normal force [N] (eq. 21) the foundation would carry if the depth went linearly from
    /// `depth_start` to `depth_end` over the prepared step; the state is not changed.
    double trial_force(double depth_start, double depth_end) const;
    /// Where inside the prepared step (0..1) the indenter would first reach an element out of contact (eq. 14, its
    /// creeping surface interpolated linearly as in advance) if the depth went linearly from `depth_start` to
    /// `depth_end`; 1 when it reaches none. The state is not changed.
    double touch_fraction(double depth_start, double depth_end) const;
    /// Advances the state over the prepared step with the depth going linearly from `depth_start` to `depth_end`.
    /// Throws mdr::InvalidInput when the contact reaches the end of the foundation (key `numerics.half_width`)
    /// or of a tabulated profile (key `indenter.r`).
    void advance(double depth_start, double depth_end);

    /// A jump of the total force to `force` [N] >= 0 in no time (two points of a force history at one time) against
    /// the parallel dashpot: a dashpot does not move in no time, so the depth, every w_i and h_{k,i} stay and only
    /// the rates jump (docs/theory.md section 3, eq. J1). An element that stays in contact follows the indenter, its
    /// stress sigma_i + eta dr (dr the indenter's change of rate); one whose stress would be negative leaves at once
    /// (flag 0, force 0: the next step takes it as force-free, at its own rate -(G_inf w + sum_k G_k h_k)/eta). The
    /// kept set {i in contact : sigma_i + eta dr >= 0} and dr solve force = 8 dx sum_set (sigma_i + eta dr). A jump
    /// up keeps every element in contact. A jump to zero force keeps the state (every element would leave and the
    /// rate is not tied to the force; the force rule's dr = -F/(8 dx eta n) is returned, the total force set to
    /// zero). Returns dr [m/s]; none, the state unchanged, when nothing is in contact (the rate is then unknown).
    /// Call after a step (advance), with a parallel dashpot.
    std::optional<double> jump(double force);
    /// Total normal force [N] after the last step or jump (eq. 21, both halves).
    double total_force() const { return total_force_; }
    /// Contact radius a [m] after the last step or jump: at a jump that receded the contact (jump), between the
    /// outermost element in contact and its neighbour that left, where the stress after the jump (the neighbour's
    /// sigma + eta dr < 0) crosses zero, interpolated linearly (eq. J2). Otherwise the edge between the outermost
    /// element in contact and its free neighbour, where the free gap d - g - w, extrapolated linearly in g from the
    /// two free neighbours, reaches zero (exact in g where the surface was never touched, second order in dx where
    /// it left contact without a parallel dashpot); with one, the nearer of that and the zero of the stresses inside,
    /// extrapolated in g from the two outermost elements in contact (a receding edge's gap opens quadratically, its
    /// stresses fall linearly: docs/theory.md section 3); x is interpolated linearly in g between the two centres. 0
    /// when the total force is 0: nothing carries a load.
    double contact_radius() const;
    /// The weight lambda <= 0 of the linear extrapolation in g from the two innermost elements to the axis,
    /// (g(0) - g_0) / (g_1 - g_0) (0 for a flat profile): a quantity q linear in g near the axis is
    /// (1 - lambda) q_0 + lambda q_1 there. When the contact shrinks to the axis, the exit time and the free gap
    /// are such quantities.
    double axis_weight() const;
    /// Where inside the last step (0..1) element i < 2 left contact; -1 when it did not leave in it.
    double inner_exit(std::size_t i) const { return inner_exit_[i]; }
    /// The largest depth [m] at which the indenter does not press on the free surface: the lowest g_i + w_i, with
    /// the surface at the axis extrapolated (axis_weight) so that a tip riding there is located to O(dx^2).
    double touching_depth() const;
    /// The elements that came into contact inside the last step (none with a stale entry from an older step).
    std::span<const Entry> entries() const { return entries_; }
    /// Elements [0, touched()) have been in contact at some time; the others have w = h = 0 and never touched.
    std::size_t touched() const { return active_; }
    /// Number of elements in contact.
    std::size_t contact_count() const;
    /// Where inside the last step (0..1) the last element to leave contact in it left (its force crossing zero,
    /// interpolated linearly); 0 when none left.
    double latest_exit() const { return latest_exit_; }
    /// dF/dd [N/m] of the prepared step while no element enters or leaves: 8 dx K n_contact (eq. 21), K the
    /// step's stiffness.
    double force_slope() const;
    /// The mean rate [m/s] that the dashpots of the elements in contact saw at the end of the last step: the
    /// indenter's end rate (see begin_step), with an element that entered in it taking its own; with that as the
    /// next step's start rate, the next step starts with the force these dashpots carried.
    double contact_rate() const;

    /// Doubles of the state that persists between steps (saved by save_state) for `count` elements and `branches`
    /// relaxation branches: 3 + count (branches + 3).
    static std::size_t state_size(std::size_t count, std::size_t branches) { return 3 + count * (branches + 3); }
    /// Writes the persistent state (depth, force, touched elements; w_i, sigma_i, contact flag, h_{k,i}) into `out`
    /// (state_size(size(), branches) doubles); the untouched elements are left as they are there.
    void save_state(std::span<double> out) const;
    /// Replaces the state with one written by save_state (or zeros: no contact yet) by a foundation of the same
    /// size and material. Call begin_step after it.
    void load_state(std::span<const double> in);
    /// Doubles of a state stepped in place (attach) for `count` elements and `branches` relaxation branches: 3 +
    /// count (branches + 2): depth, force, touched elements; w_i, contact flag, h_{k,i} (no stresses: derive_stresses).
    static std::size_t attached_size(std::size_t count, std::size_t branches) { return 3 + count * (branches + 2); }
    /// Steps the state in place in `state` (attached_size doubles written by this foundation's steps or zeros; zero
    /// beyond the touched elements; the caller has checked the touched count) instead of the foundation's own
    /// buffers: every advance reads and writes the elements' displacements, contact flags (0 or 1) and memories
    /// there, and the depth, force and touched count, until the next attach or load_state. No copy in or out. The
    /// state keeps no stresses: they stay in the foundation's own buffer (derive_stresses). Call begin_step after it;
    /// `state` must outlive the steps.
    void attach(std::span<double> state);
    /// Sets the attached elements' stresses at the start of the step from their state (eq. 16): G_inf w + eta rate +
    /// sum_k G_k h_k in contact, 0 out of it, `rate` [m/s] the dashpots' rate at the end of the last step (its
    /// secant rate for a DEM overlap). Only an exit's location inside the step reads them (equal to round-off to
    /// the stresses the last step left; an entering element's stress clamped at zero there is its raw value here,
    /// which locates an exit at the step's start either way).
    void derive_stresses(double rate);
    /// Reserves room for an event at every element, so that no later step allocates.
    void reserve_events();
    /// Line loads q_z,i [N/m] of the first out.size() <= size() elements into `out`, without allocating.
    void line_loads(std::span<double> out) const;

    /// Element displacements w_i [m].
    std::span<const double> displacements() const { return {element_displacements(), size()}; }
    /// Line load q_z(x_i) = F_N(x_i)/dx = 4 sigma_i [N/m] (eq. 22).
    std::vector<double> line_loads() const;
    /// MDR profile g(x_i) [m] at the element centres.
    std::span<const double> equivalent_profile() const { return equivalent_; }
    /// Contact flags: 1 in contact, else 0 (doubles, as the state holds them, so that the element passes that read
    /// them have one element width and vectorise).
    std::span<const double> contact_flags() const { return {element_flags(), size()}; }

private:
    struct Outcome;
    // The step of element i from its displacement w0 and stress sigma0 at the start (the state's before advance
    // overwrites them in place).
    Outcome evaluate(std::size_t i, double w0, double sigma0, double depth_start, double depth_end) const;
    // The indenter's rate at the start and the end of the prepared step, the depth going linearly from depth_start
    // to depth_end (see begin_step).
    std::pair<double, double> indenter_rates(double depth_start, double depth_end) const;
    double split_stress(std::size_t i, double w0, const Outcome& outcome, double depth_start, double depth_end,
                        double& w, double* h, double* own_rate = nullptr) const;
    void clear_beyond(std::size_t active);
    // w_i, the flags and h_{k,i}: the attached state's, else the foundation's own (found per call, so that a copy
    // never points into the original's buffers); sigma_i always the foundation's own.
    double* element_displacements() { return attached_ != nullptr ? attached_ + 3 : displacement_.data(); }
    const double* element_displacements() const {
        return attached_ != nullptr ? attached_ + 3 : displacement_.data();
    }
    double* element_stresses() { return stress_.data(); }
    const double* element_stresses() const { return stress_.data(); }
    double* element_memories() { return attached_ != nullptr ? attached_ + 3 + 2 * size() : memory_.data(); }
    const double* element_memories() const {
        return attached_ != nullptr ? attached_ + 3 + 2 * size() : memory_.data();
    }
    double* element_flags() { return attached_ != nullptr ? attached_ + 3 + size() : flags_.data(); }
    const double* element_flags() const { return attached_ != nullptr ? attached_ + 3 + size() : flags_.data(); }
    double spring_force(double w, const double* h) const;
    double free_rate(double w, const double* h) const;
    void free_substep(double time_step, double& w, double* h) const;
    double contact_substep(double time_step, double new_displacement, double end_rate, double& w, double* h) const;
    double free_gap(std::size_t i) const;
    // Where between the centres of the outermost element in contact j and its free neighbour (0..1) the free gap,
    // extrapolated in g, reaches zero (contact_radius).
    double gap_edge(std::size_t j) const;
    // With a parallel dashpot, where between the same centres (0..1) the stress inside, extrapolated in g from j - 1
    // and j, reaches zero; 1 where it gives no bound (contact_radius).
    double stress_edge(std::size_t j) const;
    double free_relaxed_of(std::size_t i) const { return free_relaxed_.empty() ? relaxed_[i] : free_relaxed_[i]; }
    std::size_t reach(double depth) const;

    rheology::Rheology material_;  // a copy: the caller's material may be a temporary
    double spacing_;
    std::vector<double> equivalent_;           ///< g(x_i)
    std::vector<double> displacement_;         ///< w_i when no state is attached
    std::vector<double> stress_;               ///< sigma_i at the end of the last step
    std::vector<double> memory_;               ///< h_{k,i}, branch-major: memory_[k * n + i], when none is attached
    double* attached_ = nullptr;               ///< the attached state (see attach), else null
    std::vector<double> flags_;                ///< contact flags when no state is attached
    std::vector<double> event_;                ///< 1 where the last step was split by an entry or exit, else 0
    std::vector<double> start_displacement_;   ///< w_i at the start of the step being taken
    std::vector<double> start_stress_;         ///< sigma_i at the start of the step being taken
    std::vector<double> increment_;            ///< dw_i of the step being taken
    std::size_t split_first_ = 0;              ///< the split elements of the step lie in [split_first_, split_end_)
    std::size_t split_end_ = 0;
    std::vector<double> relaxed_;              ///< G_inf w_i + sum_k G_k E_k h_{k,i} for the prepared step
    std::vector<double> free_relaxed_;         ///< with a dashpot: relaxed_ - eta w'_i(start) of a free element
    std::optional<double> indenter_rate_;      ///< see begin_step
    RateAtEntry rate_at_entry_ = RateAtEntry::continuous;  ///< see begin_step
    double end_rate_ = 0.0;      ///< the indenter's rate at the end of the last step (see begin_step)
    double entry_excess_ = 0.0;  ///< the sum of the entering elements' own rates less end_rate_, last step
    double contact_stiffness_ = 0.0;           ///< dsigma/dw of an element in contact over the prepared step
    double contact_offset_ = 0.0;              ///< -eta rate0 with the trapezoidal rate, else 0
    double free_stiffness_ = 0.0;              ///< dsigma/dw of a force-free element over the prepared step
    mutable std::vector<double> scratch_;      ///< per-branch memory of a trial split update
    mutable std::vector<double> scratch_gain_; ///< per-branch B_k of a sub-step
    std::vector<std::size_t> split_;           ///< elements whose step is split by an event
    std::vector<Entry> entries_;               ///< see entries()
    std::vector<double> split_state_;          ///< their new w, sigma and memory, (branches + 2) each
    double axis_ = 0.0;                        ///< g(0)
    std::array<double, 2> inner_exit_{-1.0, -1.0};  ///< see inner_exit()
    double beyond_ = 0.0;                      ///< g just beyond the half-width (or at it, see profile_ends_)
    bool profile_ends_ = false;                ///< the half-width is the end of a tabulated profile
    double profile_end_ = 0.0;                 ///< the profile's last radius (for the message)
    double last_depth_ = 0.0;                  ///< depth at the end of the last step
    double latest_exit_ = 0.0;                 ///< see latest_exit()
    /// After a jump that receded the contact: the stress sigma + eta dr < 0 the first element beyond the outermost
    /// one in contact would have had (it left at the jump); none after a step (contact_radius).
    std::optional<double> receded_stress_;
    StepCoefficients step_;
    std::size_t active_ = 0;                   ///< elements [active_, n) have never been touched: w = h = 0
    std::size_t high_water_ = 0;               ///< the largest active_ any loaded or stepped state had
    double total_force_ = 0.0;
};

}  // namespace mdr::foundation
