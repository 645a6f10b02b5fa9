#include "mdr/foundation/composed_tangential_step.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "composed_held_steps.hpp"
#include "with_branches.hpp"

namespace mdr::foundation {

using namespace composed_tangential;  // the header's entries and constants

namespace {

// Whether every element i < count in contact (flag 1) sticks at the end of the step: its stress t_i = common +
// G_inf u^_i + sum_k weight_k h^_k,i lies inside the friction circle of radius per_load max(q_i, 0) (eq. 50, the
// test of PlanarTangentialLayer's element pass). Read only; an integer count, so that it vectorises.
__attribute__((target_clones("avx2", "default"))) bool all_stick(
    std::size_t count, std::size_t branches, std::size_t stride, double common_x, double common_y, double g_inf,
    double per_load, const double* __restrict weight, const double* __restrict flags, const double* __restrict q,
    const double* __restrict u, const double* __restrict h) {
    return with_branches(branches, [&](auto m) {
        const double* __restrict contact = flags;  // local restrict pointers, as in ComposedNormalStep's passes
        const double* __restrict loads = q;
        const double* __restrict displacement = u;
        const double* __restrict memory = h;
        std::int64_t slips = 0;
        for (std::size_t i = 0; i < count; ++i) {
            double x = common_x + g_inf * displacement[i], y = common_y + g_inf * displacement[stride + i];
            for (std::size_t k = 0; k < m; ++k) {
                x += weight[k] * memory[2 * k * stride + i];
                y += weight[k] * memory[(2 * k + 1) * stride + i];
            }
            const double bound = per_load * std::max(loads[i], 0.0);
            const bool sticks = std::sqrt(x * x + y * y) <= bound;
            slips += contact[i] != 0.0 && !sticks ? 1 : 0;
        }
        return slips == 0;
    });
}

}  // namespace

ComposedTangentialStep::ComposedTangentialStep(const rheology::Rheology& material, double friction, double spacing)
    : branches_(material.terms().size()),
      g_inf_(material.equilibrium_modulus()),
      per_load_(friction / tangential_stiffness_factor),
      spacing_(spacing),
      weight_(branches_, 0.0),
      free_increment_(branches_ + 1, 0.0),
      scratch_(branches_ + (branches_ + 1) * (branches_ + 1) + 2 * branches_ + 2, 0.0) {
    for (const auto& term : material.terms()) moduli_.push_back(term.modulus);
}

std::size_t ComposedTangentialStep::map_offset() const { return composed_tangential::map_offset(branches_); }

std::size_t ComposedTangentialStep::header_size(std::size_t branches) {
    return branches * branches + 8 * branches + 10;
}

void ComposedTangentialStep::set_step(const StepCoefficients& coefficients) {
    copy_step_coefficients(coefficients, coefficients_);
    // A free element's du = (0 - relaxed) / k with relaxed = G_inf u + sum_k G_k E_k h_k (the layer's element pass
    // out of contact: its stress is zero).
    const double compliance = 1.0 / coefficients.stiffness;
    free_increment_[0] = -g_inf_ * compliance;
    for (std::size_t k = 0; k < branches_; ++k) {
        weight_[k] = moduli_[k] * coefficients.decay[k];
        free_increment_[k + 1] = -weight_[k] * compliance;
    }
}

bool ComposedTangentialStep::prepare(std::span<const double> header, PlanarVector increment, double least_load,
                                     Step& step) const {
    return with_branches(branches_, [&](auto m) { return prepare_with(header, increment, least_load, step, m); });
}

bool ComposedTangentialStep::sticks(const PlanarElements& elements, const Step& step, const double* loads) const {
    return all_stick(elements.touched, branches_, elements.stride, step.common[0], step.common[1], g_inf_, per_load_,
                     scratch_.data(), elements.flags, loads, elements.u, elements.h);
}

PlanarVector ComposedTangentialStep::force(std::span<const double> header, const Step& step) const {
    return with_branches(branches_, [&](auto m) { return force_with(header, step, m); });
}

void ComposedTangentialStep::advance(std::span<double> header, const PlanarElements& elements,
                                     const Step& step) const {
    with_branches(branches_, [&](auto m) { advance_with(header, elements, step, m); });
}

bool ComposedTangentialStep::advance_if_certain(std::span<double> header, const PlanarElements& elements,
                                                PlanarVector increment, double least_load, Step& step) const {
    return with_branches(branches_, [&](auto m) {
        if (!prepare_with(header, increment, least_load, step, m)) return false;
        advance_with(header, elements, step, m);
        return true;
    });
}

void ComposedTangentialStep::element(std::span<const double> header, const double* u, const double* h,
                                     const double* flags, std::size_t stride, std::size_t i, double* current) const {
    const std::size_t m = branches_, order = m + 1;
    // Component c's j-th written value: u^ for j = 0, else h^_(j-1).
    const auto written = [&](std::size_t c, std::size_t j) {
        return j == 0 ? u[c * stride + i] : h[(2 * (j - 1) + c) * stride + i];
    };
    if (header[composed_offset] == 0.0) {
        for (std::size_t c = 0; c < 2; ++c) {
            for (std::size_t j = 0; j < order; ++j) current[j == 0 ? c : 2 * j + c] = written(c, j);
        }
        return;
    }
    const double* scale = header.data() + scale_offset;
    const double* shift = scale + m;
    const double* map = header.data() + map_offset();
    for (std::size_t c = 0; c < 2; ++c) {
        if (flags[i] != 0.0) {
            current[c] = written(c, 0) + header[shift_offset + c];
            for (std::size_t k = 0; k < m; ++k) {
                current[2 * (k + 1) + c] = scale[k] * written(c, k + 1) + shift[c * m + k];
            }
            continue;
        }
        for (std::size_t r = 0; r < order; ++r) {
            double value = 0.0;
            for (std::size_t j = 0; j < order; ++j) value += map[r * order + j] * written(c, j);
            current[r == 0 ? c : 2 * r + c] = value;
        }
    }
}

bool ComposedTangentialStep::write(std::span<double> header, const PlanarElements& elements) const {
    if (header[composed_offset] == 0.0) return false;
    const std::size_t m = branches_;
    double* current = scratch_.data() + m + (m + 1) * (m + 1);  // one element's values (each reads its own only)
    const std::size_t n = elements.stride;
    for (std::size_t i = 0; i < elements.touched; ++i) {
        element(header, elements.u, elements.h, elements.flags, n, i, current);
        elements.u[i] = current[0];
        elements.u[n + i] = current[1];
        for (std::size_t k = 0; k < m; ++k) {
            elements.h[2 * k * n + i] = current[2 * (k + 1)];
            elements.h[(2 * k + 1) * n + i] = current[2 * (k + 1) + 1];
        }
    }
    header[composed_offset] = 0.0;
    return true;
}

void ComposedTangentialStep::summarise(std::span<double> header, const PlanarElements& elements,
                                       PlanarVector force) const {
    const std::size_t m = branches_, order = m + 1, n = elements.stride;
    double* scale = header.data() + scale_offset;
    double* shift = scale + m;
    double* hat_sum = scale + 3 * m;
    double* hat_largest = scale + 5 * m;
    double* map = header.data() + map_offset();
    double contacts = 0.0, sum_x = 0.0, sum_y = 0.0, largest = 0.0;
    std::fill(hat_sum, hat_sum + 3 * m, 0.0);
    for (std::size_t i = 0; i < elements.touched; ++i) {
        if (elements.flags[i] == 0.0) continue;
        const double x = elements.u[i], y = elements.u[n + i];
        contacts += 1.0;
        sum_x += x;
        sum_y += y;
        largest = std::max(largest, std::sqrt(x * x + y * y));
        for (std::size_t k = 0; k < m; ++k) {
            const double h_x = elements.h[2 * k * n + i], h_y = elements.h[(2 * k + 1) * n + i];
            hat_sum[k] += h_x;
            hat_sum[m + k] += h_y;
            hat_largest[k] = std::max(hat_largest[k], std::sqrt(h_x * h_x + h_y * h_y));
        }
    }
    header[composed_offset] = 1.0;
    header[force_offset] = force[0];
    header[force_offset + 1] = force[1];
    header[contacts_offset] = contacts;
    header[shift_offset] = header[shift_offset + 1] = 0.0;
    header[hat_sum_offset] = sum_x;
    header[hat_sum_offset + 1] = sum_y;
    header[hat_largest_offset] = largest;
    std::fill(scale, scale + m, 1.0);
    std::fill(shift, shift + 2 * m, 0.0);
    for (std::size_t r = 0; r < order; ++r) {
        for (std::size_t j = 0; j < order; ++j) map[r * order + j] = r == j ? 1.0 : 0.0;
    }
}

std::size_t ComposedTangentialStep::summary_mismatch(std::span<const double> header,
                                                     const PlanarElements& elements) const {
    std::vector<double> derived(header.begin(), header.end());
    summarise(derived, elements, {header[force_offset], header[force_offset + 1]});
    const std::size_t m = branches_;
    // The summary's entries: the count in contact, the sums and the largest |u^|, the sums and largest |h^_k|.
    const std::size_t ranges[3][2] = {{contacts_offset, contacts_offset + 1},
                                      {hat_sum_offset, hat_largest_offset + 1},
                                      {scale_offset + 3 * m, scale_offset + 6 * m}};
    for (const auto& range : ranges) {
        for (std::size_t i = range[0]; i < range[1]; ++i) {
            if (derived[i] != header[i]) return i;
        }
    }
    return header.size();
}

}  // namespace mdr::foundation
