#include "mdr/foundation/planar_tangential_layer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "with_branches.hpp"

namespace mdr::foundation {
namespace {

constexpr double tangential_stiffness_factor = 8.0 / 3.0;  // k_x = (8/3) G dx, eq. (11), (41)

// Element i's stress at the end of a step with no increment, G_inf u_i + sum_k G_k E_k h_k,i (`weight` G_k E_k;
// memory branch-major, x then y: h_k,x at memory[2 k n + i], h_k,y at memory[(2 k + 1) n + i]); the order of
// relaxed_sums (branch_sums.hpp), so that every value is the same.
template <class Branches>
inline PlanarVector relaxed_stress(std::size_t i, Branches branches, std::size_t n, double g_inf,
                                   const double* __restrict weight, const double* __restrict u_x,
                                   const double* __restrict u_y, const double* __restrict memory) {
    double x = g_inf * u_x[i], y = g_inf * u_y[i];
    for (std::size_t k = 0; k < branches; ++k) {
        x += weight[k] * memory[2 * k * n + i];
        y += weight[k] * memory[(2 * k + 1) * n + i];
    }
    return {x, y};
}

// (sum_i t_x,i, sum_i t_y,i) over i < count, each in four interleaved partial sums, s_j over i = j mod 4 in element
// order, added as (s_0 + s_1) + (s_2 + s_3): an order fixed whatever the instruction set (so that every clone gives
// the same bits) that takes one vector addition per four elements where a sum in element order is a chain of scalar
// additions. The blocks of four are read as the element pass's vector stores wrote them and the last count mod 4
// one by one (a load spanning several stores would wait for them: no padding with zeros).
inline __attribute__((always_inline)) PlanarVector interleaved_sums(const double* __restrict t_x,
                                                                    const double* __restrict t_y, std::size_t count) {
    using Lanes = double __attribute__((vector_size(4 * sizeof(double))));  // s_0..s_3 (two registers without AVX)
    Lanes x = {0.0, 0.0, 0.0, 0.0}, y = {0.0, 0.0, 0.0, 0.0};
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) {
        Lanes block_x, block_y;
        std::memcpy(&block_x, t_x + i, sizeof block_x);
        std::memcpy(&block_y, t_y + i, sizeof block_y);
        x += block_x;
        y += block_y;
    }
    double lane_x[4] = {x[0], x[1], x[2], x[3]}, lane_y[4] = {y[0], y[1], y[2], y[3]};
    for (std::size_t j = 0; i + j < count; ++j) {
        lane_x[j] += t_x[i + j];
        lane_y[j] += t_y[i + j];
    }
    return {(lane_x[0] + lane_x[1]) + (lane_x[2] + lane_x[3]), (lane_y[0] + lane_y[1]) + (lane_y[2] + lane_y[3])};
}

// Eq. (50) with vectors over `count` elements, one branch-free pass (selects, so that it vectorises with
// -fno-trapping-math and -fno-math-errno): an element in contact (mask 1) sticks while its trial, its relaxed stress
// plus k du, stays inside the friction circle of radius per_load q_i and slips along its trial otherwise; out of
// contact (mask 0) it is force-free. Writes the new stress t, adds the element's increment du to u and updates its
// memories, h <- E h + B du (step_coefficients.hpp; `decay` E_k, `gain` B_k). The relaxed stresses are formed here,
// not in a pass of their own, and so are the line loads q_i where they are the composed normal step's (`Composed`:
// composed_line_load of `loads`, ComposedNormalStep::line_load_form; else loads.written). Returns sum_i t_i
// (interleaved_sums). The arrays as restrict parameters, used by the lambda directly: copied into a structure, or
// inside the member function, GCC 12 leaves this loop scalar.
template <bool Composed>
inline __attribute__((always_inline)) void stick_or_slip(
    std::size_t count, std::size_t branches, std::size_t n, PlanarVector increment, double g_inf, double stiffness,
    double per_load, const double* __restrict weight, const double* __restrict decay, const double* __restrict gain,
    const double* __restrict mask, const double* __restrict share, const LineLoadForm& loads,
    const double* __restrict written, const double* __restrict profile, const double* __restrict normal_h, const double* __restrict moduli, const double* __restrict scale,
    const double* __restrict shift, double* __restrict u_x, double* __restrict u_y, double* __restrict memory,
    double* __restrict t_x, double* __restrict t_y) {
    with_branches(branches, [&](auto m) __attribute__((always_inline)) {
        const double compliance = 1.0 / stiffness;
        const double along_x = increment[0], along_y = increment[1];
        const double depth = loads.depth, normal_g_inf = loads.g_inf;
        const double dashpot = loads.dashpot;
        const std::size_t normal_stride = loads.stride;
        for (std::size_t i = 0; i < count; ++i) {
            const PlanarVector relaxed = relaxed_stress(i, m, n, g_inf, weight, u_x, u_y, memory);
            double q;
            if constexpr (Composed) {
                q = composed_line_load(i, m, depth, normal_g_inf, dashpot, profile, normal_h, normal_stride, moduli,
                                       scale, shift);
            } else {
                q = written[i];
            }
            const double in = mask[i];
            const double bound = in * per_load * std::max(q, 0.0);
            const double moved_x = along_x * share[i], moved_y = along_y * share[i];
            const double trial_x = relaxed[0] + stiffness * moved_x;
            const double trial_y = relaxed[1] + stiffness * moved_y;
            const double magnitude = std::sqrt(trial_x * trial_x + trial_y * trial_y);
            const bool sticks = in != 0.0 && magnitude <= bound;
            const double factor = sticks ? 1.0 : (in != 0.0 ? bound / magnitude : 0.0);
            const double stress_x = trial_x * factor, stress_y = trial_y * factor;
            const double du_x = sticks ? moved_x : (stress_x - relaxed[0]) * compliance;
            const double du_y = sticks ? moved_y : (stress_y - relaxed[1]) * compliance;
            u_x[i] += du_x;
            u_y[i] += du_y;
            for (std::size_t k = 0; k < m; ++k) {
                double& h_x = memory[2 * k * n + i];
                double& h_y = memory[(2 * k + 1) * n + i];
                h_x = decay[k] * h_x + gain[k] * du_x;
                h_y = decay[k] * h_y + gain[k] * du_y;
            }
            t_x[i] = stress_x;
            t_y[i] = stress_y;
        }
    });
}

// The pass and its sum for each form of the line loads, each compiled for AVX2 and for x86-64's baseline (a plugin
// cannot assume the host's instruction set), the better chosen when the library is loaded; the parameters of
// stick_or_slip, restrict here as well (else the composed form's loop stays scalar).
#define MDR_STICK_OR_SLIP_PARAMETERS                                                                                   \
    std::size_t count, std::size_t branches, std::size_t n, PlanarVector increment, double g_inf, double stiffness,   \
        double per_load, const double* __restrict weight, const double* __restrict decay,                              \
        const double* __restrict gain, const double* __restrict mask, const double* __restrict share,                  \
        const LineLoadForm& loads, const double* __restrict written, const double* __restrict profile,                \
        const double* __restrict normal_h, const double* __restrict moduli,                                            \
        const double* __restrict scale, const double* __restrict shift, double* __restrict u_x,                        \
        double* __restrict u_y, double* __restrict memory, double* __restrict t_x, double* __restrict t_y
#define MDR_STICK_OR_SLIP_ARGUMENTS                                                                                    \
    count, branches, n, increment, g_inf, stiffness, per_load, weight, decay, gain, mask, share, loads, written,       \
        profile, normal_h, moduli, scale, shift, u_x, u_y, memory, t_x, t_y
__attribute__((target_clones("avx2", "default"))) PlanarVector stick_or_slip_written(MDR_STICK_OR_SLIP_PARAMETERS) {
    stick_or_slip<false>(MDR_STICK_OR_SLIP_ARGUMENTS);
    return interleaved_sums(t_x, t_y, count);
}
__attribute__((target_clones("avx2", "default"))) PlanarVector stick_or_slip_composed(MDR_STICK_OR_SLIP_PARAMETERS) {
    stick_or_slip<true>(MDR_STICK_OR_SLIP_ARGUMENTS);
    return interleaved_sums(t_x, t_y, count);
}
#undef MDR_STICK_OR_SLIP_PARAMETERS
#undef MDR_STICK_OR_SLIP_ARGUMENTS

// q_z,i of element i (not vectorised: trials only).
double line_load(const LineLoadForm& loads, std::size_t branches, std::size_t i) {
    if (loads.written != nullptr) return loads.written[i];
    return composed_line_load(i, branches, loads.depth, loads.g_inf, loads.dashpot, loads.profile, loads.h,
                              loads.stride, loads.moduli, loads.scale, loads.shift);
}

}  // namespace

PlanarTangentialLayer::PlanarTangentialLayer(const rheology::Rheology& material, double friction, double spacing,
                                             std::size_t count)
    : material_(material),
      per_load_(friction / tangential_stiffness_factor),
      spacing_(spacing),
      count_(count),
      displacement_(2 * count, 0.0),
      stress_(2 * count, 0.0),
      memory_(2 * count * material.terms().size(), 0.0),
      weight_(material.terms().size(), 0.0),
      share_(count) {}

void PlanarTangentialLayer::begin_step(const StepCoefficients& coefficients, std::span<const Entry> entries) {
    share_.set(entries);
    // The coefficients are the material's for the time step (fill_step_coefficients): the same step length, the
    // same coefficients and weights (a DEM code's every step).
    if (prepared_ && coefficients.time_step == step_.time_step) return;
    copy_step_coefficients(coefficients, step_);
    const auto& terms = material_.terms();
    for (std::size_t k = 0; k < terms.size(); ++k) weight_[k] = terms[k].modulus * step_.decay[k];
    prepared_ = true;
}

PlanarVector PlanarTangentialLayer::trial_force(PlanarVector increment, std::span<const double> normal_line_loads,
                                                std::span<const double> contact) const {
    return trial_force(increment, LineLoadForm{.written = normal_line_loads.data()}, contact);
}

PlanarVector PlanarTangentialLayer::trial_force(PlanarVector increment, const LineLoadForm& normal_line_loads,
                                                std::span<const double> contact) const {
    const std::size_t n = count_;
    // The stresses of advance's pass, summed in its order (interleaved_sums), so that a trial of the increment a step
    // then takes gives that step's force to the bit.
    double* t_x = stress_.data();
    double* t_y = stress_.data() + n;
    for (std::size_t i = 0; i < contact.size(); ++i) {
        t_x[i] = t_y[i] = 0.0;
        if (contact[i] == 0.0) continue;
        const double q = line_load(normal_line_loads, weight_.size(), i);
        const double bound = per_load_ * std::max(q, 0.0);  // eq. (50), a circle
        const PlanarVector relaxed = relaxed_stress(i, weight_.size(), n, material_.equilibrium_modulus(),
                                                    weight_.data(), displacements(), displacements() + n, memories());
        const double trial_x = relaxed[0] + step_.stiffness * (increment[0] * share_[i]);
        const double trial_y = relaxed[1] + step_.stiffness * (increment[1] * share_[i]);
        const double magnitude = std::sqrt(trial_x * trial_x + trial_y * trial_y);
        const double scale = magnitude <= bound ? 1.0 : bound / magnitude;
        t_x[i] = trial_x * scale;
        t_y[i] = trial_y * scale;
    }
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;
    const PlanarVector sum = interleaved_sums(t_x, t_y, contact.size());
    return {factor * sum[0], factor * sum[1]};
}

void PlanarTangentialLayer::advance(PlanarVector increment, std::span<const double> normal_line_loads,
                                    std::span<const double> contact) {
    advance(increment, LineLoadForm{.written = normal_line_loads.data()}, contact);
}

void PlanarTangentialLayer::advance(PlanarVector increment, const LineLoadForm& normal_line_loads,
                                    std::span<const double> contact) {
    touched_ = std::max(touched_, contact.size());
    high_water_ = std::max(high_water_, touched_);
    // As TangentialLayer: the loads and flags cover every element ever touched (count = contact.size()); the flags
    // are the mask of the stick-or-slip pass (1 or 0).
    const auto pass = normal_line_loads.written != nullptr ? stick_or_slip_written : stick_or_slip_composed;
    const LineLoadForm& q = normal_line_loads;
    double* u = displacements();
    const PlanarVector sum =
        pass(touched_, weight_.size(), count_, increment, material_.equilibrium_modulus(), step_.stiffness, per_load_,
             weight_.data(), step_.decay.data(), step_.gain.data(), contact.data(), share_.data(), q, q.written,
             q.profile, q.h, q.moduli, q.scale, q.shift, u, u + count_, memories(), stress_.data(),
             stress_.data() + count_);
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;
    total_force_ = {factor * sum[0], factor * sum[1]};
    if (header_ != nullptr) {
        header_[0] = total_force_[0];
        header_[1] = total_force_[1];
        header_[touched_offset] = static_cast<double>(touched_);
    }
}

void PlanarTangentialLayer::save_state(std::span<double> out) const {
    const std::size_t n = count_;
    out[0] = total_force_[0];
    out[1] = total_force_[1];
    out[touched_offset] = static_cast<double>(touched_);
    double* base = out.data() + 3;
    const std::size_t blocks = 2 + 2 * material_.terms().size();  // u_x, u_y, then h_x, h_y per branch
    for (std::size_t b = 0; b < blocks; ++b) {
        const double* from = b < 2 ? displacements() + b * n : memories() + (b - 2) * n;
        std::copy_n(from, touched_, base + b * n);
    }
}

void PlanarTangentialLayer::load_state(std::span<const double> in) {
    const std::size_t n = count_;
    header_ = nullptr;
    total_force_ = {in[0], in[1]};
    const auto touched = static_cast<std::size_t>(in[touched_offset]);
    const double* base = in.data() + 3;
    const std::size_t blocks = 2 + 2 * material_.terms().size();
    for (std::size_t b = 0; b < blocks; ++b) {
        double* to = b < 2 ? displacement_.data() + b * n : memory_.data() + (b - 2) * n;
        std::copy_n(base + b * n, touched, to);
        std::fill(to + touched, to + std::max(touched, high_water_), 0.0);  // zeros beyond the loaded elements
    }
    touched_ = touched;
    high_water_ = std::max(high_water_, touched_);
}

void PlanarTangentialLayer::attach(std::span<double> state) {
    // The state's element blocks have the layout of displacement_ and memory_ (u_x, u_y, then h_x, h_y per
    // branch), and hold zeros beyond its touched elements (initialised so, written only below the touched count).
    header_ = state.data();
    total_force_ = {state[0], state[1]};
    touched_ = static_cast<std::size_t>(state[touched_offset]);
    high_water_ = std::max(high_water_, touched_);
}

}  // namespace mdr::foundation
