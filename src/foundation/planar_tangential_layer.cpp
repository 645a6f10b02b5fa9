#include "mdr/foundation/planar_tangential_layer.hpp"

#include <algorithm>
#include <cmath>

#include "branch_sums.hpp"

namespace mdr::foundation {
namespace {

constexpr double tangential_stiffness_factor = 8.0 / 3.0;  // k_x = (8/3) G dx, eq. (11), (41)

}  // namespace

PlanarTangentialLayer::PlanarTangentialLayer(const rheology::Rheology& material, double friction, double spacing,
                                             std::size_t count)
    : material_(material),
      per_load_(friction / tangential_stiffness_factor),
      spacing_(spacing),
      displacement_(2 * count, 0.0),
      stress_(2 * count, 0.0),
      memory_(2 * count * material.terms().size(), 0.0),
      relaxed_(2 * count, 0.0),
      share_(count, 1.0) {
    entered_.reserve(count);
}

void PlanarTangentialLayer::begin_step(const StepCoefficients& coefficients, std::span<const Entry> entries) {
    step_ = coefficients;
    for (const std::size_t i : entered_) share_[i] = 1.0;
    entered_.clear();
    for (const Entry& entry : entries) {
        share_[entry.element] = 1.0 - entry.fraction;
        entered_.push_back(entry.element);
    }
    relaxed_sums(material_, step_, displacement_.data(), memory_.data(), displacement_.size(), 2 * touched_,
                 relaxed_.data());
}

PlanarVector PlanarTangentialLayer::trial_force(PlanarVector increment, std::span<const double> normal_line_loads,
                                                std::span<const std::uint8_t> contact) const {
    double sum_x = 0.0, sum_y = 0.0;
    for (std::size_t i = 0; i < contact.size(); ++i) {
        if (!contact[i]) continue;
        const double bound = per_load_ * std::max(normal_line_loads[i], 0.0);  // eq. (50), a circle
        const double trial_x = relaxed_[2 * i] + step_.stiffness * (increment[0] * share_[i]);
        const double trial_y = relaxed_[2 * i + 1] + step_.stiffness * (increment[1] * share_[i]);
        const double magnitude = std::sqrt(trial_x * trial_x + trial_y * trial_y);
        const double scale = magnitude <= bound ? 1.0 : bound / magnitude;
        sum_x += trial_x * scale;
        sum_y += trial_y * scale;
    }
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;
    return {factor * sum_x, factor * sum_y};
}

void PlanarTangentialLayer::advance(PlanarVector increment, std::span<const double> normal_line_loads,
                                    std::span<const std::uint8_t> contact) {
    touched_ = std::max(touched_, contact.size());
    high_water_ = std::max(high_water_, touched_);
    const std::size_t stride = displacement_.size();
    const auto& terms = material_.terms();
    const double compliance = 1.0 / step_.stiffness;
    double sum_x = 0.0, sum_y = 0.0;
    for (std::size_t i = 0; i < touched_; ++i) {
        // Eq. (50) with vectors: stick when the trial stays inside the friction circle, else slip along the trial;
        // out of contact force-free. An element beyond the contact's span is out of contact.
        const bool in = i < contact.size() && contact[i] != 0;
        const double bound = in ? per_load_ * std::max(normal_line_loads[i], 0.0) : 0.0;
        const double moved_x = increment[0] * share_[i], moved_y = increment[1] * share_[i];
        const double trial_x = relaxed_[2 * i] + step_.stiffness * moved_x;
        const double trial_y = relaxed_[2 * i + 1] + step_.stiffness * moved_y;
        const double magnitude = std::sqrt(trial_x * trial_x + trial_y * trial_y);
        const bool sticks = in && magnitude <= bound;
        const double scale = sticks ? 1.0 : (in ? bound / magnitude : 0.0);
        const double stress_x = trial_x * scale, stress_y = trial_y * scale;
        const double du_x = sticks ? moved_x : (stress_x - relaxed_[2 * i]) * compliance;
        const double du_y = sticks ? moved_y : (stress_y - relaxed_[2 * i + 1]) * compliance;
        for (std::size_t k = 0; k < terms.size(); ++k) {  // h <- E h + B du (step_coefficients.hpp)
            double* h = memory_.data() + k * stride + 2 * i;
            h[0] = step_.decay[k] * h[0] + step_.gain[k] * du_x;
            h[1] = step_.decay[k] * h[1] + step_.gain[k] * du_y;
        }
        displacement_[2 * i] += du_x;
        displacement_[2 * i + 1] += du_y;
        stress_[2 * i] = stress_x;
        stress_[2 * i + 1] = stress_y;
        sum_x += stress_x;
        sum_y += stress_y;
    }
    const double factor = 2.0 * tangential_stiffness_factor * spacing_;
    total_force_ = {factor * sum_x, factor * sum_y};
}

void PlanarTangentialLayer::save_state(std::span<double> out) const {
    const std::size_t stride = displacement_.size();
    out[0] = total_force_[0];
    out[1] = total_force_[1];
    out[touched_offset] = static_cast<double>(touched_);
    double* u = out.data() + 3;
    double* t = u + stride;
    double* h = t + stride;
    const std::size_t used = 2 * touched_;
    std::copy_n(displacement_.data(), used, u);
    std::copy_n(stress_.data(), used, t);
    for (std::size_t k = 0; k < material_.terms().size(); ++k) {
        std::copy_n(memory_.data() + k * stride, used, h + k * stride);
    }
}

void PlanarTangentialLayer::load_state(std::span<const double> in) {
    const std::size_t stride = displacement_.size();
    const std::size_t branches = material_.terms().size();
    total_force_ = {in[0], in[1]};
    const auto touched = static_cast<std::size_t>(in[touched_offset]);
    for (std::size_t j = 2 * touched; j < 2 * high_water_; ++j) {  // zeros beyond the loaded state's elements
        displacement_[j] = stress_[j] = relaxed_[j] = 0.0;
        for (std::size_t k = 0; k < branches; ++k) memory_[k * stride + j] = 0.0;
    }
    const double* u = in.data() + 3;
    const double* t = u + stride;
    const double* h = t + stride;
    const std::size_t used = 2 * touched;
    std::copy_n(u, used, displacement_.data());
    std::copy_n(t, used, stress_.data());
    for (std::size_t k = 0; k < branches; ++k) std::copy_n(h + k * stride, used, memory_.data() + k * stride);
    touched_ = touched;
    high_water_ = std::max(high_water_, touched_);
}

}  // namespace mdr::foundation
