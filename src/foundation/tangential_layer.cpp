#include "mdr/foundation/tangential_layer.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "branch_sums.hpp"

namespace mdr::foundation {
namespace {

constexpr double tangential_stiffness_factor = 8.0 / 3.0;  // k_x = (8/3) G dx, eq. (11), (41)
constexpr double at_limit = 1e-9;                           // |t| within this fraction of the limit: at the limit

}  // namespace

TangentialLayer::TangentialLayer(const rheology::Rheology& material, double friction, double spacing,
                                 std::size_t count)
    : material_(material),
      friction_(friction),
      spacing_(spacing),
      displacement_(count, 0.0),
      stress_(count, 0.0),
      memory_(count * material.terms().size(), 0.0),
      state_(count, TangentialState::free),
      relaxed_(count, 0.0),
      limit_(count, 0.0),
      share_(count, 1.0),
      rate_gain_(material.terms().size(), 0.0) {}

void TangentialLayer::begin_step(const StepCoefficients& coefficients, std::span<const Entry> entries) {
    step_ = coefficients;
    for (const std::size_t i : entered_) share_[i] = 1.0;
    entered_.clear();
    for (const Entry& entry : entries) {
        share_[entry.element] = 1.0 - entry.fraction;
        entered_.push_back(entry.element);
    }
    const std::size_t n = displacement_.size();
    relaxed_sums(material_, step_, displacement_.data(), memory_.data(), n, touched_, relaxed_.data());
    const auto& terms = material_.terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        // (1 - B) / r with r = dt/tau: its series below r = 1e-3, where 1 - B would cancel (B = 1 - r/2 + ...).
        const double r = step_.time_step / terms[k].relaxation_time;
        rate_gain_[k] = r < 1e-3 ? 0.5 - r / 6.0 + r * r / 24.0 - r * r * r / 120.0 : (1.0 - step_.gain[k]) / r;
    }
}

inline double TangentialLayer::limit(double normal_line_load) const {
    // |F_x,i| <= mu F_N,i with F_x,i = (8/3) dx t_i and F_N,i = q_z,i dx (eq. 50).
    return friction_ * std::max(normal_line_load, 0.0) / tangential_stiffness_factor;
}

inline TangentialLayer::ElementStep TangentialLayer::element_step(std::size_t i, double increment, double normal_line_load,
                                                           bool contact) const {
    const double relaxed = relaxed_[i];
    const double stiffness = step_.stiffness;
    if (!contact) return {-relaxed / stiffness, 0.0, TangentialState::free};
    increment *= share_[i];  // an element entering in the step moves only after its entry
    const double trial = relaxed + stiffness * increment;
    const double bound = limit(normal_line_load);
    // An element held exactly at its limit (a slip zone at rest) is still in the slip zone of eq. (51).
    if (std::abs(trial) < bound * (1.0 - at_limit)) return {increment, trial, TangentialState::stick};
    if (std::abs(trial) <= bound) return {increment, trial, TangentialState::slip};
    const double stress = std::copysign(bound, trial);
    return {(stress - relaxed) / stiffness, stress, TangentialState::slip};
}

double TangentialLayer::trial_force(double increment, std::span<const double> normal_line_loads,
                                    std::span<const std::uint8_t> contact) const {
    // element_step's stress, branch-free: the stick trial clamped to the friction limit in contact, 0 outside.
    const double stiffness = step_.stiffness;
    const double per_load = friction_ / tangential_stiffness_factor;  // limit() per unit line load
    const double* __restrict relaxed = relaxed_.data();
    const double* __restrict share = share_.data();
    const double* __restrict q = normal_line_loads.data();
    const std::uint8_t* __restrict in_contact = contact.data();
    std::array<double, 4> partial{};  // four partial sums: the reduction vectorises
    const std::size_t count = contact.size();
    std::size_t i = 0;
    const auto stress = [&](std::size_t j) {
        const double bound = per_load * std::max(q[j], 0.0);
        const double trial = relaxed[j] + stiffness * (increment * share[j]);
        return in_contact[j] ? std::min(std::max(trial, -bound), bound) : 0.0;
    };
    for (; i + 4 <= count; i += 4) {
        for (std::size_t lane = 0; lane < 4; ++lane) partial[lane] += stress(i + lane);
    }
    for (; i < count; ++i) partial[0] += stress(i);
    const double sum = (partial[0] + partial[1]) + (partial[2] + partial[3]);
    return 2.0 * tangential_stiffness_factor * spacing_ * sum;
}

double TangentialLayer::sliding_force(std::span<const double> normal_line_loads,
                                      std::span<const std::uint8_t> contact) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < contact.size(); ++i) {
        if (contact[i]) sum += limit(normal_line_loads[i]);
    }
    return 2.0 * tangential_stiffness_factor * spacing_ * sum;
}

double TangentialLayer::sliding_increment(double direction, std::span<const double> normal_line_loads,
                                          std::span<const std::uint8_t> contact) const {
    double increment = 0.0;
    bool any = false;
    for (std::size_t i = 0; i < contact.size(); ++i) {
        if (!contact[i] || share_[i] == 0.0) continue;
        const double reach = (direction * limit(normal_line_loads[i]) - relaxed_[i]) / (step_.stiffness * share_[i]);
        increment = any ? (direction > 0.0 ? std::max(increment, reach) : std::min(increment, reach)) : reach;
        any = true;
    }
    return increment;
}

void TangentialLayer::advance(double increment, std::span<const double> normal_line_loads,
                              std::span<const std::uint8_t> contact) {
    const std::size_t n = displacement_.size();
    touched_ = std::max(touched_, contact.size());
    high_water_ = std::max(high_water_, touched_);
    const auto& terms = material_.terms();
    const double dt = step_.time_step;
    const double viscous = dt > 0.0 ? material_.viscosity() / dt : 0.0;
    double sum = 0.0, material_work = 0.0, friction_work = 0.0;
    for (std::size_t i = 0; i < touched_; ++i) {
        const ElementStep s = element_step(i, increment, normal_line_loads[i], contact[i] != 0);
        // The element's mean stress over the step, int t dt / dt (see material_work()).
        double mean = material_.equilibrium_modulus() * (displacement_[i] + 0.5 * s.increment) + viscous * s.increment;
        displacement_[i] += s.increment;
        for (std::size_t k = 0; k < terms.size(); ++k) {
            double& h = memory_[k * n + i];
            mean += terms[k].modulus * (step_.gain[k] * h + rate_gain_[k] * s.increment);
            h = step_.decay[k] * h + step_.gain[k] * s.increment;
        }
        material_work += mean * s.increment;
        if (contact[i]) friction_work += 0.5 * (stress_[i] + s.stress) * (share_[i] * increment - s.increment);
        stress_[i] = s.stress;
        state_[i] = s.state;
        limit_[i] = limit(normal_line_loads[i]);
        sum += s.stress;
    }
    total_force_ = 2.0 * tangential_stiffness_factor * spacing_ * sum;
    material_work_ = 2.0 * tangential_stiffness_factor * spacing_ * material_work;
    friction_work_ = 2.0 * tangential_stiffness_factor * spacing_ * friction_work;
}

void TangentialLayer::save_state(std::span<double> out) const {
    const std::size_t n = size();
    out[0] = total_force_;
    out[1] = static_cast<double>(touched_);
    double* u = out.data() + 2;
    double* t = u + n;
    double* state = t + n;
    double* bound = state + n;
    double* h = bound + n;
    for (std::size_t i = 0; i < touched_; ++i) {
        u[i] = displacement_[i];
        t[i] = stress_[i];
        state[i] = static_cast<double>(state_[i]);
        bound[i] = limit_[i];
    }
    for (std::size_t k = 0; k < material_.terms().size(); ++k) {
        for (std::size_t i = 0; i < touched_; ++i) h[k * n + i] = memory_[k * n + i];
    }
}

void TangentialLayer::load_state(std::span<const double> in) {
    const std::size_t n = size();
    const std::size_t branches = material_.terms().size();
    total_force_ = in[0];
    const std::size_t touched = static_cast<std::size_t>(in[1]);
    for (std::size_t i = touched; i < high_water_; ++i) {  // zeros beyond the loaded state's elements
        displacement_[i] = stress_[i] = relaxed_[i] = limit_[i] = 0.0;
        state_[i] = TangentialState::free;
        for (std::size_t k = 0; k < branches; ++k) memory_[k * n + i] = 0.0;
    }
    const double* u = in.data() + 2;
    const double* t = u + n;
    const double* state = t + n;
    const double* bound = state + n;
    const double* h = bound + n;
    for (std::size_t i = 0; i < touched; ++i) {
        displacement_[i] = u[i];
        stress_[i] = t[i];
        state_[i] = static_cast<TangentialState>(static_cast<std::uint8_t>(state[i]));
        limit_[i] = bound[i];
    }
    for (std::size_t k = 0; k < branches; ++k) {
        for (std::size_t i = 0; i < touched; ++i) memory_[k * n + i] = h[k * n + i];
    }
    touched_ = touched;
    high_water_ = std::max(high_water_, touched_);
}

double TangentialLayer::stick_slope() const {
    const auto end = state_.begin() + static_cast<std::ptrdiff_t>(touched_);
    const auto sticking = std::count(state_.begin(), end, TangentialState::stick);
    return 2.0 * tangential_stiffness_factor * spacing_ * step_.stiffness * static_cast<double>(sticking);
}

double TangentialLayer::stick_radius(double contact_radius) const {
    const auto end = state_.begin() + static_cast<std::ptrdiff_t>(touched_);
    const auto first_slip = std::find(state_.begin(), end, TangentialState::slip);
    const bool any_contact = std::any_of(state_.begin(), end,
                                         [](TangentialState s) { return s != TangentialState::free; });
    if (!any_contact) return 0.0;
    if (first_slip == end) return contact_radius;
    const auto j = static_cast<std::size_t>(first_slip - state_.begin());
    if (j == 0 || state_[j - 1] != TangentialState::stick) {
        return j == 0 ? 0.0 : (static_cast<double>(j)) * spacing_;
    }
    // The limit mu F_N(x), linear between the two centres, meets the sticking element's force.
    const double inside = limit_[j - 1] - std::abs(stress_[j - 1]);
    const double drop = limit_[j - 1] - limit_[j];
    const double fraction = drop > 0.0 ? std::clamp(inside / drop, 0.0, 1.0) : 0.0;
    return (static_cast<double>(j) - 0.5 + fraction) * spacing_;
}

std::vector<double> TangentialLayer::line_loads() const {
    std::vector<double> q(stress_.size());
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = tangential_stiffness_factor * stress_[i];
    return q;
}

}  // namespace mdr::foundation
