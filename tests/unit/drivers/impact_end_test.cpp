// impact_outcome, the one rule for the end of an impact's contact on the half-space and on a layer (eq. 39): its
// numbers against the formulas worked by hand, and the restitution outside [0, 1] refused as unresolved numerics.

#include <gtest/gtest.h>

#include <stdexcept>

#include "drivers/impact_end.hpp"

namespace mdr::drivers {
namespace {

// 10 g arriving at 0.5 m/s; the step of 10 us began at 1 ms moving out at 0.3 m/s under 2 N and lost the contact a
// quarter in: v(T) = -0.3 - 2 * 0.25 * 1e-5 / (2 * 0.01) = -0.30025 m/s.
ImpactEnd quarter_in(double velocity) {
    return {.mass = 0.01, .approach = 0.5, .time = 1e-3, .time_step = 1e-5, .velocity = velocity, .force = 2.0,
            .fraction = 0.25};
}

TEST(ImpactOutcome, IsTheLinearDecayOfTheForceToTheLoss) {
    const ImpactOutcome outcome = impact_outcome(quarter_in(-0.3));
    EXPECT_NEAR(outcome.contact_time, 1.0025e-3, 1e-18);
    EXPECT_NEAR(outcome.rebound_velocity, 0.30025, 1e-15);
    EXPECT_NEAR(outcome.restitution, 0.6005, 1e-15);
    EXPECT_NEAR(outcome.dissipated_energy, 0.5 * 0.01 * (0.25 - 0.30025 * 0.30025), 1e-18);
    EXPECT_FALSE(outcome.oblique);
}

TEST(ImpactOutcome, RefusesARestitutionOutsideZeroToOne) {
    EXPECT_THROW(impact_outcome(quarter_in(-0.6)), std::runtime_error);  // e = 1.2005: more energy than given
    EXPECT_THROW(impact_outcome(quarter_in(0.1)), std::runtime_error);   // e = -0.199: still moving in
    // e = 1 to round-off (1e-6) passes.
    const ImpactEnd elastic{.mass = 0.01, .approach = 0.5, .time = 0.0, .time_step = 1e-5, .velocity = -0.5000002,
                            .force = 0.0, .fraction = 0.5};
    EXPECT_NEAR(impact_outcome(elastic).restitution, 1.0000004, 1e-12);
}

}  // namespace
}  // namespace mdr::drivers
