#pragma once
/// \file
/// The tangential step of an attached planar tangential layer in O(M) while every element in normal contact sticks
/// and none enters or leaves contact (issue 29; a held DEM contact with friction): the elements' updates are composed
/// in a header instead of applied, as ComposedNormalStep composes the normal step.

#include <cstddef>
#include <span>
#include <vector>

#include "mdr/foundation/planar_tangential_layer.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::dem {
class ContactLaw;
}

namespace mdr::foundation {

/// The tangential elements of a state in the layout of PlanarTangentialLayer::attach, with the normal contact flags
/// beside them: `touched` elements, u_x,i = u[i], u_y,i = u[stride + i], memories branch-major and x before y
/// (h_k,x,i = h[2 k stride + i], h_k,y,i = h[(2 k + 1) stride + i]), `flags` 0 or 1 (the Foundation's).
struct PlanarElements {
    double* u;
    double* h;
    const double* flags;
    std::size_t stride;
    std::size_t touched;
};

/// While the normal step is composed (ComposedNormalStep: no element enters or leaves normal contact, so every
/// element in contact takes the whole increment du, share 1) and every element in contact sticks, element i in
/// contact steps u_i <- u_i + du, h_k,i <- E_k h_k,i + B_k du (eq. 50, the stick branch; step_coefficients.hpp), so
/// u_i = u^_i + U and h_k,i = A_k h^_k,i + C_k with u^, h^ the written values, U, A_k = prod E_k and C_k <- E_k C_k +
/// B_k du kept in a header. A free touched element (out of normal contact) is force-free: its (u, h_1..h_M), per
/// component, goes through one linear map F (du = -relaxed / stiffness), composed as P <- F P. The element's stress
/// at the step's end is t_i = S + G_inf u^_i + sum_k G_k E_k A_k h^_k,i with S = G_inf U + sum_k G_k E_k C_k + k du
/// (k = G_inf + eta / dt + sum_k G_k B_k: the dashpot's eta du / dt included), and the force F_t = 2 (8/3) dx sum_i
/// t_i (eq. 46) over the elements in contact needs the sums of u^ and h^_k only: O(M). Every element sticks when
/// |t_i| <= mu q_z,i / (8/3) (eq. 50, a circle): first by the bound |S| + G_inf max|u^| + sum_k G_k E_k A_k max|h^_k|
/// against the least line load, else by a read-only pass over the elements; where one would slip, the caller writes
/// the elements (write) and takes the layer's step.
///
/// The header (header_size(M) doubles): [0] 1 while it composes the steps since its elements were summarised, else
/// 0; [1, 3) the tangential force after the last step (either form); [3] the elements in contact; [4, 6) U; [6, 8)
/// the sums of u^ over the elements in contact; [8] the largest |u^_i| there; then A_k (M), C_k (x then y, M each),
/// the sums of h^_k (x then y, M each), the largest |h^_k,i| (M), P (row-major, order M + 1). Zeros are the header of
/// an untouched contact.
class ComposedTangentialStep {
public:
    /// `material` and `friction` mu of the layer, `spacing` dx [m].
    ComposedTangentialStep(const rheology::Rheology& material, double friction, double spacing);

    /// Doubles of the header for `branches` relaxation branches M: M^2 + 8 M + 10.
    static std::size_t header_size(std::size_t branches);
    /// Offset in the header of the flag "composed".
    static constexpr std::size_t composed_offset = 0;
    /// Offset in the header of the tangential force (2).
    static constexpr std::size_t force_offset = 1;
    /// Offset in the header of the number of elements in contact.
    static constexpr std::size_t contacts_offset = 3;
    /// Offset in the header of the composition factors A_k (M).
    static constexpr std::size_t factors_offset = 9;

    /// What a composed step derives before it is taken (prepare): the stress common to the elements in contact.
    struct Step {
        PlanarVector increment{0.0, 0.0};  ///< du
        PlanarVector common{0.0, 0.0};     ///< S
    };

    /// Sets the coefficients of the following steps (the material's for the time step).
    void set_step(const StepCoefficients& coefficients);
    /// Derives a step with increment `increment` [m] from a header that composes (flag 1): S, and the weights
    /// G_k E_k A_k that sticks and force read (kept in this object until the next prepare). Returns whether every
    /// element in contact certainly sticks (the bound above) when every normal line load in contact is at least
    /// `least_load` [N/m]; where not, sticks decides.
    bool prepare(std::span<const double> header, PlanarVector increment, double least_load, Step& step) const;
    /// Whether every element in contact sticks, each against its line load `loads[i]` q_z,i [N/m] (read only).
    bool sticks(const PlanarElements& elements, const Step& step, const double* loads) const;
    /// F_t [N] (eq. 46, both halves) at the end of the prepared step, every element in contact sticking.
    PlanarVector force(std::span<const double> header, const Step& step) const;
    /// Takes the prepared step in the header (every element in contact sticks) and stores its force there. Where a
    /// composition factor falls below 1e-150 the elements are written and summarised again.
    void advance(std::span<double> header, const PlanarElements& elements, const Step& step) const;
    /// prepare and, where it returns true (every element in contact certainly sticks), advance: one call for a held
    /// step. Returns prepare's answer; where false, `step` is prepared for sticks and advance.
    bool advance_if_certain(std::span<double> header, const PlanarElements& elements, PlanarVector increment,
                            double least_load, Step& step) const;
    /// Writes the elements' current u and h (the composed maps applied) and returns true when the header composes,
    /// which it then no longer does (the flags must be those of the composed steps: before a normal step changes
    /// them).
    bool write(std::span<double> header, const PlanarElements& elements) const;
    /// Summarises the written elements into the header, which then composes from the next step on (after a layer's
    /// step in which every element in contact stuck), with `force` the force after that step.
    void summarise(std::span<double> header, const PlanarElements& elements, PlanarVector force) const;
    /// Stores `force`, the force after a layer's step, in a header that does not compose (some element slipped).
    static void keep(std::span<double> header, PlanarVector force) {
        header[composed_offset] = 0.0;
        header[force_offset] = force[0];
        header[force_offset + 1] = force[1];
    }
    /// The index of the first entry of `header`'s summary (the elements in contact, the sums and largest values of
    /// u^ and h^_k there) that is not the summary of `elements`, or header.size() when none (a restart's check).
    std::size_t summary_mismatch(std::span<const double> header, const PlanarElements& elements) const;
    /// Element i's current u_x, u_y, then h_k,x, h_k,y per branch (2 + 2 M doubles into `current`), the header's
    /// maps applied; `u`, `h`, `flags`, `stride` as in PlanarElements.
    void element(std::span<const double> header, const double* u, const double* h, const double* flags,
                 std::size_t stride, std::size_t i, double* current) const;

private:
    friend class dem::ContactLaw;  // its held step calls the bodies below for one dispatch on M
    // The steps' bodies for a branch count `branches` M (a std::integral_constant for M = 1, 2, 3: with_branches),
    // defined inline in src/foundation/composed_held_steps.hpp (so callable only from the library's own sources), for
    // a caller that dispatches on M once for more than one step (the DEM contact law's held step): prepare, force and
    // advance dispatch on M and call them.
    /// prepare for a given M.
    template <class Branches>
    bool prepare_with(std::span<const double> header, PlanarVector increment, double least_load, Step& step,
                      Branches branches) const;
    /// force for a given M.
    template <class Branches>
    PlanarVector force_with(std::span<const double> header, const Step& step, Branches branches) const;
    /// advance for a given M.
    template <class Branches>
    void advance_with(std::span<double> header, const PlanarElements& elements, const Step& step,
                      Branches branches) const;

    // The formulas of a composed step, for a double or two contacts' lanes (`Value`, ContactLaw::advance_spatial_pair):
    // the relaxed stress S (x, y; eq. 50) for the increment (du, dv) from the shift U, the factors A_k (`scale`) and
    // shifts C_k, with the weights G_k E_k A_k into `composed_weight`, and the bound of the element stresses |t_i|;
    // F_t (eq. 46). Defined in composed_held_steps.hpp.
    template <class Value, class Branches>
    void relaxed_stress(Value shift_x, Value shift_y, Value hat_largest, const Value* scale, const Value* shift_x_k,
                        const Value* shift_y_k, const Value* largest, Value du, Value dv, Value& stress_x,
                        Value& stress_y, Value& bound, Value* composed_weight, Branches branches) const;
    template <class Value, class Branches>
    void force_of(Value contacts, Value stress_x, Value stress_y, Value hat_sum_x, Value hat_sum_y,
                  const Value* composed_weight, const Value* hat_x, const Value* hat_y, Value& force_x, Value& force_y,
                  Branches branches) const;

    std::size_t map_offset() const;

    std::size_t branches_;
    double g_inf_;
    double per_load_;  ///< mu / (8/3): the friction limit [Pa] per unit line load [N/m]
    double spacing_;
    std::vector<double> moduli_;  ///< G_k
    StepCoefficients coefficients_;
    std::vector<double> weight_;          ///< G_k E_k of the step
    std::vector<double> free_increment_;  ///< c: a free element's du = c . (u, h) (the layer's force-free update)
    mutable std::vector<double> scratch_;  ///< the step's weights G_k E_k A_k and map F P; written values
};

}  // namespace mdr::foundation
