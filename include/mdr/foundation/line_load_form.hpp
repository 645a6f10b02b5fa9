#pragma once
/// \file
/// The normal line loads q_z,i = 4 sigma_i (eq. 16, 22) of a normal step's elements in a form an element pass reads
/// in place: the values a Foundation's step wrote, or the composed normal step's formula (ComposedNormalStep), so
/// that the tangential layer's pass forms each element's load itself instead of reading a pass of its own.

#include <cstddef>

namespace mdr::foundation {

/// Where element i's line load q_z,i [N/m] comes from: `written[i]` when `written` is not null, else the formula
/// of composed_line_load with the fields below (ComposedNormalStep::line_load_form). An element out of normal
/// contact carries no load, whatever the form gives for it.
struct LineLoadForm {
    const double* written = nullptr;  ///< q_z,i at [i] (Foundation::line_loads), or null
    double depth = 0.0;     ///< d [m] at the end of the step
    double g_inf = 0.0;     ///< G_inf [Pa]
    double dashpot = 0.0;   ///< eta times the dashpots' rate [Pa]
    const double* profile = nullptr;  ///< g_i [m]
    const double* h = nullptr;        ///< the written h^_k,i at [k * stride + i]
    std::size_t stride = 0;
    const double* moduli = nullptr;  ///< G_k [Pa]
    const double* scale = nullptr;   ///< A_k (1 when not composed)
    const double* shift = nullptr;   ///< C_k (0 when not composed)
};

/// q_z,i = 4 (G_inf (d - g_i) + eta rate + sum_k G_k (A_k h^_k,i + C_k)) (eq. 11, 16, 22) of element i in normal
/// contact at the end of a step the composed normal step took: its displacement is w_i = d - g_i (eq. 13), whether
/// the header still composes the element's updates or ComposedNormalStep::write has just written it at d (then
/// A_k = 1, C_k = 0); `branches` M (a constant where it can be). The fields of LineLoadForm as restrict pointers, so
/// that the passes that call it vectorise.
template <class Branches>
inline double composed_line_load(std::size_t i, Branches branches, double depth, double g_inf, double dashpot,
                                 const double* __restrict profile, const double* __restrict h, std::size_t stride,
                                 const double* __restrict moduli, const double* __restrict scale,
                                 const double* __restrict shift) {
    constexpr double normal_stiffness_factor = 4.0;  // k_z = 4 G dx, eq. (11)
    double stress = g_inf * (depth - profile[i]) + dashpot;
    for (std::size_t k = 0; k < branches; ++k) stress += moduli[k] * (scale[k] * h[k * stride + i] + shift[k]);
    return normal_stiffness_factor * stress;
}

}  // namespace mdr::foundation
