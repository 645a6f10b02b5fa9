#pragma once
// Two contacts' doubles in the lanes of one vector register (ContactLaw::advance_spatial_pair), and the operations
// the composed steps' formulas (composed_held_steps.hpp) need beyond arithmetic, for a double and for lanes alike:
// IEEE operations lane by lane, so each lane's result is the double's, to the bit.

#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mdr::foundation {

/// Two doubles, the first contact's in lane 0, the second's in lane 1 (GCC's and Clang's vector extensions: SSE2's
/// registers on x86-64); arithmetic acts lane by lane.
typedef double Lanes __attribute__((vector_size(2 * sizeof(double))));

/// The square root (IEEE: correctly rounded).
[[gnu::always_inline]] inline double square_root(double value) { return std::sqrt(value); }

[[gnu::always_inline]] inline Lanes square_root(Lanes value) {
#if defined(__SSE2__)
    return reinterpret_cast<Lanes>(_mm_sqrt_pd(reinterpret_cast<__m128d>(value)));
#else
    return Lanes{std::sqrt(value[0]), std::sqrt(value[1])};
#endif
}

/// `if_not_negative` where `value` >= 0, else `otherwise` (lane by lane).
[[gnu::always_inline]] inline double by_sign(double value, double if_not_negative, double otherwise) {
    return value >= 0.0 ? if_not_negative : otherwise;
}

[[gnu::always_inline]] inline Lanes by_sign(Lanes value, Lanes if_not_negative, Lanes otherwise) {
    return Lanes{value[0] >= 0.0 ? if_not_negative[0] : otherwise[0],
                 value[1] >= 0.0 ? if_not_negative[1] : otherwise[1]};
}

}  // namespace mdr::foundation
