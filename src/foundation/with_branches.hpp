#pragma once
// The branch count as a compile-time constant for the element passes of the composed normal step and the planar
// tangential layer.

#include <cstddef>
#include <type_traits>

namespace mdr::foundation {

/// Calls `kernel` with the branch count as a constant for M = 1, 2, 3 (its loops over the branches unrolled, the
/// loop over the elements vectorised), else as a number.
template <class Kernel>
inline __attribute__((always_inline)) auto with_branches(std::size_t branches, Kernel kernel) {
    if (branches == 1) return kernel(std::integral_constant<std::size_t, 1>{});
    switch (branches) {
        case 2: return kernel(std::integral_constant<std::size_t, 2>{});
        case 3: return kernel(std::integral_constant<std::size_t, 3>{});
        default: return kernel(branches);
    }
}

}  // namespace mdr::foundation
