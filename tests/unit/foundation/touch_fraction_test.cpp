// Foundation::touch_fraction: where inside a step a depth going linearly from d0 to d1 first reaches a surface out of
// contact (eq. 14). On a surface never touched the surface is g(x_i) itself, so the fraction is (g_0 - d0)/(d1 - d0)
// for the innermost element exactly; 1 where the depth does not reach it.

#include <gtest/gtest.h>

#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {
namespace {

constexpr double R = 1e-3, spacing = 1e-6, time_step = 1e-3;

TEST(FoundationTouchFraction, AnUntouchedSurfaceIsReachedWhereTheDepthCrossesTheInnermostProfileHeight) {
    const auto sphere = profile::make_sphere(R);
    const auto material = rheology::Rheology::kelvin_voigt(1e6, 1e3);
    Foundation foundation(material, *sphere, spacing, 100);
    foundation.begin_step(step_coefficients(material, time_step));
    const double g0 = sphere->equivalent(0.5 * spacing);  // x_0^2 / R
    const double d0 = -3e-9, d1 = 1e-9;
    EXPECT_NEAR(foundation.touch_fraction(d0, d1), (g0 - d0) / (d1 - d0), 1e-12);
    EXPECT_EQ(foundation.touch_fraction(d0, 0.5 * g0), 1.0);  // not reached
    EXPECT_EQ(foundation.contact_count(), 0u);  // the state is not changed
    foundation.advance(d0, d1);  // the step the fraction described: the innermost elements enter
    ASSERT_GT(foundation.contact_count(), 0u);
    EXPECT_EQ(foundation.entries().front().element, 0u);
    EXPECT_NEAR(foundation.entries().front().fraction, (g0 - d0) / (d1 - d0), 1e-12);
}

TEST(FoundationTouchFraction, ElementsInContactDoNotCount) {
    const auto punch = profile::make_flat_punch(100 * spacing);
    const auto material = rheology::Rheology::kelvin_voigt(1e6, 1e3);
    Foundation foundation(material, *punch, spacing, 100);
    const auto coefficients = step_coefficients(material, time_step);
    foundation.begin_step(coefficients);
    foundation.advance(0.0, 1e-9);
    ASSERT_EQ(foundation.contact_count(), 100u);
    foundation.begin_step(coefficients);
    EXPECT_EQ(foundation.touch_fraction(1e-9, 2e-9), 1.0);  // all in contact: nothing left to touch
}

}  // namespace
}  // namespace mdr::foundation
