#include "mdr/foundation/composed_normal_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "composed_held_steps.hpp"
#include "with_branches.hpp"

namespace mdr::foundation {

using namespace composed_normal;  // the header's entries and constants

namespace {

// Whether no element i < count enters or leaves contact over the step: one in contact keeps a compressive end
// stress, common - G_inf g_i + sum_k weight_k h^_k,i >= 0 (eq. 20), a free one stays clear of the indenter,
// g_i + row_0 w^_i + sum_k row_(k+1) h^_k,i >= depth (eq. 14). Read only; an integer count, so that it vectorises
// (GCC leaves a floating-point min reduction scalar).
__attribute__((target_clones("avx2", "default"))) bool no_event_pass(
    std::size_t count, std::size_t branches, const double* __restrict w, const double* __restrict flags,
    const double* __restrict h, std::size_t stride, double g_inf, double common, double depth,
    const double* __restrict g, const double* __restrict weight, const double* __restrict row) {
    return with_branches(branches, [&](auto m) {
        const double* __restrict profile = g;  // local restrict pointers, as in stress_pass
        const double* __restrict displacement = w;
        const double* __restrict contact_flags = flags;
        const double* __restrict memory = h;
        std::int64_t events = 0;
        for (std::size_t i = 0; i < count; ++i) {
            double contact = common - g_inf * profile[i];
            double free = profile[i] - depth + row[0] * displacement[i];
            for (std::size_t k = 0; k < m; ++k) {
                contact += weight[k] * memory[k * stride + i];
                free += row[k + 1] * memory[k * stride + i];
            }
            events += (contact_flags[i] != 0.0 ? contact : free) >= 0.0 ? 0 : 1;
        }
        return events == 0;
    });
}

// Line loads 4 sigma_i (eq. 16, 22) of elements i < count at the end of a step advance took: in contact G_inf (d - g_i)
// + eta rate + sum_k G_k (A_k h^_k + C_k) (eq. 13: w_i = d - g_i whether the header composes the element or write has
// just written it at d, A_k = 1 and C_k = 0 then; the written w_i is not read), 0 out of contact.
__attribute__((target_clones("avx2", "default"))) void stress_pass(
    std::size_t count, std::size_t branches, double depth, double g_inf, double dashpot, const double* __restrict g,
    const double* __restrict flags, const double* __restrict h, std::size_t stride, const double* __restrict moduli,
    const double* __restrict scale, const double* __restrict shift, double* __restrict out) {
    with_branches(branches, [&](auto m) {
        // Local restrict pointers: the lambda's captures lose the parameters' (and the loop would stay scalar).
        const double* __restrict profile = g;
        const double* __restrict contact = flags;
        const double* __restrict memory = h;
        double* __restrict loads = out;
        for (std::size_t i = 0; i < count; ++i) {
            double stress = g_inf * (depth - profile[i]) + dashpot;
            for (std::size_t k = 0; k < m; ++k) stress += moduli[k] * (scale[k] * memory[k * stride + i] + shift[k]);
            loads[i] = contact[i] != 0.0 ? normal_stiffness_factor * stress : 0.0;
        }
    });
}

}  // namespace

ComposedNormalStep::ComposedNormalStep(const rheology::Rheology& material, std::span<const double> profile,
                                       double spacing, double deepest)
    : branches_(material.terms().size()),
      g_inf_(material.equilibrium_modulus()),
      viscosity_(material.viscosity()),
      spacing_(spacing),
      deepest_(deepest),
      profile_(profile.begin(), profile.end()),
      free_increment_(branches_ + 1, 0.0),
      unit_(2 * branches_ + (branches_ + 1) * (branches_ + 1), 0.0),
      scratch_(branches_ + (branches_ + 1) * (branches_ + 1) + branches_ * profile.size(), 0.0) {
    for (const auto& term : material.terms()) moduli_.push_back(term.modulus);
    std::fill(unit_.begin(), unit_.begin() + static_cast<std::ptrdiff_t>(branches_), 1.0);
    for (std::size_t r = 0; r <= branches_; ++r) unit_[2 * branches_ + r * (branches_ + 1) + r] = 1.0;
}

std::size_t ComposedNormalStep::map_offset() const { return composed_normal::map_offset(branches_); }

std::size_t ComposedNormalStep::header_size(std::size_t branches) { return branches * branches + 8 * branches + 9; }

void ComposedNormalStep::set_step(const StepCoefficients& coefficients) {
    copy_step_coefficients(coefficients, coefficients_);
    // A free element's dw = -(relaxed + [eta > 0] (G_inf w + sum_k G_k h_k)) / K_free with relaxed = G_inf w +
    // sum_k G_k E_k h_k and K_free = G_inf + sum_k G_k B_k + 2 eta / dt (Foundation::begin_step, plain_step).
    const double dashpot = viscosity_ > 0.0 ? 1.0 : 0.0;
    const double free_stiffness = coefficients.stiffness + viscosity_ / coefficients.time_step;
    free_increment_[0] = -g_inf_ * (1.0 + dashpot) / free_stiffness;
    for (std::size_t k = 0; k < branches_; ++k) {
        free_increment_[k + 1] = -moduli_[k] * (coefficients.decay[k] + dashpot) / free_stiffness;
    }
}

bool ComposedNormalStep::trial_force(std::span<const double> header, const AttachedElements& elements,
                                     double depth_start, double depth_end, double& force) const {
    return with_branches(branches_, [&](auto m) {
        Step step;
        if (!prepare_with(header, elements, depth_start, depth_end, step, m)) return false;
        force = sum_force(header, step, m);
        return true;
    });
}

bool ComposedNormalStep::advance(std::span<double> header, const AttachedElements& elements, double depth_start,
                                 double depth_end, double& force, double& least_stress) const {
    return with_branches(branches_, [&](auto m) {
        Step step;
        if (!prepare_with(header, elements, depth_start, depth_end, step, m)) return false;
        force = take_with(header, elements, depth_end, step, m);
        least_stress = step.least_stress;
        return true;
    });
}

bool ComposedNormalStep::no_event(const AttachedElements& elements, double common, double depth,
                                  const double* weight, const double* row) const {
    return no_event_pass(elements.touched, branches_, elements.w, elements.flags, elements.h, elements.stride, g_inf_,
                         common, depth, profile_.data(), weight, row);
}

void ComposedNormalStep::element(std::span<const double> header, const double* w, const double* flags,
                                 const double* h, std::size_t stride, std::size_t i, double depth, double& current_w,
                                 double* current_h) const {
    const std::size_t m = branches_, order = m + 1;
    if (header[composed_offset] == 0.0) {
        current_w = w[i];
        for (std::size_t k = 0; k < m; ++k) current_h[k] = h[k * stride + i];
        return;
    }
    const double* scale = header.data() + scale_offset;
    const double* shift = scale + m;
    const double* map = header.data() + map_offset();
    if (flags[i] != 0.0) {
        current_w = depth - profile_[i];
        for (std::size_t k = 0; k < m; ++k) current_h[k] = scale[k] * h[k * stride + i] + shift[k];
        return;
    }
    const auto written = [&](std::size_t j) { return j == 0 ? w[i] : h[(j - 1) * stride + i]; };
    current_w = 0.0;
    for (std::size_t j = 0; j < order; ++j) current_w += map[j] * written(j);
    for (std::size_t k = 0; k < m; ++k) {
        current_h[k] = 0.0;
        for (std::size_t j = 0; j < order; ++j) current_h[k] += map[(k + 1) * order + j] * written(j);
    }
}

bool ComposedNormalStep::write(std::span<double> header, const AttachedElements& elements, double depth) const {
    if (header[composed_offset] == 0.0) return false;
    {
        const std::size_t m = branches_;
        double* fresh = scratch_.data() + m + (m + 1) * (m + 1);  // each new memory reads all the old ones
        const std::size_t n = elements.touched;
        double current_w = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            element(header, elements.w, elements.flags, elements.h, elements.stride, i, depth, current_w,
                    fresh + i * m);
            elements.w[i] = current_w;
        }
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t k = 0; k < m; ++k) elements.h[k * elements.stride + i] = fresh[i * m + k];
        }
    }
    header[composed_offset] = 0.0;
    return true;
}

void ComposedNormalStep::summarise(std::span<double> header, const AttachedElements& elements, double rate) const {
    const std::size_t m = branches_, order = m + 1;
    constexpr double infinity = std::numeric_limits<double>::infinity();
    double* scale = header.data() + scale_offset;
    double* shift = scale + m;
    double* hat_sum = scale + 2 * m;
    double* hat_floor = scale + 3 * m;
    double* map = header.data() + map_offset();
    double* free_floor = map + order * order;
    double* free_ceiling = free_floor + order;
    double contacts = 0.0, profile_sum = 0.0, outermost = 0.0, innermost_free = infinity;
    std::fill(hat_sum, hat_sum + m, 0.0);
    std::fill(hat_floor, hat_floor + m, infinity);
    std::fill(free_floor, free_floor + order, infinity);
    std::fill(free_ceiling, free_ceiling + order, -infinity);
    for (std::size_t i = 0; i < elements.touched; ++i) {
        const double g = profile_[i];
        if (elements.flags[i] != 0.0) {
            contacts += 1.0;
            profile_sum += g;
            outermost = std::max(outermost, g);
            for (std::size_t k = 0; k < m; ++k) {
                const double h = elements.h[k * elements.stride + i];
                hat_sum[k] += h;
                hat_floor[k] = std::min(hat_floor[k], h);
            }
            continue;
        }
        innermost_free = std::min(innermost_free, g);
        for (std::size_t j = 0; j < order; ++j) {
            const double value = j == 0 ? elements.w[i] : elements.h[(j - 1) * elements.stride + i];
            free_floor[j] = std::min(free_floor[j], value);
            free_ceiling[j] = std::max(free_ceiling[j], value);
        }
    }
    // An extreme over no element is not read (no element in contact, or none free): 0 keeps the header finite.
    const auto finite = [](double* first, double* last) {
        std::transform(first, last, first, [](double value) { return std::isfinite(value) ? value : 0.0; });
    };
    finite(hat_floor, hat_floor + m);
    finite(free_floor, free_ceiling + order);
    header[composed_offset] = 0.0;
    header[rate_offset] = rate;
    header[contacts_offset] = contacts;
    header[profile_sum_offset] = profile_sum;
    header[outermost_offset] = outermost;
    header[innermost_free_offset] = std::isfinite(innermost_free) ? innermost_free : 0.0;
    std::fill(scale, scale + m, 1.0);
    std::fill(shift, shift + m, 0.0);
    for (std::size_t r = 0; r < order; ++r) {
        for (std::size_t j = 0; j < order; ++j) map[r * order + j] = r == j ? 1.0 : 0.0;
    }
}

std::size_t ComposedNormalStep::summary_mismatch(std::span<const double> header,
                                                 const AttachedElements& elements) const {
    std::vector<double> derived(header.begin(), header.end());
    summarise(derived, elements, header[rate_offset]);
    const std::size_t m = branches_, free_floor = map_offset() + (m + 1) * (m + 1);
    // The summary's entries: [2, 6), S_k and the least h^_k, the free elements' least and largest (w^, h^_k).
    const std::size_t ranges[3][2] = {{contacts_offset, scale_offset},
                                      {scale_offset + 2 * m, scale_offset + 4 * m},
                                      {free_floor, free_floor + 2 * (m + 1)}};
    for (const auto& range : ranges) {
        for (std::size_t i = range[0]; i < range[1]; ++i) {
            if (derived[i] != header[i]) return i;
        }
    }
    return header.size();
}

void ComposedNormalStep::line_loads(std::span<const double> header, const AttachedElements& elements, double depth,
                                    std::span<double> out) const {
    const double* scale = header[composed_offset] != 0.0 ? header.data() + scale_offset : unit_.data();
    stress_pass(elements.touched, branches_, depth, g_inf_, viscosity_ * header[rate_offset], profile_.data(),
                elements.flags, elements.h, elements.stride, moduli_.data(), scale, scale + branches_, out.data());
}

}  // namespace mdr::foundation
