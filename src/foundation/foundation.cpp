#include "mdr/foundation/foundation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <new>
#include <optional>
#include <type_traits>
#include <utility>

#include "branch_sums.hpp"
#include "element_stiffness.hpp"
#include "mdr/error.hpp"

namespace mdr::foundation {

void require_element_count(const std::string& key, std::size_t count) {
    if (count < 1 || count > max_elements) {
        throw InvalidInput(key, std::to_string(count),
                           "must be from 1 to " + std::to_string(max_elements) +
                               " (the state would not fit in memory)");
    }
}

bool state_fits(std::size_t count, std::size_t branches) {
    return count <= max_elements && count * (branches + 9) <= max_elements * 4;
}

namespace {

// g just beyond the half-width: +infinity beyond a flat punch's radius and beyond a tabulated profile's end.
double beyond_half_width(const profile::Profile& profile, double half_width) {
    return profile.equivalent(half_width * (1.0 + 1e-12));
}

}  // namespace

double deepest_depth(const profile::Profile& profile, double half_width) {
    const double beyond = beyond_half_width(profile, half_width);
    return std::isfinite(beyond) || profile.is_flat_punch() ? beyond : profile.equivalent(half_width);
}

namespace {



// An element's step when no entry or exit splits it: w follows the indenter in contact (eq. 13) and is
// force-free outside (eq. 20). `split` tells that it would need a tensile force in contact (an exit) or that the
// indenter reaches its creeping surface outside (an entry, eq. 14). Branch-free, so that loops over it vectorise.
struct PlainStep {
    double increment;  ///< dw
    double stress;     ///< sigma at the end of the step
    double split;      ///< 1 when an exit or entry happens inside the step, else 0 (a double: with a bool member
                       ///< GCC 12 does not vectorise the loop over it)
};

inline PlainStep plain_step(bool contact, double contact_relaxed, double free_relaxed, double g, double w,
                            double depth_end, double contact_stiffness, double free_stiffness) {
    const double contact_increment = depth_end - g - w;
    const double contact_stress = contact_relaxed + contact_stiffness * contact_increment;
    const double free_increment = -free_relaxed / free_stiffness;
    const double gap_end = contact_increment - free_increment;  // indenter below the free surface when > 0
    return {contact ? contact_increment : free_increment, contact ? contact_stress : 0.0,
            contact ? (contact_stress >= 0.0 ? 0.0 : 1.0) : (gap_end <= 0.0 ? 0.0 : 1.0)};
}

// Foundation::advance's branch-free pass over elements [0, end): steps every element in place as if unsplit (w,
// sigma), keeping its start w and sigma, its increment dw, and event = 1 where an entry or exit splits the step. A
// free function of restrict pointers: inside the member function GCC 12 leaves this loop scalar.
__attribute__((target_clones("avx2", "default"))) void plain_pass(
    std::size_t end, double depth_end, double contact_offset, double contact_stiffness, double free_stiffness,
    const double* __restrict g, const double* __restrict contact, const double* __restrict relaxed,
    const double* __restrict free_relaxed, double* __restrict w, double* __restrict sigma,
    double* __restrict start_w, double* __restrict start_sigma, double* __restrict dw, double* __restrict event) {
    for (std::size_t i = 0; i < end; ++i) {
        const double w0 = w[i];
        const PlainStep plain = plain_step(contact[i] != 0.0, relaxed[i] + contact_offset, free_relaxed[i], g[i], w0,
                                           depth_end, contact_stiffness, free_stiffness);
        start_w[i] = w0;
        start_sigma[i] = sigma[i];
        w[i] = w0 + plain.increment;
        sigma[i] = plain.stress;
        dw[i] = plain.increment;
        event[i] = plain.split;
    }
}

}  // namespace

struct Foundation::Outcome {
    double stress = 0.0;     ///< sigma at the end of the step
    bool contact = false;    ///< contact flag at the end of the step
    bool split = false;      ///< an entry or exit happens inside the step
    double fraction = 0.0;   ///< where inside the step (0..1)
};

Foundation::Foundation(const rheology::Rheology& material, const profile::Profile& profile, double spacing,
                       std::size_t count)
    : material_(material), spacing_(spacing) {
    require_positive("numerics.elements", static_cast<double>(count));
    const std::size_t branches = material.terms().size();
    if (!state_fits(count, branches)) {
        throw InvalidInput("numerics.elements", std::to_string(count),
                           "the foundation state would not fit in memory; use fewer elements");
    }
    try {
        equivalent_.resize(count);
        displacement_.assign(count, 0.0);
        stress_.assign(count, 0.0);
        memory_.assign(count * branches, 0.0);
        flags_.assign(count, 0.0);
        event_.assign(count, 0.0);
        start_displacement_.assign(count, 0.0);
        start_stress_.assign(count, 0.0);
        increment_.assign(count, 0.0);
        relaxed_.assign(count, 0.0);
        if (material.viscosity() > 0.0) free_relaxed_.assign(count, 0.0);
        scratch_.assign(branches, 0.0);
        scratch_gain_.assign(branches, 0.0);
    } catch (const std::bad_alloc&) {
        throw InvalidInput("numerics.elements", std::to_string(count),
                           "the foundation state does not fit in memory; use fewer elements");
    }
    for (std::size_t i = 0; i < count; ++i) equivalent_[i] = profile.equivalent(position(i));
    axis_ = profile.equivalent(0.0);
    // Beyond a tabulated profile nothing is known (not a rigid wall, as beyond a flat punch): the contact must stay
    // inside it.
    profile_ends_ = !profile.is_flat_punch() && !std::isfinite(beyond_half_width(profile, half_width()));
    profile_end_ = profile.max_radius();
    beyond_ = deepest_depth(profile, half_width());
}

__attribute__((target_clones("avx2", "default"))) void Foundation::begin_step(const StepCoefficients& coefficients,
                                                                               std::optional<double> indenter_rate,
                                                                               RateAtEntry rate_at_entry) {
    copy_step_coefficients(coefficients, step_);
    indenter_rate_ = indenter_rate;
    rate_at_entry_ = rate_at_entry;
    const std::size_t n = size();
    const double g_inf = material_.equilibrium_modulus();
    const double eta = material_.viscosity();
    const double dt = step_.time_step;
    const double springs = step_.stiffness - (dt > 0.0 ? eta / dt : 0.0);  // G_inf + sum G_k B_k
    // The dashpot's rate at the end of the step: the secant rate for a prescribed depth (exact while it is linear),
    // the trapezoidal 2 dd/dt - rate0 when the depth is solved from a smooth motion; a free element always takes
    // the trapezoidal rate from its own start rate -(G_inf w + sum G_k h)/eta (its force is zero).
    contact_stiffness_ = springs + (dt > 0.0 ? (indenter_rate ? 2.0 : 1.0) * eta / dt : 0.0);
    contact_offset_ = indenter_rate ? -eta * *indenter_rate : 0.0;
    free_stiffness_ = springs + (dt > 0.0 ? 2.0 * eta / dt : 0.0);
    const auto& terms = material_.terms();
    double* __restrict relaxed = relaxed_.data();
    const double* __restrict w = element_displacements();
    relaxed_sums(material_, step_, w, element_memories(), n, active_, relaxed);
    if (eta == 0.0) return;
    // free_relaxed = relaxed - eta rate0 = relaxed + G_inf w + sum_k G_k h_k.
    double* __restrict free_relaxed = free_relaxed_.data();
    for (std::size_t i = 0; i < active_; ++i) free_relaxed[i] = relaxed[i] + g_inf * w[i];
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double weight = terms[k].modulus;
        const double* __restrict h = element_memories() + k * n;
        for (std::size_t i = 0; i < active_; ++i) free_relaxed[i] += weight * h[i];
    }
}

std::size_t Foundation::reach(double depth) const {
    std::size_t i = active_;
    while (i < size() && equivalent_[i] < depth) ++i;
    return i;
}

Foundation::Outcome Foundation::evaluate(std::size_t i, double w0, double sigma0, double depth_start,
                                         double depth_end) const {
    const double g = equivalent_[i];
    const double w = w0;
    const bool contact = element_flags()[i] != 0.0;
    const double relaxed = i < active_ ? relaxed_[i] : 0.0;
    const double free_relaxed = i < active_ ? free_relaxed_of(i) : 0.0;
    const PlainStep plain = plain_step(contact, relaxed + contact_offset_, free_relaxed, g, w, depth_end,
                                       contact_stiffness_, free_stiffness_);
    Outcome outcome;
    outcome.contact = contact;
    outcome.stress = plain.stress;
    if (plain.split == 0.0) return outcome;
    outcome.split = true;
    outcome.contact = !contact;
    if (contact) {
        // Exit (eq. 20): the force crosses zero inside the step.
        const double before = sigma0;
        outcome.fraction = before > 0.0 ? before / (before - plain.stress) : 0.0;
    } else {
        // Entry (eq. 14): the indenter reaches the creeping surface inside the step; at its start where it touched
        // it then (an indenter riding on the recovering surface: gap_start = 0, and gap_end, rounded apart from
        // plain_step's, may be 0 too).
        const double gap_start = std::min(depth_start - g - w, 0.0);
        const double gap_end = depth_end - g - (w + plain.increment);
        outcome.fraction = gap_start < gap_end ? gap_start / (gap_start - gap_end) : 0.0;
    }
    return outcome;
}

double Foundation::spring_force(double w, const double* h) const {
    const auto& terms = material_.terms();
    double force = material_.equilibrium_modulus() * w;
    for (std::size_t k = 0; k < terms.size(); ++k) force += terms[k].modulus * h[k];
    return force;
}

double Foundation::free_rate(double w, const double* h) const {
    const double eta = material_.viscosity();
    return eta > 0.0 ? -spring_force(w, h) / eta : 0.0;  // G_inf w + eta w' + sum G_k h_k = 0
}

void Foundation::free_substep(double time_step, double& w, double* h) const {
    const auto& terms = material_.terms();
    const double eta = material_.viscosity();
    if (time_step <= 0.0 && eta > 0.0) return;  // a dashpot does not move in no time
    // Force-free: G_inf w + eta w' + sum G_k h_k = 0 at the end, the dashpot with the trapezoidal rate from its
    // start rate -(G_inf w + sum G_k h_k)/eta.
    const double start_force = spring_force(w, h);
    double relaxed = material_.equilibrium_modulus() * w + (eta > 0.0 ? start_force : 0.0);
    double stiffness = material_.equilibrium_modulus() + (eta > 0.0 ? 2.0 * eta / time_step : 0.0);
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double ratio = time_step / terms[k].relaxation_time;
        const double gain = branch_gain(ratio);
        h[k] *= std::exp(-ratio);
        relaxed += terms[k].modulus * h[k];
        stiffness += terms[k].modulus * gain;
        scratch_gain_[k] = gain;
    }
    const double dw = -relaxed / stiffness;
    for (std::size_t k = 0; k < terms.size(); ++k) h[k] += scratch_gain_[k] * dw;
    w += dw;
}

double Foundation::contact_substep(double time_step, double new_displacement, double end_rate, double& w,
                                   double* h) const {
    const auto& terms = material_.terms();
    const double dw = new_displacement - w;
    double stress = material_.equilibrium_modulus() * new_displacement + material_.viscosity() * end_rate;
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double ratio = time_step / terms[k].relaxation_time;
        h[k] = std::exp(-ratio) * h[k] + branch_gain(ratio) * dw;
        stress += terms[k].modulus * h[k];
    }
    w = new_displacement;
    return stress;
}

std::pair<double, double> Foundation::indenter_rates(double depth_start, double depth_end) const {
    const double secant = step_.time_step > 0.0 ? (depth_end - depth_start) / step_.time_step : 0.0;
    const double start_rate = indenter_rate_.value_or(secant);
    return {start_rate, indenter_rate_ ? 2.0 * secant - start_rate : secant};
}

double Foundation::split_stress(std::size_t i, double w0, const Outcome& outcome, double depth_start,
                                double depth_end, double& w, double* h, double* own_rate) const {
    const std::size_t n = size();
    const std::size_t branches = material_.terms().size();
    const double* memory = element_memories();
    w = w0;
    for (std::size_t k = 0; k < branches; ++k) h[k] = memory[k * n + i];
    const double first = outcome.fraction * step_.time_step;
    const double second = step_.time_step - first;
    const double g = equivalent_[i];
    const auto [start_rate, end_rate] = indenter_rates(depth_start, depth_end);
    if (outcome.contact) {  // free, then in contact from the entry on
        const bool own = rate_at_entry_ == RateAtEntry::breaks && step_.time_step > 0.0;
        const double start_rate_own = free_rate(w, h);
        free_substep(first, w, h);
        // Its own rate over the step (see begin_step), the trapezoidal from its free start rate or the secant with the
        // free part at its end rate.
        const double dt = step_.time_step;
        const double rate = !own            ? end_rate
                            : indenter_rate_ ? 2.0 * (depth_end - g - w0) / dt - start_rate_own
                                             : (depth_end - g - w) / dt + outcome.fraction * free_rate(w, h);
        if (own_rate != nullptr) *own_rate = rate;
        return std::max(contact_substep(second, depth_end - g, rate, w, h), 0.0);
    }
    const double depth_at_exit = depth_start + outcome.fraction * (depth_end - depth_start);
    contact_substep(first, depth_at_exit - g, start_rate + outcome.fraction * (end_rate - start_rate), w, h);
    free_substep(second, w, h);
    return 0.0;
}

double Foundation::trial_force(double depth_start, double depth_end) const {
    const std::size_t end = std::min(reach(std::max(depth_start, depth_end)), size());
    const double* displacement = element_displacements();
    const double* stress = element_stresses();
    const double* flags = element_flags();
    double sum = 0.0;
    double w = 0.0;
    for (std::size_t i = 0; i < end; ++i) {
        const bool touched = i < active_;
        const PlainStep plain =
            plain_step(flags[i] != 0.0, (touched ? relaxed_[i] : 0.0) + contact_offset_,
                       touched ? free_relaxed_of(i) : 0.0, equivalent_[i], displacement[i], depth_end,
                       contact_stiffness_, free_stiffness_);
        if (plain.split == 0.0) {
            sum += plain.stress;
            continue;
        }
        const Outcome outcome = evaluate(i, displacement[i], stress[i], depth_start, depth_end);
        sum += split_stress(i, displacement[i], outcome, depth_start, depth_end, w, scratch_.data());
    }
    return 2.0 * normal_stiffness_factor * spacing_ * sum;
}

double Foundation::touch_fraction(double depth_start, double depth_end) const {
    const std::size_t end = reach(std::max(depth_start, depth_end));
    const double* displacement = element_displacements();
    const double* stress = element_stresses();
    const double* flags = element_flags();
    double first = 1.0;
    for (std::size_t i = 0; i < end; ++i) {
        if (flags[i] != 0.0) continue;
        const Outcome outcome = evaluate(i, displacement[i], stress[i], depth_start, depth_end);
        if (outcome.split) first = std::min(first, outcome.fraction);
    }
    return first;
}

__attribute__((target_clones("avx2", "default"))) void Foundation::advance(double depth_start, double depth_end) {
    const double deepest = std::max(depth_start, depth_end);
    if (deepest > beyond_ && profile_ends_) {
        throw InvalidInput("indenter.r", "[..., " + format_value(profile_end_) + "]",
                           "the contact grows beyond the last tabulated radius at depth " + format_value(deepest) +
                               "; tabulate the profile further");
    }
    if (deepest > beyond_) {
        throw InvalidInput("numerics.half_width", format_value(half_width()),
                           "the contact reaches the end of the foundation at depth " + format_value(deepest) +
                               "; give a larger half-width");
    }
    const std::size_t n = size();
    const std::size_t end = reach(deepest);
    const std::size_t branches = material_.terms().size();
    // One branch-free pass over the elements (plain_pass; it vectorises, see CMakeLists.txt) steps every element in
    // place as if unsplit, keeping its start w and sigma in the start_* buffers, its increment dw, and event_ = 1
    // where an entry or exit splits the step (flags and events doubles, so that the pass has one element width).
    // The scalar pass over the few split elements starts from the kept values (relaxed_ is zero beyond active_,
    // never written there; the memories are not yet stepped), then the branch memories take dw and the split
    // elements are overwritten from their saved state. Elements at or beyond `end` are untouched: zero.
    const double* free_relaxed = material_.viscosity() > 0.0 ? free_relaxed_.data() : relaxed_.data();
    plain_pass(end, depth_end, contact_offset_, contact_stiffness_, free_stiffness_, equivalent_.data(),
               element_flags(), relaxed_.data(), free_relaxed, element_displacements(), element_stresses(),
               start_displacement_.data(), start_stress_.data(), increment_.data(), event_.data());
    {
        // The range of split elements (they gather at the contact edge), so that the scalar pass scans only it
        // (a pass of its own: with these reductions in it, plain_pass would not vectorise).
        const double* __restrict event = event_.data();
        std::int32_t first = static_cast<std::int32_t>(end), last = -1;
        for (std::size_t i = 0; i < end; ++i) {
            const auto index = static_cast<std::int32_t>(i);
            first = std::min(first, event[i] != 0.0 ? index : first);
            last = std::max(last, event[i] != 0.0 ? index : last);
        }
        split_first_ = static_cast<std::size_t>(first);
        split_end_ = static_cast<std::size_t>(last + 1);
    }
    split_.clear();
    end_rate_ = indenter_rates(depth_start, depth_end).second;
    entry_excess_ = 0.0;
    entries_.clear();
    split_state_.clear();
    latest_exit_ = 0.0;
    inner_exit_ = {-1.0, -1.0};
    receded_stress_.reset();
    for (std::size_t i = split_first_; i < split_end_; ++i) {
        if (event_[i] == 0.0) continue;
        const Outcome outcome = evaluate(i, start_displacement_[i], start_stress_[i], depth_start, depth_end);
        if (!outcome.contact) latest_exit_ = std::max(latest_exit_, outcome.fraction);
        if (!outcome.contact && i < inner_exit_.size()) inner_exit_[i] = outcome.fraction;
        double split_w = 0.0;
        const std::size_t offset = split_state_.size();
        split_state_.resize(offset + branches + 2);
        double own_rate = end_rate_;
        const double stress =
            split_stress(i, start_displacement_[i], outcome, depth_start, depth_end, split_w,
                         split_state_.data() + offset + 2, &own_rate);
        if (outcome.contact) entry_excess_ += own_rate - end_rate_;
        split_state_[offset] = split_w;
        split_state_[offset + 1] = stress;
        split_.push_back(i);
        if (outcome.contact) entries_.push_back({i, outcome.fraction});
        element_flags()[i] = outcome.contact ? 1.0 : 0.0;
    }
    const auto& terms = material_.terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double decay = step_.decay[k];
        const double gain = step_.gain[k];
        double* __restrict h = element_memories() + k * n;
        const double* __restrict dw = increment_.data();
        for (std::size_t i = 0; i < end; ++i) h[i] = decay * h[i] + gain * dw[i];
    }
    double* displacement = element_displacements();
    double* stress = element_stresses();
    double* memory = element_memories();
    for (std::size_t s = 0; s < split_.size(); ++s) {
        const std::size_t i = split_[s];
        const double* state = split_state_.data() + s * (branches + 2);
        displacement[i] = state[0];
        stress[i] = state[1];
        for (std::size_t k = 0; k < branches; ++k) memory[k * n + i] = state[2 + k];
    }
    active_ = std::max(active_, end);
    high_water_ = std::max(high_water_, active_);
    last_depth_ = depth_end;
    // Four partial sums: the reduction vectorises (a single running sum is a serial chain of additions).
    std::array<double, 4> partial{};
    std::size_t i = 0;
    for (; i + 4 <= active_; i += 4) {
        for (std::size_t lane = 0; lane < 4; ++lane) partial[lane] += stress[i + lane];
    }
    for (; i < active_; ++i) partial[0] += stress[i];
    const double sum = (partial[0] + partial[1]) + (partial[2] + partial[3]);
    total_force_ = 2.0 * normal_stiffness_factor * spacing_ * sum;
    if (attached_ != nullptr) {
        attached_[0] = last_depth_;
        attached_[1] = total_force_;
        attached_[2] = static_cast<double>(active_);
    }
}

std::optional<double> Foundation::jump(double force) {
    // eq. J1 (docs/theory.md section 3): force = 8 dx sum_{i in contact} max(sigma_i + eta dr, 0), continuous,
    // piecewise linear and increasing in dr where positive.
    const double contacts = static_cast<double>(contact_count());
    if (contacts == 0.0) return std::nullopt;
    const double eta = material_.viscosity();
    const double per_stress = 2.0 * normal_stiffness_factor * spacing_;  // F = 8 dx sum sigma (eq. 21)
    double* flags = element_flags();
    double* stress = element_stresses();
    // Every element kept: the force's change shared by the n dashpots, dF = 8 dx eta n dr (eq. 16, 21).
    double rate_change = (force - total_force_) / (per_stress * eta * contacts);
    total_force_ = force;
    if (attached_ != nullptr) attached_[1] = total_force_;
    receded_stress_.reset();
    if (force == 0.0) return rate_change;  // the state kept (see the declaration)
    double lowest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < active_; ++i) {
        if (flags[i] != 0.0) lowest = std::min(lowest, stress[i]);
    }
    // The kept set, where some would pull: the m largest stresses v_1 >= v_2 >= ... (prefix sums P_m), the rate
    // change dr_m = (force/(8 dx) - P_m)/(eta m); v_m + eta dr_m >= 0 holds exactly for m up to the solution's m*
    // (it reads force/(8 dx) >= P_m - m v_m, which grows with m), and then v_{m*+1} + eta dr_{m*} < 0.
    double threshold = lowest;
    if (lowest + eta * rate_change < 0.0) {
        std::vector<double> sorted;
        sorted.reserve(static_cast<std::size_t>(contacts));
        for (std::size_t i = 0; i < active_; ++i) {
            if (flags[i] != 0.0) sorted.push_back(stress[i]);
        }
        std::sort(sorted.begin(), sorted.end(), std::greater<>());
        const double target = force / per_stress;
        double prefix = 0.0;
        for (std::size_t m = 0; m < sorted.size(); ++m) {
            if (target < prefix - static_cast<double>(m) * sorted[m]) break;
            prefix += sorted[m];
            threshold = sorted[m];
            rate_change = (target - prefix) / (eta * static_cast<double>(m + 1));
        }
    }
    // The elements below the threshold leave with force 0, keeping w and h; the others carry sigma + eta dr. The
    // first element beyond the contact, where it left at the jump, keeps for the edge (contact_radius, eq. J2) the
    // stress it would have had in contact.
    std::size_t outer = 0;  // one past the outermost element kept
    for (std::size_t i = 0; i < active_; ++i) {
        if (flags[i] != 0.0 && stress[i] >= threshold) outer = i + 1;
    }
    if (outer < active_ && flags[outer] != 0.0) receded_stress_ = stress[outer] + eta * rate_change;
    for (std::size_t i = 0; i < active_; ++i) {
        if (flags[i] == 0.0) continue;
        const bool kept = stress[i] >= threshold;
        stress[i] = kept ? stress[i] + eta * rate_change : 0.0;
        flags[i] = kept ? 1.0 : 0.0;
    }
    return rate_change;
}

std::size_t Foundation::contact_count() const {
    const double* flags = element_flags();
    return static_cast<std::size_t>(std::count(flags, flags + active_, 1.0));
}

double Foundation::force_slope() const {
    return 2.0 * normal_stiffness_factor * spacing_ * contact_stiffness_ * static_cast<double>(contact_count());
}

double Foundation::contact_rate() const {
    const auto contacts = static_cast<double>(contact_count());
    return contacts > 0.0 ? end_rate_ + entry_excess_ / contacts : end_rate_;
}

double Foundation::free_gap(std::size_t i) const {
    if (i >= size()) return -std::numeric_limits<double>::infinity();
    return last_depth_ - equivalent_[i] - element_displacements()[i];
}

double Foundation::axis_weight() const {
    if (size() < 2 || !(equivalent_[1] > equivalent_[0])) return 0.0;
    return (axis_ - equivalent_[0]) / (equivalent_[1] - equivalent_[0]);
}

double Foundation::touching_depth() const {
    double lowest = std::numeric_limits<double>::infinity();
    const double* displacement = element_displacements();
    for (std::size_t i = 0; i < active_; ++i) lowest = std::min(lowest, equivalent_[i] + displacement[i]);
    if (active_ < 2) return lowest;
    const double at_axis = last_depth_ - (1.0 - axis_weight()) * free_gap(0) - axis_weight() * free_gap(1);
    return std::min(lowest, at_axis);
}

double Foundation::contact_radius() const {
    // Without force no element carries one: the load-bearing contact is empty (an element that entered at zero
    // force, clamped there, is no contact), as on a [layer]'s cells.
    if (!(total_force_ > 0.0)) return 0.0;
    const double* flags = element_flags();
    std::size_t outer = active_;
    while (outer > 0 && flags[outer - 1] == 0.0) --outer;
    if (outer == 0) return 0.0;
    const std::size_t j = outer - 1;
    if (receded_stress_) {
        // Just after a jump that receded the contact (eq. J2): the stress after the jump, sigma_j + eta dr >= 0 in
        // contact and the would-be one < 0 of its neighbour that left, crosses zero between the two centres.
        const double inside = element_stresses()[j];
        const double outside = std::min(*receded_stress_, 0.0);
        return position(j) + (inside > 0.0 ? inside / (inside - outside) : 0.0) * spacing_;
    }
    if (j + 1 >= size() || !std::isfinite(equivalent_[j + 1])) return position(j) + 0.5 * spacing_;
    // The nearer of the two zeros (docs/theory.md section 3, as the layer's L19c): each meets the edge to second
    // order where its side leaves zero with a slope and lies beyond it where that side does not.
    return position(j) + std::min(gap_edge(j), stress_edge(j)) * spacing_;
}

double Foundation::gap_edge(std::size_t j) const {
    const double* flags = element_flags();
    const double g_in = equivalent_[j], g_out = equivalent_[j + 1];
    const double outside = std::min(free_gap(j + 1), 0.0);
    // The free gap d - g - w vanishes at the edge and is linear in g beyond it (exactly d - g where the surface
    // was never touched; (d' - w')(t - t_exit) where it left contact, d' - w' != 0 there without a parallel
    // dashpot; with one it opens quadratically, and its zero lies beyond the edge: stress_edge): extrapolated in g
    // from the two free neighbours, the edge is where it reaches zero, and x is interpolated linearly in g between
    // the centres.
    if (j + 2 < size() && std::isfinite(equivalent_[j + 2]) && flags[j + 2] == 0.0 && g_out > g_in) {
        const double further = free_gap(j + 2);
        const double rise = equivalent_[j + 2] - g_out;
        if (further < outside && rise > 0.0) {
            const double edge = g_out + outside * rise / (outside - further);
            return std::clamp((edge - g_in) / (g_out - g_in), 0.0, 1.0);
        }
    }
    // Otherwise (a free element between two in contact, a flat profile) between the two centres, where the
    // displacement the element could still give up (inside) and the free gap (outside) cross zero.
    const double inside = element_stresses()[j] / contact_stiffness_;
    const double fraction = inside > 0.0 ? inside / (inside - outside) : 0.0;
    return std::clamp(fraction, 0.0, 1.0);
}

double Foundation::stress_edge(std::size_t j) const {
    // With a parallel dashpot an element leaves where its stress reaches zero with its rate continuous, so the
    // stresses inside a receding edge fall to zero with a slope, linearly in g (G (D - g) on a Kelvin-Voigt body):
    // extrapolated in g from the two outermost elements in contact, where they fall towards the edge. At a growing
    // edge the stress jumps by eta times the rate (the zero lies beyond the gap's), except on an element that entered
    // in the last step with its own rate (RateAtEntry::breaks: its stress grows from zero), which is not taken. 1 (no
    // bound) without a dashpot, with fewer than two elements in contact at the edge, after an entry at j, or where the
    // zero lies beyond the neighbour.
    const auto entered = [&](const Entry& entry) { return entry.element == j; };
    if (!(material_.viscosity() > 0.0) || j == 0 || element_flags()[j - 1] == 0.0 ||
        std::any_of(entries_.begin(), entries_.end(), entered)) {
        return 1.0;
    }
    const double g_before = equivalent_[j - 1], g_in = equivalent_[j], g_out = equivalent_[j + 1];
    const double before = element_stresses()[j - 1], inside = element_stresses()[j];
    if (!(before > inside && inside >= 0.0 && g_in > g_before && g_out > g_in)) return 1.0;
    const double edge = g_in + (g_in - g_before) * inside / (before - inside);
    return std::min((edge - g_in) / (g_out - g_in), 1.0);
}

void Foundation::save_state(std::span<double> out) const {
    const std::size_t n = size();
    const std::size_t branches = material_.terms().size();
    out[0] = last_depth_;
    out[1] = total_force_;
    out[2] = static_cast<double>(active_);
    // Local restrict pointers: the loops vectorise (the out span could otherwise alias the buffers).
    double* __restrict w = out.data() + 3;
    double* __restrict sigma = w + n;
    double* __restrict flag = sigma + n;
    double* __restrict h = flag + n;
    const double* __restrict displacement = element_displacements();
    const double* __restrict stress = element_stresses();
    const double* __restrict contact = element_flags();
    const double* __restrict memory = element_memories();
    const std::size_t active = active_;
    for (std::size_t i = 0; i < active; ++i) {
        w[i] = displacement[i];
        sigma[i] = stress[i];
        flag[i] = contact[i];
    }
    for (std::size_t k = 0; k < branches; ++k) {
        for (std::size_t i = 0; i < active; ++i) h[k * n + i] = memory[k * n + i];
    }
}

void Foundation::load_state(std::span<const double> in) {
    const std::size_t n = size();
    const std::size_t branches = material_.terms().size();
    attached_ = nullptr;
    receded_stress_.reset();
    last_depth_ = in[0];
    total_force_ = in[1];
    const std::size_t active = static_cast<std::size_t>(in[2]);
    clear_beyond(active);
    const double* __restrict w = in.data() + 3;
    const double* __restrict sigma = w + n;
    const double* __restrict flag = sigma + n;
    const double* __restrict h = flag + n;
    double* __restrict displacement = displacement_.data();
    double* __restrict stress = stress_.data();
    double* __restrict contact = flags_.data();
    double* __restrict memory = memory_.data();
    for (std::size_t i = 0; i < active; ++i) {
        displacement[i] = w[i];
        stress[i] = sigma[i];
        contact[i] = flag[i] != 0.0 ? 1.0 : 0.0;
    }
    for (std::size_t k = 0; k < branches; ++k) {
        for (std::size_t i = 0; i < active; ++i) memory[k * n + i] = h[k * n + i];
    }
    active_ = active;
    high_water_ = std::max(high_water_, active_);
}

void Foundation::attach(std::span<double> state) {
    attached_ = nullptr;
    receded_stress_.reset();
    last_depth_ = state[0];
    total_force_ = state[1];
    const std::size_t active = static_cast<std::size_t>(state[2]);
    clear_beyond(active);
    active_ = active;
    high_water_ = std::max(high_water_, active_);
    attached_ = state.data();
}

void Foundation::derive_stresses(double rate) {
    const std::size_t n = size();
    const auto& terms = material_.terms();
    const double dashpot = material_.viscosity() * rate;
    const double g_inf = material_.equilibrium_modulus();
    const double* __restrict w = element_displacements();
    const double* __restrict flags = element_flags();
    double* __restrict sigma = stress_.data();
    for (std::size_t i = 0; i < active_; ++i) sigma[i] = g_inf * w[i] + dashpot;
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double modulus = terms[k].modulus;
        const double* __restrict h = element_memories() + k * n;
        for (std::size_t i = 0; i < active_; ++i) sigma[i] += modulus * h[i];
    }
    for (std::size_t i = 0; i < active_; ++i) sigma[i] = flags[i] != 0.0 ? sigma[i] : 0.0;
}

void Foundation::clear_beyond(std::size_t active) {
    const std::size_t n = size();
    const std::size_t branches = material_.terms().size();
    // Beyond the loaded state's touched elements every buffer must hold zeros (advance() relies on it): clear what
    // an earlier state left there, buffer by buffer (each fill one vectorised store run).
    if (active < high_water_) {
        const auto clear = [&](auto& buffer, std::size_t offset) {
            std::fill(buffer.begin() + static_cast<std::ptrdiff_t>(offset + active),
                      buffer.begin() + static_cast<std::ptrdiff_t>(offset + high_water_),
                      typename std::decay_t<decltype(buffer)>::value_type{});
        };
        for (auto* buffer : {&displacement_, &stress_, &start_displacement_, &start_stress_, &increment_, &relaxed_,
                             &event_, &flags_}) {
            clear(*buffer, 0);
        }
        if (!free_relaxed_.empty()) clear(free_relaxed_, 0);
        for (std::size_t k = 0; k < branches; ++k) clear(memory_, k * n);
    }
}

void Foundation::reserve_events() {
    split_.reserve(size());
    entries_.reserve(size());
    split_state_.reserve(size() * (material_.terms().size() + 2));
}

void Foundation::line_loads(std::span<double> out) const {
    const double* sigma = element_stresses();  // a local pointer: the loop vectorises
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = normal_stiffness_factor * sigma[i];
}

std::vector<double> Foundation::line_loads() const {
    std::vector<double> q(size());
    for (std::size_t i = 0; i < size(); ++i) q[i] = normal_stiffness_factor * element_stresses()[i];
    return q;
}

}  // namespace mdr::foundation
