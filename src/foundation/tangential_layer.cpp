#include "mdr/foundation/tangential_layer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "branch_sums.hpp"
#include "element_stiffness.hpp"

namespace mdr::foundation {
namespace {

constexpr double at_limit = 1e-9;                           // |t| within this fraction of the limit: at the limit

// Partial sums of a reduction: the sum of x[j] for j < size kept as partial[j % 8] (the last size % 8 values in
// partial[0]). Independent partial sums let the additions vectorise and overlap (a single running sum is a serial
// chain of additions); eight fill two 4-wide registers.
using Partials = std::array<double, 8>;

[[gnu::always_inline]] inline void add_partial(const double* x, std::size_t size, Partials& partial) {
    std::size_t j = 0;
    for (; j + 8 <= size; j += 8) {
        for (std::size_t lane = 0; lane < 8; ++lane) partial[lane] += x[j + lane];
    }
    for (; j < size; ++j) partial[0] += x[j];
}

double total(const Partials& p) { return ((p[0] + p[1]) + (p[2] + p[3])) + ((p[4] + p[5]) + (p[6] + p[7])); }

}  // namespace

TangentialLayer::TangentialLayer(const rheology::Rheology& material, double friction, double spacing,
                                 std::size_t count)
    : material_(material),
      per_load_(friction / tangential_stiffness_factor),
      spacing_(spacing),
      displacement_(count, 0.0),
      stress_(count, 0.0),
      memory_(count * material.terms().size(), 0.0),
      state_(count, TangentialState::free),
      relaxed_(count, 0.0),
      limit_(count, 0.0),
      share_(count),
      increment_(count, 0.0),
      work_(count, 0.0),
      slip_work_(count, 0.0),
      contact_mask_(count, 0.0),
      rate_gain_(material.terms().size(), 0.0) {}

__attribute__((target_clones("avx2", "default"))) void TangentialLayer::begin_step(const StepCoefficients& coefficients,
                                                                                    std::span<const Entry> entries) {
    copy_step_coefficients(coefficients, step_);
    jump_ = false;
    share_.set(entries);
    const std::size_t n = displacement_.size();
    relaxed_sums(material_, step_, displacement_.data(), memory_.data(), n, touched_, relaxed_.data());
    const auto& terms = material_.terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        // (1 - B) / r with r = dt/tau: its series below r = 1e-3, where 1 - B would cancel (B = 1 - r/2 + ...).
        const double r = step_.time_step / terms[k].relaxation_time;
        rate_gain_[k] = r < 1e-3 ? 0.5 - r / 6.0 + r * r / 24.0 - r * r * r / 120.0 : (1.0 - step_.gain[k]) / r;
    }
}

void TangentialLayer::begin_jump() {
    // No time: E_k = B_k = 1 (numerics notes eq. 16, 18), so h_k keeps its value with du_i = 0; no element enters.
    begin_step(step_coefficients(material_, 0.0));
    jump_ = true;
    // Eq. T1: the trial is the stress before the jump (its dashpot's part included) plus the increment, a stress.
    step_.stiffness = 1.0;
    std::copy_n(stress_.begin(), touched_, relaxed_.begin());
}

inline double TangentialLayer::limit(double normal_line_load) const {
    // |F_x,i| <= mu F_N,i with F_x,i = (8/3) dx t_i and F_N,i = q_z,i dx (eq. 50).
    return per_load_ * std::max(normal_line_load, 0.0);
}

__attribute__((target_clones("avx2", "default"))) double TangentialLayer::trial_force(
    double increment, std::span<const double> normal_line_loads, std::span<const double> contact) const {
    // advance()'s stress, branch-free: the stick trial clamped to the friction limit in contact, to a limit of 0
    // (so to 0) outside. In blocks on the stack: the contact flags as doubles first, so that the element loop has one
    // element width, then the stresses, so that their sum vectorises (GCC does not vectorise a reduction whose terms
    // mix widths).
    constexpr std::size_t block = 256;  // a multiple of 8: the sum is add_partial's over all elements
    std::array<double, block> in, stresses;
    Partials partial{};
    const double stiffness = step_.stiffness;
    const double per_load = per_load_;
    const std::size_t count = contact.size();
    for (std::size_t start = 0; start < count; start += block) {
        const std::size_t length = std::min(block, count - start);
        const double* flags = contact.data() + start;
        for (std::size_t j = 0; j < length; ++j) in[j] = flags[j] != 0.0 ? 1.0 : 0.0;
        const double* relaxed = relaxed_.data() + start;
        const double* share = share_.data() + start;
        const double* q = normal_line_loads.data() + start;
        for (std::size_t j = 0; j < length; ++j) {
            const double bound = in[j] * (per_load * std::max(q[j], 0.0));  // limit(), 0 out of contact
            const double trial = relaxed[j] + stiffness * (increment * share[j]);
            stresses[j] = std::min(std::max(trial, -bound), bound);
        }
        add_partial(stresses.data(), length, partial);
    }
    return 2.0 * tangential_stiffness_factor * spacing_ * total(partial);
}

double TangentialLayer::sliding_force(std::span<const double> normal_line_loads,
                                      std::span<const double> contact) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < contact.size(); ++i) {
        if (contact[i] != 0.0) sum += limit(normal_line_loads[i]);
    }
    return 2.0 * tangential_stiffness_factor * spacing_ * sum;
}

double TangentialLayer::sliding_increment(double direction, std::span<const double> normal_line_loads,
                                          std::span<const double> contact) const {
    double increment = 0.0;
    bool any = false;
    for (std::size_t i = 0; i < contact.size(); ++i) {
        if (contact[i] == 0.0 || share_[i] == 0.0) continue;
        const double reach = (direction * limit(normal_line_loads[i]) - relaxed_[i]) / (step_.stiffness * share_[i]);
        increment = any ? (direction > 0.0 ? std::max(increment, reach) : std::min(increment, reach)) : reach;
        any = true;
    }
    return increment;
}

__attribute__((target_clones("avx2", "default"))) void TangentialLayer::advance(
    double increment, std::span<const double> normal_line_loads, std::span<const double> contact) {
    const std::size_t n = displacement_.size();
    touched_ = std::max(touched_, contact.size());
    high_water_ = std::max(high_water_, touched_);
    const std::size_t count = touched_;
    const auto& terms = material_.terms();
    const double dt = step_.time_step;
    const double viscous = dt > 0.0 ? material_.viscosity() / dt : 0.0;
    const double g_inf = material_.equilibrium_modulus();
    const double stiffness = step_.stiffness;
    if (jump_) {
        // In a jump (begin_jump) no element moves (eq. T1): the increment, a stress, goes into each trial, and the
        // pass below takes no increment and no compliance (a slipping element does not move either).
        for (std::size_t i = 0; i < count; ++i) relaxed_[i] += stiffness * (increment * share_[i]);
        increment = 0.0;
    }
    // The contact flags as doubles, so that the element pass below has one element width: GCC vectorises it four
    // elements to a register (with the bytes in it, 32 elements at a time, spilling registers).
    double* __restrict mask = contact_mask_.data();
    for (std::size_t i = 0; i < count; ++i) mask[i] = contact[i] != 0.0 ? 1.0 : 0.0;
    // One branch-free pass (it vectorises, with -fno-trapping-math, see CMakeLists.txt) takes every element's step
    // (eq. 50): in contact it first sticks, u_i += share du (an element entering moves only after its entry); when
    // then |t| exceeds the friction limit it slips, t = the limit with the sign of its trial, u_i solved from it;
    // out of contact it is force-free, t = 0. It writes the element's work over the step and friction's, and
    // updates the first branch's memory (h <- E h + B du, step_coefficients.hpp) in the same pass; the other
    // branches follow one per pass from du_i.
    const auto element_pass = [&](auto first_branch, auto more_branches) {
        constexpr bool fused = decltype(first_branch)::value;
        constexpr bool keep_increments = decltype(more_branches)::value;
        const double* __restrict relaxed = relaxed_.data();
        const double* __restrict share = share_.data();
        const double* __restrict q = normal_line_loads.data();
        double* __restrict u = displacement_.data();
        double* __restrict t = stress_.data();
        double* __restrict bound_of = limit_.data();
        double* __restrict du = increment_.data();
        double* __restrict work = work_.data();
        double* __restrict slip_work = slip_work_.data();
        double* __restrict h = memory_.data();  // branch 0
        const double compliance = jump_ ? 0.0 : 1.0 / stiffness;
        const double per_load = per_load_;
        const double modulus = fused ? terms[0].modulus : 0.0, decay = fused ? step_.decay[0] : 0.0;
        const double gain = fused ? step_.gain[0] : 0.0, rate_gain = fused ? rate_gain_[0] : 0.0;
#pragma GCC ivdep
        for (std::size_t i = 0; i < count; ++i) {
            // Products with the mask (1 or 0) rather than selects: GCC then keeps every store unconditional.
            const double in = mask[i];
            const double bound = per_load * std::max(q[i], 0.0);  // limit()
            const double moved = increment * share[i];
            const double trial = relaxed[i] + stiffness * moved;
            const double stress = in * std::min(std::max(trial, -bound), bound);  // the trial within the limit
            const double step_increment =
                in != 0.0 && std::abs(trial) <= bound ? moved : (stress - relaxed[i]) * compliance;
            // The mean stress over the step, int t dt / dt, times du (see material_work()).
            double element_work = (g_inf * (u[i] + 0.5 * step_increment) + viscous * step_increment) * step_increment;
            if constexpr (fused) {
                element_work += modulus * (gain * h[i] + rate_gain * step_increment) * step_increment;
                h[i] = decay * h[i] + gain * step_increment;
            }
            work[i] = element_work;
            slip_work[i] = in * (0.5 * (t[i] + stress) * (moved - step_increment));
            u[i] += step_increment;
            if constexpr (keep_increments) du[i] = step_increment;
            t[i] = stress;
            bound_of[i] = bound;
        }
    };
    if (terms.empty()) {
        element_pass(std::false_type{}, std::false_type{});
    } else if (terms.size() == 1) {
        element_pass(std::true_type{}, std::false_type{});
    } else {
        element_pass(std::true_type{}, std::true_type{});
    }
    for (std::size_t k = 1; k < terms.size(); ++k) {
        const double modulus = terms[k].modulus, decay = step_.decay[k], gain = step_.gain[k];
        const double rate_gain = rate_gain_[k];
        double* __restrict h = memory_.data() + k * n;
        const double* __restrict du = increment_.data();
        double* __restrict work = work_.data();
        for (std::size_t i = 0; i < count; ++i) {
            work[i] += modulus * (gain * h[i] + rate_gain * du[i]) * du[i];
            h[i] = decay * h[i] + gain * du[i];
        }
    }
    // The state: an element in contact stuck when its trial stayed inside the limit by more than at_limit (t is then
    // that trial); one held at its limit (a slip zone at rest) is in the slip zone of eq. (51).
    for (std::size_t i = 0; i < count; ++i) {
        const bool in = mask[i] != 0.0;
        const bool sticks = in & (std::abs(stress_[i]) < limit_[i] * (1.0 - at_limit));
        state_[i] = sticks ? TangentialState::stick : (in ? TangentialState::slip : TangentialState::free);
    }
    sticking_ = static_cast<std::size_t>(
        std::count(state_.begin(), state_.begin() + static_cast<std::ptrdiff_t>(count), TangentialState::stick));
    Partials force{}, material{}, friction{};
    add_partial(stress_.data(), count, force);
    add_partial(work_.data(), count, material);
    add_partial(slip_work_.data(), count, friction);
    const double scale = 2.0 * tangential_stiffness_factor * spacing_;
    total_force_ = scale * total(force);
    material_work_ = scale * total(material);
    friction_work_ = scale * total(friction);
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
    sticking_ = static_cast<std::size_t>(
        std::count(state_.begin(), state_.begin() + static_cast<std::ptrdiff_t>(touched_), TangentialState::stick));
}

double TangentialLayer::stick_slope() const {
    return 2.0 * tangential_stiffness_factor * spacing_ * step_.stiffness * static_cast<double>(sticking_);
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
