#pragma once
/// \file
/// The normal step of an attached foundation state in O(M) while no element enters or leaves contact (issue 29; a
/// DEM contact holds its overlap for most steps): the elements' updates are composed instead of applied.

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::dem {
class ContactLaw;
}

namespace mdr::foundation {

/// The elements of a state in the layout of Foundation::attach: `touched` elements with displacements `w`, contact
/// flags `flags` (0 or 1) and memories `h` (branch-major, h_{k,i} = h[k * stride + i]).
struct AttachedElements {
    double* w;
    double* flags;
    double* h;
    std::size_t stride;
    std::size_t touched;
};

/// Over a step the depth goes linearly from d0 to d1, so every element that stays in contact has the same increment
/// dw = d1 - d0 (eq. 13) and each of its branch memories the same affine map h_k <- E_k h_k + B_k dw (E_k, B_k of
/// StepCoefficients; numerics notes eq. 16, 18); a force-free element's update (Foundation::begin_step) is one
/// linear map F of (w, h_1..h_M) for all of them. A contact's header keeps the compositions since its elements were
/// last written, h_k = A_k h^_k + C_k in contact and (w, h) = P (w^, h^) free (w^, h^ the written values), and a
/// summary of the written values (the sums and extremes below); then F_N = 8 dx sum_i sigma_i (eq. 21) needs O(M)
/// and the step O(M^2). The exit rule (eq. 20) and the entry rule (eq. 14) are checked as the Foundation checks
/// them: first by lower bounds from the summary, where one is negative by a read-only pass over the elements. A
/// step with an entry or exit is the Foundation's (the caller writes the elements, takes it, and summarises).
///
/// The header (header_size(M) doubles): [0] 1 while composed (the elements are older than the header), else 0;
/// [1] the dashpots' rate at the end of the last step; [2] the elements in contact; [3] sum of g_i over them; [4]
/// the largest of those g_i; [5] the smallest g_i of a touched free element; then A_k, C_k, S_k (the sum of h^_k
/// over the elements in contact), their least h^_k (M each), P (row-major, order M + 1), the least and the largest
/// of (w^, h^_k) over the touched free elements (M + 1 each). Zeros are the header of an untouched contact; an
/// extreme over no element is stored as 0 (not read).
class ComposedNormalStep {
public:
    /// `material`, `profile` g(x_i) at the element centres [m], `spacing` dx [m], `deepest` the deepest depth the
    /// foundation takes (deepest_depth): the Foundation's own.
    ComposedNormalStep(const rheology::Rheology& material, std::span<const double> profile, double spacing,
                       double deepest);

    /// Doubles of the header for `branches` relaxation branches M: M^2 + 8 M + 9.
    static std::size_t header_size(std::size_t branches);
    /// Offset in the header of the flag "composed".
    static constexpr std::size_t composed_offset = 0;
    /// Offset in the header of the dashpots' rate at the end of the last step.
    static constexpr std::size_t rate_offset = 1;
    /// Offset in the header of the number of elements in contact.
    static constexpr std::size_t contacts_offset = 2;
    /// Offset in the header of the composition factors A_k (M).
    static constexpr std::size_t factors_offset = 6;

    /// The deepest depth [m] the foundation takes (a deeper step is the Foundation's, which refuses it).
    double deepest() const { return deepest_; }
    /// Sets the coefficients of the following steps (the free elements' map F).
    void set_step(const StepCoefficients& coefficients);
    /// Steps from `depth_start` to `depth_end` [m] in the composed form and returns true, writing the header only
    /// (but see write), when no element enters or leaves contact, none is reached for the first time and the depth
    /// stays within the foundation; else returns false and changes nothing. `force` is then F_N at the end (eq. 21)
    /// and `least_stress` a lower bound [Pa] of the end stresses sigma_i of the elements in contact (from the
    /// header's summary; +infinity when none is in contact; it may be negative though none is).
    bool advance(std::span<double> header, const AttachedElements& elements, double depth_start, double depth_end,
                 double& force, double& least_stress) const;
    /// F_N [N] if the step went from `depth_start` to `depth_end`, when advance would take it; false otherwise.
    bool trial_force(std::span<const double> header, const AttachedElements& elements, double depth_start,
                     double depth_end, double& force) const;
    /// Writes the elements' current w and h at depth `depth` (the composed maps applied) and returns true when the
    /// header holds a composition, which it then no longer does; its summary describes the elements again only
    /// after summarise. advance does both itself where a composition factor falls below 1e-150 (the written
    /// values' digits would be lost).
    bool write(std::span<double> header, const AttachedElements& elements, double depth) const;
    /// Summarises the written elements into the header (after the Foundation's step), `rate` the dashpots' rate
    /// at its end.
    void summarise(std::span<double> header, const AttachedElements& elements, double rate) const;
    /// The index of the first entry of `header`'s summary of the written elements (as summarise makes it: the
    /// elements in contact, the sum and the largest of their g_i, the least g_i of a free one, the sums and least
    /// values of the memories in contact, the free ones' extremes) that is not the summary of `elements`, or
    /// header.size() when none: the summary is derived, and a state read back (a restart) must hold its own.
    std::size_t summary_mismatch(std::span<const double> header, const AttachedElements& elements) const;
    /// Element i's current displacement w [m] and memories h (M doubles) at depth `depth`.
    void element(std::span<const double> header, const double* w, const double* flags, const double* h,
                 std::size_t stride, std::size_t i, double depth, double& current_w, double* current_h) const;
    /// Line loads q_z,i = 4 sigma_i [N/m] (eq. 22) of the touched elements at depth `depth` into `out`, after a step
    /// advance took to `depth` (the elements in contact then have w_i = d - g_i; their written w_i are not read).
    void line_loads(std::span<const double> header, const AttachedElements& elements, double depth,
                    std::span<double> out) const;

    /// What a step in the composed form derives before it is taken (prepare_with).
    struct Step {
        double common = 0.0;     ///< the end stress common to the elements in contact, eq. (16): G_inf d1 + ...
        double increment = 0.0;  ///< d1 - d0
        double rate = 0.0;       ///< the dashpots' (secant) rate
        bool free = false;       ///< some touched element is out of contact
        double least_stress = std::numeric_limits<double>::infinity();  ///< a lower bound of the end stresses in
                                                                        ///< contact (+infinity when none is)
        double* weight = nullptr;   ///< G_k E_k A_k (M; in this object until the next prepare_with)
        double* next = nullptr;     ///< F P, row-major (order M + 1)
    };

private:
    friend class dem::ContactLaw;  // its held step calls the bodies below for one dispatch on M
    // The held step's bodies for a branch count `branches` M (a std::integral_constant for M = 1, 2, 3: with_branches),
    // defined inline in src/foundation/composed_held_steps.hpp (so callable only from the library's own sources), for
    // a caller that dispatches on M once for more than one step (the DEM contact law's held step): advance is
    // prepare_with and, where it returns true, take_with.
    /// Derives the step from `depth_start` to `depth_end` [m] into `step` and returns whether advance takes it in the
    /// composed form (no entry or exit, the depth within the foundation). Writes no header or element.
    template <class Branches>
    bool prepare_with(std::span<const double> header, const AttachedElements& elements, double depth_start,
                      double depth_end, Step& step, Branches branches) const;
    /// Takes the step prepare_with derived (and found composable) to `depth_end` in the header and returns F_N [N]
    /// at its end (eq. 21); where a composition factor falls below 1e-150 it writes the elements and summarises them
    /// again (as advance).
    template <class Branches>
    double take_with(std::span<double> header, const AttachedElements& elements, double depth_end, const Step& step,
                     Branches branches) const;

    template <class Branches>
    double sum_force(std::span<const double> header, const Step& step, Branches branches) const;
    // The formulas of a composed step, for a double or two contacts' lanes (`Value`, ContactLaw::advance_spatial_pair):
    // the end stress common to the elements in contact (eq. 16) from the factors A_k (`scale`) and shifts C_k, with
    // the weights G_k E_k A_k into `weight`; lower bounds of the end stresses in contact and of the free surfaces'
    // clearance; F_N (eq. 21). Defined in composed_held_steps.hpp.
    template <class Value, class Branches>
    Value common_stress(const Value* scale, const Value* shift, Value depth_end, Value rate, Value increment,
                        Value* weight, Branches branches) const;
    template <class Value, class Branches>
    Value least_stress(Value common, Value outermost, const Value* weight, const Value* floor, Branches branches) const;
    template <class Value>
    static Value free_clearance(Value innermost, Value depth_end, const Value* next, const Value* floor,
                                const Value* ceiling, std::size_t order);
    template <class Value, class Branches>
    Value force_of(Value contacts, Value common, Value profile_sum, const Value* weight, const Value* hat_sum,
                   Branches branches) const;
    bool no_event(const AttachedElements& elements, double common, double depth, const double* weight,
                  const double* row) const;
    std::size_t map_offset() const;

    std::size_t branches_;
    double g_inf_;
    double viscosity_;
    double spacing_;
    double deepest_;
    std::vector<double> moduli_;  ///< G_k
    std::vector<double> profile_;  ///< g(x_i)
    StepCoefficients coefficients_;
    std::vector<double> free_increment_;  ///< c: a free element's dw = c . (w, h) (Foundation::begin_step)
    std::vector<double> unit_;  ///< the maps when not composed: A_k = 1, C_k = 0 (M each), P = I
    mutable std::vector<double> scratch_;  ///< the step's weights G_k E_k A_k and map F P; written memories
};

}  // namespace mdr::foundation
