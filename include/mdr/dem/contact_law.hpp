#pragma once
/// \file
/// The MDR contact of two viscoelastic spheres as a contact law for time-stepping (DEM) codes: the state of each
/// contact lives in the caller's memory; the law steps it with the library's own Foundation and a
/// PlanarTangentialLayer (the tangential displacement a vector in the contact's tangent plane).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mdr/foundation/composed_normal_step.hpp"
#include "mdr/foundation/composed_tangential_step.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/planar_tangential_layer.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::dem {

/// A tangential vector in the contact frame: components along its two axes [m] or [N].
using PlanarVector = foundation::PlanarVector;
/// A vector in the caller's three-dimensional frame.
using SpatialVector = std::array<double, 3>;

/// The contact law of one kind of contact (two sphere types). Sphere-sphere contact maps onto a rigid sphere of the
/// equivalent radius R = R1 R2 / (R1 + R2) on a half-space with the combined creep function J = J1 + J2 (eq. 8;
/// both bodies incompressible). The law owns a workspace — one Foundation (section 5) and one
/// PlanarTangentialLayer (section 6) of N elements on the half-width L — and no contact's state: a contact's state
/// is state_size() doubles in the caller's memory (a pair style's per-contact history, say), zeroed by
/// initialise() at first touch; the elements are stepped in place there (no copy into the workspace and back),
/// the workspace keeps only what a step derives. While no element enters or leaves normal contact the normal step
/// is composed in the state's header (foundation::ComposedNormalStep, O(M)): it reads and writes the header only,
/// not the elements; while, besides, every element in contact sticks, so is the tangential step (a second header,
/// foundation::ComposedTangentialStep), from the step after one in which the layer's elements all stuck. A step of
/// one contact:
///
///     law.begin(state);                      // attaches the contact's state (its header checked)
///     law.normal_trial(overlap);             // optional: F_N for a trial overlap (an implicit integrator's solve)
///     law.advance_normal(overlap);           // the new normal overlap (eq. 13-22)
///     law.tangential_trial(displacement);    // optional: the tangential force for a trial displacement
///     law.advance_tangential(displacement);  // the new tangential displacement of the contact point (eq. 41-51)
///     law.end(state);                        // the tangential displacement and the frame into the state
///
/// or law.advance(state, overlap, displacement) for the four calls without trials, or advance_spatial for a code
/// that works with three-dimensional vectors (the contact frame then lives in the state and turns with the
/// normal). The state must stay in place between begin and end. Between begin and end the overlap and the
/// displacement go linearly in time over the step (the elements' updates are exact for that); a dashpot sees the
/// secant rate. The time step may change between steps (set_time_step). Nothing allocates after construction. One
/// law per thread (the workspace is its).
///
/// The tangential displacement is that of the first body's contact point relative to the second's; the tangential
/// force is the force on the second body (the first feels its opposite); both are components in the contact frame.
class ContactLaw {
public:
    /// `material` the combined rheology, `radius` R [m] the equivalent radius, `friction` mu >= 0, `elements` N on
    /// the half-width `half_width` L [m] (it must cover the largest contact radius, sqrt(R d_max) for a sphere),
    /// `time_step` dt [s] > 0 of the first step. Throws mdr::InvalidInput naming these parameters.
    ContactLaw(const rheology::Rheology& material, double radius, double friction, std::size_t elements,
               double half_width, double time_step);

    /// Doubles of one contact's state for N elements and M relaxation branches: 2 M^2 + 16 M + 31 + N (3 M + 4).
    static std::size_t state_size(std::size_t elements, std::size_t branches);
    /// state_size for this law's N and M.
    std::size_t state_size() const { return state_size_; }
    /// Doubles at the start of a contact's state that every step reads and writes (the displacement, the frame, the
    /// composed normal step's header, the overlap, normal force and element count): all that a held step without
    /// friction writes (a code may prefetch them; docs/dem-performance.md, "Is the step memory-bound?").
    std::size_t held_step_size() const { return normal_offset_ + 3; }
    /// Besides these, a held step touches held_tangential_size() doubles from held_tangential_offset() (a code may
    /// prefetch them too): with friction, where every element sticks, the composed tangential step's header and the
    /// layer's force and element count; without friction the layer's element count alone (begin reads it: a layer
    /// never touched stays at rest).
    std::size_t held_tangential_offset() const {
        return friction_ > 0.0 ? tangential_header_offset_
                               : tangential_offset_ + foundation::PlanarTangentialLayer::touched_offset;
    }
    /// See held_tangential_offset().
    std::size_t held_tangential_size() const { return friction_ > 0.0 ? tangential_size_ + 3 : 1; }
    /// Zeroes a contact's state at first touch (state_size() doubles).
    void initialise(std::span<double> state) const;
    /// Throws mdr::InvalidInput (key `state[i]`) unless `state` is a state this law could have written: state_size()
    /// doubles, all finite, element counts within N, contact flags 0 or 1 and as many as the header counts, the
    /// header's flag "composed" 0 or 1 with composition factors in (0, 1] and a summary of the written elements
    /// that is theirs (ComposedNormalStep::summary_mismatch), the same of the tangential header
    /// (ComposedTangentialStep::summary_mismatch; while it composes, the layer touched what the Foundation did and
    /// no more elements are in contact than the normal header counts), a unit frame axis with handedness +-1
    /// (or all zero before the first advance_spatial). For states read back from a file (a restart).
    void check(std::span<const double> state) const;
    /// Turns a contact's state into the same contact seen with the two bodies swapped (a code that stores a
    /// contact with either body first): the frame's axes and the normal reverse, so every component stays.
    static void mirror(std::span<double> state);

    /// Sets the length [s] > 0 of the following steps (cheap when unchanged). Throws mdr::InvalidInput.
    void set_time_step(double time_step);
    /// The length [s] of the next step.
    double time_step() const { return coefficients_.time_step; }

    /// Takes a contact's state and prepares its step: the elements are then stepped in place in `state`
    /// (advance_normal and advance_tangential write them there), the tangential displacement and the frame are
    /// written by end(). Throws
    /// mdr::InvalidInput when the state's sizes are not this law's (a corrupted state); check() inspects every value.
    void begin(std::span<double> state);
    /// Total normal force [N] if the step ended at `overlap` [m]. The state keeps its values; where an element
    /// would enter or leave contact its elements are brought up to date first (the composed maps applied).
    double normal_trial(double overlap);
    /// Advances the normal problem to `overlap` [m] over the step. Throws mdr::InvalidInput (key `half_width`)
    /// when the contact would grow beyond the half-width, (key `overlap`) for an overlap that is not finite.
    void advance_normal(double overlap);
    /// Tangential force [N] if the step ended at tangential displacement `displacement` [m] (after
    /// advance_normal), to the bit the force advance_tangential would give. The state keeps its values; where an
    /// element would slip out of a composed tangential step the elements are brought up to date first (the maps
    /// applied, as advance_tangential does).
    PlanarVector tangential_trial(PlanarVector displacement) const;
    /// Advances the tangential problem to `displacement` [m] (after advance_normal); throws mdr::InvalidInput (key
    /// `displacement`) unless it is finite. A layer never touched stays at rest, unstepped, while the law has no
    /// friction or the displacement does not change (a frictionless or head-on contact: its force is zero).
    void advance_tangential(PlanarVector displacement);
    /// Writes the tangential displacement and the frame into the contact's state (the elements are already there).
    void end(std::span<double> state) const;
    /// begin, advance_normal, advance_tangential, end; a displacement that is not finite raises (key
    /// `displacement`) before the normal step, the state unchanged.
    void advance(std::span<double> state, double overlap, PlanarVector displacement);
    /// One step for a code with three-dimensional vectors: `normal` the unit normal from the first body to the
    /// second at the end of the step, `increment` [m] the displacement of the first body's contact point relative
    /// to the second's over the step (its normal part is ignored). The contact frame, kept in the state, first
    /// turns into the new tangent plane (its axis projected and rescaled, as LAMMPS's granular history); at first
    /// touch its axis is the increment's direction. Returns the tangential force [N] on the second body. A law
    /// without friction (mu = 0) steps the normal problem only: its tangential force is zero, and the state's
    /// displacement and frame stay as they are (zero from initialise). Throws mdr::InvalidInput (key `normal`,
    /// `increment`) for a vector that is not finite, (key `displacement`) where the displacement in the frame
    /// overflows from finite ones (a normal far from unit length), the state unchanged.
    SpatialVector advance_spatial(std::span<double> state, double overlap, const SpatialVector& normal,
                                  const SpatialVector& increment);

    /// One contact's step for advance_spatial_pair: advance_spatial's arguments.
    struct SpatialStep {
        std::span<double> state;
        double overlap = 0.0;
        SpatialVector normal{0.0, 0.0, 0.0};
        SpatialVector increment{0.0, 0.0, 0.0};
    };
    /// A contact's step as its caller reads it: advance_spatial's tangential force [N] and step_work() [J].
    struct SpatialOutcome {
        SpatialVector tangential_force{0.0, 0.0, 0.0};
        double work = 0.0;
    };
    /// Two contacts' steps at once, each contact in one lane of the processor's vector registers, where both are held
    /// steps: no element entering or leaving normal contact and, with friction, every element in contact certainly
    /// sticking (a settled packing's contacts; docs/dem-performance.md, "Two contacts a step"). Returns false, having
    /// written nothing, for any other pair (and for M = 0 or M > 3): step each with advance_spatial then.
    /// Where it returns true the two states and `outcomes` are, to the bit, those two advance_spatial calls give;
    /// the workspace's accessors (normal_force(), step_work() and the others) keep their values. Never throws: a
    /// state that advance_spatial would refuse makes it return false.
    bool advance_spatial_pair(const SpatialStep& first, const SpatialStep& second,
                              std::span<SpatialOutcome, 2> outcomes);

    /// Normal force F_N [N] (eq. 21) of the workspace after the last advance_normal.
    double normal_force() const { return normal_force_; }
    /// Tangential force [N] (eq. 46) of the workspace after the last advance_tangential.
    PlanarVector tangential_force() const { return tangential_force_; }
    /// Where inside the last normal step (0..1) the last element to leave contact left; 0 when none left.
    double latest_exit() const { return composed_step_ ? 0.0 : foundation_.latest_exit(); }
    /// Number of elements in normal contact after the last advance_normal (0: the contact has ended).
    std::size_t contact_count() const { return contact_count_; }

    /// Work [J] the two bodies did on the contact over the last step (after begin, advance_normal and
    /// advance_tangential): the trapezoidal rule, (F_N0 + F_N1) / 2 (d1 - d0) + (F_t0 + F_t1) / 2 . (u1 - u0), with
    /// the forces at the step's start and end (second order in the step; advance_spatial's displacement is the
    /// increment in the frame turned into the new tangent plane).
    double step_work() const { return normal_work_ + tangential_work_; }
    /// Elastic energy [J] stored in a contact's state: the springs of its elements (both halves), sum_i 2 c dx
    /// (G_inf |w_i|^2 + sum_k G_k |h_k,i|^2) / 2 with c = 4 for the normal and 8/3 for the tangential elements (eq.
    /// 11, 41), h_k,i a branch's spring strain. The work done on a contact (the sum of step_work) less the energy
    /// stored is what it dissipated: in its dashpots, by friction, and with elements that left contact and relax.
    /// InvalidInput for a state shorter than state_size() or with a corrupted element count.
    double stored_energy(std::span<const double> state) const;

    /// Normal force [N] stored in a contact's state (after end()).
    double normal_force(std::span<const double> state) const { return state[normal_offset_ + 1]; }
    /// Tangential force [N] stored in a contact's state (in the composed tangential step's header).
    PlanarVector tangential_force(std::span<const double> state) const {
        const std::size_t force = tangential_header_offset_ + foundation::ComposedTangentialStep::force_offset;
        return {state[force], state[force + 1]};
    }
    /// Tangential force [N] on the second body stored in a contact's state, as a vector for the contact's unit
    /// `normal` (that of its last advance_spatial); zero before the first.
    SpatialVector tangential_force(std::span<const double> state, const SpatialVector& normal) const;
    /// Overlap [m] stored in a contact's state.
    double overlap(std::span<const double> state) const { return state[normal_offset_]; }
    /// Tangential displacement [m] stored in a contact's state.
    PlanarVector displacement(std::span<const double> state) const { return {state[0], state[1]}; }

private:
    // The state: [0, 2) the tangential displacement, [2, 5) the frame's first axis, [5] its handedness (e2 =
    // handedness normal x e1; 0 before the first advance_spatial), then the composed normal step's header (first, so
    // that a step without an entry or exit touches the state's first cache lines only), the Foundation's attached
    // state, the composed tangential step's header (just before the layer's force and count, which every step reads:
    // a held step with every element sticking touches those lines besides the first, one without friction not) and
    // the layer's state (whose own force is that of its last element-by-element step; the contact's is in the
    // tangential header).
    static constexpr std::size_t frame_offset = 2;
    static constexpr std::size_t handedness_offset = 5;
    static constexpr std::size_t header_offset = 6;
    std::span<double> header() const { return {state_ + header_offset, header_size_}; }
    std::span<double> tangential_header() const { return {state_ + tangential_header_offset_, tangential_size_}; }
    foundation::AttachedElements elements() const;
    foundation::PlanarElements tangential_elements() const;
    foundation::AttachedElements elements_at(double* state, std::size_t touched) const;
    foundation::PlanarElements tangential_elements_at(double* state, std::size_t touched) const;
    /// Whether the count at `offset` is a whole number in [0, N] (into `count` where it is): its conversion back is
    /// exact (signed conversions, one instruction each on x86-64, N being far below 2^63; no call of floor, which
    /// is not inlined for its baseline instruction set). Every step reads two.
    bool read_count(std::span<const double> state, std::size_t offset, std::size_t& count) const {
        const double value = state[offset];
        if (value >= 0.0 && value <= static_cast<double>(static_cast<std::int64_t>(elements_)) &&
            static_cast<double>(static_cast<std::int64_t>(value)) == value) [[likely]] {
            count = static_cast<std::size_t>(static_cast<std::int64_t>(value));
            return true;
        }
        return false;
    }
    template <class Branches>
    bool held_pair_with(const SpatialStep& first, const SpatialStep& second, std::span<SpatialOutcome, 2> outcomes,
                        Branches branches);
    bool tangential_composes() const;
    bool tangential_sticks(PlanarVector increment, foundation::ComposedTangentialStep::Step& step) const;
    void require_loads() const;
    void require_layer() const;
    void write_tangential() const;
    void check_tangential_header(std::span<const double> state, std::size_t active, std::size_t touched,
                                 std::size_t contacts) const;
    void prepare_foundation(bool summarise);
    std::span<const double> loads() const;
    std::span<const double> contact_flags() const;
    std::size_t count_at(std::span<const double> state, std::size_t offset) const;
    [[noreturn, gnu::noinline, gnu::cold]] void refuse_count(std::size_t offset, double count) const;
    bool tangential_at_rest(PlanarVector increment) const;
    void skip_resting_layer(PlanarVector displacement);
    void require_state_size(std::span<const double> state) const;
    void take_state(std::span<double> state);
    void take_normal_state(std::span<double> state);
    void take_frame(std::span<const double> state);
    void step_normal(double overlap);
    void end_composed_normal(double overlap);
    void end_normal(double overlap);
    void end_tangential(PlanarVector displacement, PlanarVector increment);
    bool step_held(double overlap, PlanarVector displacement);
    template <class Branches>
    bool step_held_with(double overlap, PlanarVector displacement, Branches branches);
    void step_normal_by_elements(double overlap);
    void step_tangential(PlanarVector displacement);
    bool step_composed_tangential(PlanarVector increment);
    void step_tangential_by_elements(PlanarVector increment);
    [[noreturn, gnu::noinline, gnu::cold]] void refuse_state_size(std::size_t size) const;

    foundation::Foundation foundation_;
    foundation::ComposedNormalStep composed_;
    foundation::ComposedTangentialStep tangential_;
    mutable foundation::PlanarTangentialLayer layer_;  ///< attached and prepared where a step needs it
    foundation::StepCoefficients coefficients_;
    rheology::Rheology material_;
    mutable std::vector<double> loads_;  ///< q_z,i of the last normal step (derived when needed: require_loads)
    mutable bool loads_ready_ = false;   ///< loads_ holds the last normal step's
    mutable bool layer_ready_ = false;   ///< layer_ is attached to this step's state and prepared (require_layer)
    std::size_t layer_touched_ = 0;      ///< the layer's touched elements at begin
    std::size_t elements_;  ///< N
    double friction_;
    bool tangential_idle_ = false;  ///< the layer stays at rest this step (tangential_at_rest): nothing to step;
                                    ///< skip_resting_layer decides it for step_tangential
    std::size_t branches_;
    std::size_t header_size_;
    std::size_t tangential_size_;           ///< the composed tangential step's header
    std::size_t normal_offset_;  ///< the Foundation's attached state: depth, force, touched count, the elements
    std::size_t tangential_header_offset_;  ///< the composed tangential step's header, before the layer's state
    std::size_t tangential_offset_;
    std::size_t state_size_;
    PlanarVector displacement_{0.0, 0.0};  ///< tangential displacement at the start of the step
    SpatialVector frame_{0.0, 0.0, 0.0};   ///< the frame's first axis
    double handedness_ = 0.0;
    double overlap_ = 0.0;  ///< overlap at the start of the step
    double* state_ = nullptr;  ///< the contact's state from begin() on
    bool composed_step_ = false;  ///< the last normal step was composed (no entry or exit)
    double least_stress_ = 0.0;   ///< a lower bound of its end stresses in contact (ComposedNormalStep::advance)
    PlanarVector tangential_force_{0.0, 0.0};  ///< F_t after the last advance_tangential
    double normal_force_ = 0.0;   ///< F_N after the last advance_normal
    std::size_t contact_count_ = 0;  ///< elements in contact after the last advance_normal
    std::size_t touched_ = 0;        ///< elements touched (from begin on; after the last advance_normal)
    mutable std::vector<double> memories_;  ///< one element's h_k (stored_energy)
    double start_normal_force_ = 0.0;           ///< F_N at the start of the step
    PlanarVector start_tangential_force_{0.0, 0.0};  ///< F_t at the start of the step
    double normal_work_ = 0.0;      ///< the normal force's work over the step
    double tangential_work_ = 0.0;  ///< the tangential force's work over the step
};

}  // namespace mdr::dem
