#pragma once
// The composed normal and tangential steps' bodies for a branch count M given as a type (a std::integral_constant
// for M = 1, 2, 3, else std::size_t: with_branches.hpp), inline: the classes' own methods dispatch on M and call
// them, and so does a caller that dispatches on M once for both steps (the DEM contact law's held step,
// ContactLaw::step_held). The formulas are those of the classes' comments (composed_normal_step.hpp,
// composed_tangential_step.hpp).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "mdr/foundation/composed_normal_step.hpp"
#include "mdr/foundation/composed_tangential_step.hpp"
#include "element_stiffness.hpp"

namespace mdr::foundation {

// A composition factor below this would lose the written values' digits: the elements are written again.
constexpr double smallest_factor = 1e-150;

// F P = D P + b (c^T P) into `next`: a free element's force-free update (D = diag(1, E_k), b = (1, B_k), c the free
// increment: Foundation::begin_step, the tangential layer's) composed onto the map P (row-major, order M + 1).
// `Value` a double, or two contacts' doubles in the lanes of a vector (ContactLaw::advance_spatial_pair).
template <class Value>
[[gnu::always_inline]] inline void compose_free_map(std::size_t order, const double* __restrict increment,
                                                    const double* __restrict decay, const double* __restrict gain,
                                                    const Value* __restrict map, Value* __restrict next) {
    for (std::size_t j = 0; j < order; ++j) {
        Value projection{};
        for (std::size_t l = 0; l < order; ++l) projection += increment[l] * map[l * order + j];
        next[j] = map[j] + projection;
        for (std::size_t r = 1; r < order; ++r) {
            next[r * order + j] = decay[r - 1] * map[r * order + j] + gain[r - 1] * projection;
        }
    }
}

// The normal header's entries (ComposedNormalStep's comment) and constants.
namespace composed_normal {
constexpr std::size_t profile_sum_offset = 3, outermost_offset = 4, innermost_free_offset = 5;
constexpr std::size_t scale_offset = ComposedNormalStep::factors_offset;
/// Offset of the map P for M branches: after A_k, C_k, S_k and the least h^_k.
constexpr std::size_t map_offset(std::size_t branches) { return scale_offset + 4 * branches; }
}  // namespace composed_normal

// The tangential header's entries (ComposedTangentialStep's comment) and constants.
namespace composed_tangential {
constexpr std::size_t shift_offset = 4, hat_sum_offset = 6, hat_largest_offset = 8;
constexpr std::size_t scale_offset = ComposedTangentialStep::factors_offset;
/// Offset of the map P for M branches: after A_k, C_k (x, y), the sums of h^_k (x, y) and the largest |h^_k|.
constexpr std::size_t map_offset(std::size_t branches) { return scale_offset + 6 * branches; }
}  // namespace composed_tangential

template <class Branches>
[[gnu::always_inline]] inline bool ComposedNormalStep::prepare_with(std::span<const double> header,
                                                                   const AttachedElements& elements,
                                                                   double depth_start, double depth_end, Step& step,
                                                                   Branches m) const {
    using namespace composed_normal;
    const std::size_t order = m + 1, touched = elements.touched;
    const double deepest = std::max(depth_start, depth_end);
    // The Foundation's step: an element reached for the first time (Foundation::reach), the end of the foundation.
    if ((touched < profile_.size() && profile_[touched] < deepest) || deepest > deepest_) return false;
    // Not composed: A_k = 1, C_k = 0, P = I (unit_).
    const bool composed = header[composed_offset] != 0.0;
    const double* __restrict decay = coefficients_.decay.data();
    const double* __restrict gain = coefficients_.gain.data();
    const double* __restrict moduli = moduli_.data();
    const double* __restrict scale = composed ? header.data() + scale_offset : unit_.data();
    const double* __restrict shift = scale + m;
    const double* __restrict map = composed ? header.data() + composed_normal::map_offset(m) : unit_.data() + 2 * m;
    double* __restrict weight = scratch_.data();
    double* __restrict next = weight + m;
    step.weight = weight;
    step.next = next;
    step.increment = depth_end - depth_start;
    step.rate = step.increment / coefficients_.time_step;
    double common = g_inf_ * depth_end + viscosity_ * step.rate;
    for (std::size_t k = 0; k < m; ++k) {
        common += moduli[k] * (decay[k] * shift[k] + gain[k] * step.increment);
        weight[k] = moduli[k] * decay[k] * scale[k];
    }
    step.common = common;
    const double contacts = header[contacts_offset];
    // A signed conversion (one instruction; touched <= N elements).
    step.free = static_cast<double>(static_cast<std::int64_t>(touched)) > contacts;
    bool certain = true;
    // Lower bounds of the end stresses in contact (G_k E_k A_k > 0: each is at least common - G_inf max g_i +
    // sum_k G_k E_k A_k min h^_k,i) and of the free surfaces' clearance g_i + w_i - d1 (from the extremes of w^, h^
    // by the signs of F P's first row); where one is negative, each element's (no_event).
    if (contacts > 0.0) {
        const double* __restrict floor = header.data() + scale_offset + 3 * m;
        double lower = common - g_inf_ * header[outermost_offset];
        for (std::size_t k = 0; k < m; ++k) lower += weight[k] * floor[k];
        step.least_stress = lower;
        certain = lower >= 0.0;
    }
    if (step.free) {
        compose_free_map(order, free_increment_.data(), decay, gain, map, next);
        if (certain) {
            const double* __restrict free_floor = header.data() + composed_normal::map_offset(m) + order * order;
            const double* __restrict free_ceiling = free_floor + order;
            double lower = header[innermost_free_offset] - depth_end;
            for (std::size_t j = 0; j < order; ++j) {
                lower += next[j] * (next[j] >= 0.0 ? free_floor[j] : free_ceiling[j]);
            }
            certain = lower >= 0.0;
        }
    }
    return certain || no_event(elements, common, depth_end, weight, step.free ? next : map);
}

template <class Branches>
[[gnu::always_inline]] inline double ComposedNormalStep::sum_force(std::span<const double> header, const Step& step,
                                                                   Branches m) const {
    using namespace composed_normal;
    const double* hat_sum = header.data() + scale_offset + 2 * m;
    // F_N = 8 dx sum_i sigma_i (eq. 21, both halves) over the elements in contact.
    double sum = header[contacts_offset] * step.common - g_inf_ * header[profile_sum_offset];
    for (std::size_t k = 0; k < m; ++k) sum += step.weight[k] * hat_sum[k];
    return 2.0 * normal_stiffness_factor * spacing_ * sum;
}

template <class Branches>
[[gnu::always_inline]] inline double ComposedNormalStep::take_with(std::span<double> header,
                                                                  const AttachedElements& elements, double depth_end,
                                                                  const Step& step, Branches m) const {
    using namespace composed_normal;
    const double force = sum_force(header, step, m);
    const std::size_t order = m + 1;
    const bool composed = header[composed_offset] != 0.0;
    double* scale = header.data() + scale_offset;
    double* shift = scale + m;
    double smallest = 1.0;
    for (std::size_t k = 0; k < m; ++k) {
        const double decay = coefficients_.decay[k];
        scale[k] = decay * (composed ? scale[k] : 1.0);
        shift[k] = decay * (composed ? shift[k] : 0.0) + coefficients_.gain[k] * step.increment;
        smallest = std::min(smallest, scale[k]);
    }
    if (step.free) {
        double largest = 0.0;
        for (std::size_t j = 0; j < order * order; ++j) largest = std::max(largest, std::abs(step.next[j]));
        std::copy(step.next, step.next + order * order, header.data() + composed_normal::map_offset(m));
        smallest = std::min(smallest, largest);
    } else if (!composed) {
        std::copy(unit_.data() + 2 * m, unit_.data() + 2 * m + order * order,
                  header.data() + composed_normal::map_offset(m));
    }
    header[composed_offset] = 1.0;
    header[rate_offset] = step.rate;
    // A composition factor this small would lose the written values' digits: the elements are written again.
    if (smallest < smallest_factor && write(header, elements, depth_end)) {
        summarise(header, elements, header[rate_offset]);
    }
    return force;
}

template <class Branches>
[[gnu::always_inline]] inline bool ComposedTangentialStep::prepare_with(std::span<const double> header,
                                                                       PlanarVector increment, double least_load,
                                                                       Step& step, Branches m) const {
    using namespace composed_tangential;
    const double* __restrict scale = header.data() + scale_offset;
    const double* __restrict shift = scale + m;  // C_k,x then C_k,y
    const double* __restrict largest = scale + 5 * m;
    const double* __restrict weight = weight_.data();
    double* __restrict composed_weight = scratch_.data();
    // S = G_inf U + sum_k G_k E_k C_k + k du: the relaxed stress of u = u^ + U, h_k = A_k h^_k + C_k less its
    // element's part, plus the stick branch's k du (eq. 50; the layer's relaxed_stress in its order); the bound of
    // |t_i|: |S| + G_inf max |u^| + sum_k G_k E_k A_k max |h^_k|.
    double x = g_inf_ * header[shift_offset], y = g_inf_ * header[shift_offset + 1];
    double bound = g_inf_ * header[hat_largest_offset];
    for (std::size_t k = 0; k < m; ++k) {
        x += weight[k] * shift[k];
        y += weight[k] * shift[m + k];
        composed_weight[k] = weight[k] * scale[k];
        bound += composed_weight[k] * largest[k];
    }
    step.increment = increment;
    step.common = {x + coefficients_.stiffness * increment[0], y + coefficients_.stiffness * increment[1]};
    bound += std::sqrt(step.common[0] * step.common[0] + step.common[1] * step.common[1]);
    return bound <= per_load_ * least_load;
}

template <class Branches>
[[gnu::always_inline]] inline PlanarVector ComposedTangentialStep::force_with(std::span<const double> header,
                                                                             const Step& step, Branches m) const {
    using namespace composed_tangential;
    const double* hat_sum = header.data() + scale_offset + 3 * m;  // x then y
    const double contacts = header[contacts_offset];
    double x = contacts * step.common[0] + g_inf_ * header[hat_sum_offset];
    double y = contacts * step.common[1] + g_inf_ * header[hat_sum_offset + 1];
    for (std::size_t k = 0; k < m; ++k) {
        x += scratch_[k] * hat_sum[k];
        y += scratch_[k] * hat_sum[m + k];
    }
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;  // eq. (46), both halves
    return {factor * x, factor * y};
}

template <class Branches>
[[gnu::always_inline]] inline void ComposedTangentialStep::advance_with(std::span<double> header,
                                                                       const PlanarElements& elements,
                                                                       const Step& step, Branches m) const {
    using namespace composed_tangential;
    const std::size_t order = m + 1;
    const PlanarVector total = force_with(header, step, m);
    header[force_offset] = total[0];
    header[force_offset + 1] = total[1];
    header[shift_offset] += step.increment[0];
    header[shift_offset + 1] += step.increment[1];
    double* scale = header.data() + scale_offset;
    double* shift = scale + m;
    double smallest = 1.0;
    for (std::size_t k = 0; k < m; ++k) {
        const double decay = coefficients_.decay[k], gain = coefficients_.gain[k];
        scale[k] *= decay;
        shift[k] = decay * shift[k] + gain * step.increment[0];
        shift[m + k] = decay * shift[m + k] + gain * step.increment[1];
        smallest = std::min(smallest, scale[k]);
    }
    // A signed conversion (one instruction; touched <= N elements), as the normal step's.
    if (static_cast<double>(static_cast<std::int64_t>(elements.touched)) > header[contacts_offset]) {
        // the same map for x and y
        double* map = header.data() + composed_tangential::map_offset(m);
        double* next = scratch_.data() + m;
        compose_free_map(order, free_increment_.data(), coefficients_.decay.data(), coefficients_.gain.data(), map,
                         next);
        double largest = 0.0;
        for (std::size_t j = 0; j < order * order; ++j) largest = std::max(largest, std::abs(next[j]));
        std::copy(next, next + order * order, map);
        if (largest > 0.0) smallest = std::min(smallest, largest);  // a map of zeros is exact (an elastic element)
    }
    // A composition factor this small would lose the written values' digits: the elements are written again.
    if (smallest < smallest_factor) {
        write(header, elements);
        summarise(header, elements, total);
    }
}

}  // namespace mdr::foundation
