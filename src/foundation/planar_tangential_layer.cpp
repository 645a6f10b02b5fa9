#include "mdr/foundation/planar_tangential_layer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "element_stiffness.hpp"
#include "with_branches.hpp"

namespace mdr::foundation {
namespace {


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

// Eq. (50) with vectors over `count` elements, one branch-free pass (selects, so that it vectorises with
// -fno-trapping-math and -fno-math-errno): an element in contact (mask 1) sticks while its trial, its relaxed stress
// plus k du, stays inside the friction circle of radius per_load q_i and slips along its trial otherwise; out of
// contact (mask 0) it is force-free. Writes the new stress t, adds the element's increment du to u and updates its
// memories, h <- E h + B du (step_coefficients.hpp; `decay` E_k, `gain` B_k). The relaxed stresses are formed here,
// not in a pass of their own. Returns the number of elements in contact that slipped (an integer count, so that the
// pass still vectorises). A free function of restrict pointers: inside the member function GCC 12 leaves this
// loop scalar.
__attribute__((target_clones("avx2", "default"))) std::int64_t stick_or_slip(
    std::size_t count, std::size_t branches, std::size_t n, PlanarVector increment, double g_inf, double stiffness,
    double per_load, const double* __restrict weight, const double* __restrict decay, const double* __restrict gain,
    const double* __restrict mask, const double* __restrict q, const double* __restrict share,
    double* __restrict u_x, double* __restrict u_y, double* __restrict memory, double* __restrict t_x,
    double* __restrict t_y) {
    return with_branches(branches, [&](auto m) {
        const double compliance = 1.0 / stiffness;
        std::int64_t slips = 0;
        const double along_x = increment[0], along_y = increment[1];
        for (std::size_t i = 0; i < count; ++i) {
            const PlanarVector relaxed = relaxed_stress(i, m, n, g_inf, weight, u_x, u_y, memory);
            const double in = mask[i];
            const double bound = in * per_load * std::max(q[i], 0.0);
            const double moved_x = along_x * share[i], moved_y = along_y * share[i];
            const double trial_x = relaxed[0] + stiffness * moved_x;
            const double trial_y = relaxed[1] + stiffness * moved_y;
            const double magnitude = std::sqrt(trial_x * trial_x + trial_y * trial_y);
            const bool sticks = in != 0.0 && magnitude <= bound;
            // bitwise, not &&: GCC 12 leaves the loop scalar with the conditional form of this count
            slips += static_cast<std::int64_t>(in != 0.0) & static_cast<std::int64_t>(!sticks);
            const double scale = sticks ? 1.0 : (in != 0.0 ? bound / magnitude : 0.0);
            const double stress_x = trial_x * scale, stress_y = trial_y * scale;
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
        return slips;
    });
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
    const std::size_t n = count_;
    double sum_x = 0.0, sum_y = 0.0;
    for (std::size_t i = 0; i < contact.size(); ++i) {
        if (contact[i] == 0.0) continue;
        const double bound = per_load_ * std::max(normal_line_loads[i], 0.0);  // eq. (50), a circle
        const PlanarVector relaxed = relaxed_stress(i, weight_.size(), n, material_.equilibrium_modulus(),
                                                    weight_.data(), displacements(), displacements() + n, memories());
        const double trial_x = relaxed[0] + step_.stiffness * (increment[0] * share_[i]);
        const double trial_y = relaxed[1] + step_.stiffness * (increment[1] * share_[i]);
        const double magnitude = std::sqrt(trial_x * trial_x + trial_y * trial_y);
        const double scale = magnitude <= bound ? 1.0 : bound / magnitude;
        sum_x += trial_x * scale;
        sum_y += trial_y * scale;
    }
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;
    return {factor * sum_x, factor * sum_y};
}

void PlanarTangentialLayer::advance(PlanarVector increment, std::span<const double> normal_line_loads,
                                    std::span<const double> contact) {
    touched_ = std::max(touched_, contact.size());
    high_water_ = std::max(high_water_, touched_);
    const std::size_t n = count_, count = touched_;
    // As TangentialLayer: the loads and flags cover every element ever touched (count = contact.size()); the flags
    // are the mask of the stick-or-slip pass (1 or 0).
    double* u = displacements();
    const double* t_x = stress_.data();
    const double* t_y = stress_.data() + n;
    const std::int64_t slips =
        stick_or_slip(count, weight_.size(), n, increment, material_.equilibrium_modulus(), step_.stiffness,
                      per_load_, weight_.data(), step_.decay.data(), step_.gain.data(), contact.data(),
                      normal_line_loads.data(), share_.data(), u, u + n, memories(), stress_.data(),
                      stress_.data() + n);
    stuck_ = slips == 0;
    double sum_x = 0.0, sum_y = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        sum_x += t_x[i];
        sum_y += t_y[i];
    }
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;
    total_force_ = {factor * sum_x, factor * sum_y};
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
