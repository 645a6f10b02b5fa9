// The foundation keeps its own copy of the material: one built from a temporary Rheology gives the closed-form
// flat-punch force of a depth ramp (Lee-Radok), F(t) = 8 a v [G_inf t + G1 tau1 (1 - exp(-t/tau1))].

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {
namespace {

TEST(FoundationOwnership, AFoundationBuiltFromATemporaryMaterialStaysRight) {
    constexpr double radius = 1e-3, rate = 1e-4, G_inf = 1e6, G1 = 3e6, tau1 = 0.1, time_step = 1e-2;
    const auto punch = profile::make_flat_punch(radius);
    Foundation foundation(rheology::Rheology::standard(G_inf, G1, tau1), *punch, radius / 50.0, 50);
    const auto coefficients = step_coefficients(rheology::Rheology::standard(G_inf, G1, tau1), time_step);
    for (int n = 1; n <= 30; ++n) {
        foundation.begin_step(coefficients);
        foundation.advance(rate * (n - 1) * time_step, rate * n * time_step);
        const double t = n * time_step;
        const double expected = 8.0 * radius * rate * (G_inf * t + G1 * tau1 * (1.0 - std::exp(-t / tau1)));
        EXPECT_NEAR(foundation.total_force(), expected, 1e-9 * expected) << "t = " << t;
    }
}

}  // namespace
}  // namespace mdr::foundation
