#pragma once
// The sum every element step starts from, shared by the normal foundation and the tangential layer.

#include <cstddef>

#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {

/// relaxed_i = G_inf w_i + sum_k G_k E_k h_{k,i} for i < count: the element's stress at the end of a step with no
/// increment (memory branch-major, h_{k,i} = memory[k * stride + i]). Inline so that callers compiled for several
/// instruction sets vectorise it with their own.
inline void relaxed_sums(const rheology::Rheology& material, const StepCoefficients& step,
                         const double* __restrict w, const double* __restrict memory, std::size_t stride,
                         std::size_t count, double* __restrict relaxed) {
    const double g_inf = material.equilibrium_modulus();
    for (std::size_t i = 0; i < count; ++i) relaxed[i] = g_inf * w[i];
    const auto& terms = material.terms();
    for (std::size_t k = 0; k < terms.size(); ++k) {
        const double weight = terms[k].modulus * step.decay[k];
        const double* __restrict h = memory + k * stride;
        for (std::size_t i = 0; i < count; ++i) relaxed[i] += weight * h[i];
    }
}

}  // namespace mdr::foundation
