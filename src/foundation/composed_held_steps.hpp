#pragma once
// The composed normal and tangential steps' bodies for a branch count M given as a type (a std::integral_constant
// for M = 1, 2, 3, else std::size_t: with_branches.hpp), inline: the classes' own methods dispatch on M and call
// them, and so does a caller that dispatches on M once for both steps (the DEM contact law's held step,
// ContactLaw::step_held). The formulas are those of the classes' comments (composed_normal_step.hpp,
// composed_tangential_step.hpp), written once for a value that is a double or two contacts' lanes (lanes.hpp:
// common_stress, least_stress, free_clearance, force_of, relaxed_stress, compose_free_map), so that the held step of
// two contacts at once (ContactLaw::advance_spatial_pair) uses them too.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "lanes.hpp"
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

template <class Value, class Branches>
[[gnu::always_inline]] inline Value ComposedNormalStep::common_stress(const Value* __restrict scale,
                                                                     const Value* __restrict shift, Value depth_end,
                                                                     Value rate, Value increment,
                                                                     Value* __restrict weight, Branches m) const {
    const double* __restrict decay = coefficients_.decay.data();
    const double* __restrict gain = coefficients_.gain.data();
    const double* __restrict moduli = moduli_.data();
    Value common = g_inf_ * depth_end + viscosity_ * rate;
    for (std::size_t k = 0; k < m; ++k) {
        common += moduli[k] * (decay[k] * shift[k] + gain[k] * increment);
        weight[k] = moduli[k] * decay[k] * scale[k];
    }
    return common;
}

// G_k E_k A_k > 0: each end stress in contact is at least common - G_inf max g_i + sum_k G_k E_k A_k min h^_k,i.
template <class Value, class Branches>
[[gnu::always_inline]] inline Value ComposedNormalStep::least_stress(Value common, Value outermost,
                                                                    const Value* __restrict weight,
                                                                    const Value* __restrict floor, Branches m) const {
    Value lower = common - g_inf_ * outermost;
    for (std::size_t k = 0; k < m; ++k) lower += weight[k] * floor[k];
    return lower;
}

// The free surfaces' clearance g_i + w_i - d1 is at least g_min - d1 + the extremes of w^, h^ by the signs of F P's
// first row (`next`).
template <class Value>
[[gnu::always_inline]] inline Value ComposedNormalStep::free_clearance(Value innermost, Value depth_end,
                                                                      const Value* __restrict next,
                                                                      const Value* __restrict floor,
                                                                      const Value* __restrict ceiling,
                                                                      std::size_t order) {
    Value lower = innermost - depth_end;
    for (std::size_t j = 0; j < order; ++j) lower += next[j] * by_sign(next[j], floor[j], ceiling[j]);
    return lower;
}

// F_N = 8 dx sum_i sigma_i (eq. 21, both halves) over the elements in contact.
template <class Value, class Branches>
[[gnu::always_inline]] inline Value ComposedNormalStep::force_of(Value contacts, Value common, Value profile_sum,
                                                                const Value* __restrict weight,
                                                                const Value* __restrict hat_sum, Branches m) const {
    Value sum = contacts * common - g_inf_ * profile_sum;
    for (std::size_t k = 0; k < m; ++k) sum += weight[k] * hat_sum[k];
    return 2.0 * normal_stiffness_factor * spacing_ * sum;
}

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
    const double* __restrict scale = composed ? header.data() + scale_offset : unit_.data();
    const double* __restrict shift = scale + m;
    const double* __restrict map = composed ? header.data() + composed_normal::map_offset(m) : unit_.data() + 2 * m;
    double* __restrict weight = scratch_.data();
    double* __restrict next = weight + m;
    step.weight = weight;
    step.next = next;
    step.increment = depth_end - depth_start;
    step.rate = step.increment / coefficients_.time_step;
    const double common = common_stress(scale, shift, depth_end, step.rate, step.increment, weight, m);
    step.common = common;
    const double contacts = header[contacts_offset];
    // A signed conversion (one instruction; touched <= N elements).
    step.free = static_cast<double>(static_cast<std::int64_t>(touched)) > contacts;
    bool certain = true;
    // Lower bounds of the end stresses in contact (G_k E_k A_k > 0: each is at least common - G_inf max g_i +
    // sum_k G_k E_k A_k min h^_k,i) and of the free surfaces' clearance g_i + w_i - d1 (from the extremes of w^, h^
    // by the signs of F P's first row); where one is negative, each element's (no_event).
    if (contacts > 0.0) {
        const double* floor = header.data() + scale_offset + 3 * m;  // the least h^_k
        step.least_stress = least_stress(common, header[outermost_offset], weight, floor, m);
        certain = step.least_stress >= 0.0;
    }
    if (step.free) {
        compose_free_map(order, free_increment_.data(), coefficients_.decay.data(), coefficients_.gain.data(), map,
                         next);
        if (certain) {
            const double* free_floor = header.data() + composed_normal::map_offset(m) + order * order;
            certain = free_clearance(header[innermost_free_offset], depth_end, next, free_floor, free_floor + order,
                                     order) >= 0.0;
        }
    }
    return certain || no_event(elements, common, depth_end, weight, step.free ? next : map);
}

template <class Branches>
[[gnu::always_inline]] inline double ComposedNormalStep::sum_force(std::span<const double> header, const Step& step,
                                                                   Branches m) const {
    using namespace composed_normal;
    return force_of(header[contacts_offset], step.common, header[profile_sum_offset], step.weight,
                    header.data() + scale_offset + 2 * m, m);
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

// S = G_inf U + sum_k G_k E_k C_k + k du: the relaxed stress of u = u^ + U, h_k = A_k h^_k + C_k less its element's
// part, plus the stick branch's k du (eq. 50; the layer's relaxed_stress in its order); the bound of |t_i|: |S| +
// G_inf max |u^| + sum_k G_k E_k A_k max |h^_k|.
template <class Value, class Branches>
[[gnu::always_inline]] inline void ComposedTangentialStep::relaxed_stress(
    Value shift_x, Value shift_y, Value hat_largest, const Value* __restrict scale, const Value* __restrict shift_x_k,
    const Value* __restrict shift_y_k, const Value* __restrict largest, Value du, Value dv, Value& stress_x,
    Value& stress_y, Value& bound, Value* __restrict composed_weight, Branches m) const {
    const double* __restrict weight = weight_.data();
    Value x = g_inf_ * shift_x, y = g_inf_ * shift_y;
    bound = g_inf_ * hat_largest;
    for (std::size_t k = 0; k < m; ++k) {
        x += weight[k] * shift_x_k[k];
        y += weight[k] * shift_y_k[k];
        composed_weight[k] = weight[k] * scale[k];
        bound += composed_weight[k] * largest[k];
    }
    stress_x = x + coefficients_.stiffness * du;
    stress_y = y + coefficients_.stiffness * dv;
    bound += square_root(stress_x * stress_x + stress_y * stress_y);
}

// F_t (eq. 46, both halves) over the elements in contact, every one sticking.
template <class Value, class Branches>
[[gnu::always_inline]] inline void ComposedTangentialStep::force_of(Value contacts, Value stress_x, Value stress_y,
                                                                   Value hat_sum_x, Value hat_sum_y,
                                                                   const Value* __restrict composed_weight,
                                                                   const Value* __restrict hat_x,
                                                                   const Value* __restrict hat_y, Value& force_x,
                                                                   Value& force_y, Branches m) const {
    Value x = contacts * stress_x + g_inf_ * hat_sum_x;
    Value y = contacts * stress_y + g_inf_ * hat_sum_y;
    for (std::size_t k = 0; k < m; ++k) {
        x += composed_weight[k] * hat_x[k];
        y += composed_weight[k] * hat_y[k];
    }
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;
    force_x = factor * x;
    force_y = factor * y;
}

template <class Branches>
[[gnu::always_inline]] inline bool ComposedTangentialStep::prepare_with(std::span<const double> header,
                                                                       PlanarVector increment, double least_load,
                                                                       Step& step, Branches m) const {
    using namespace composed_tangential;
    const double* scale = header.data() + scale_offset;  // A_k, then C_k,x, C_k,y, ..., the largest |h^_k|
    double bound = 0.0;
    relaxed_stress(header[shift_offset], header[shift_offset + 1], header[hat_largest_offset], scale, scale + m,
                   scale + 2 * m, scale + 5 * m, increment[0], increment[1], step.common[0], step.common[1], bound,
                   scratch_.data(), m);
    step.increment = increment;
    return bound <= per_load_ * least_load;
}

template <class Branches>
[[gnu::always_inline]] inline PlanarVector ComposedTangentialStep::force_with(std::span<const double> header,
                                                                             const Step& step, Branches m) const {
    using namespace composed_tangential;
    const double* hat_sum = header.data() + scale_offset + 3 * m;  // x then y
    PlanarVector force{0.0, 0.0};
    force_of(header[contacts_offset], step.common[0], step.common[1], header[hat_sum_offset],
             header[hat_sum_offset + 1], scratch_.data(), hat_sum, hat_sum + m, force[0], force[1], m);
    return force;
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
