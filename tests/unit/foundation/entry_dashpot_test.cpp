// Foundation::begin_step's depth source and an element entering contact inside a step with a parallel dashpot.
// Under a prescribed depth the entering element follows the indenter's rate at once, so the force steps by its
// dashpot's, 8 dx eta s (s the step's secant rate, both halves): exact for the element. Where the depth is solved
// from a balance the force must not step, or the balance has no root (a row missed it by up to that step): the
// entering element's dashpot takes its own rate over the step, which at an entry at the step's very end is the free
// element's, so the trial force is continuous in the end depth. Checked at the exact entry depth of an untouched
// element (g(x_j)) and of one that left contact and creeps back (its free surface at the step's end).

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {
namespace {

constexpr double R = 1e-3, spacing = 1e-6, time_step = 1e-3, eta = 1e3;

// The step in the trial force across `entry` (the end depth at which an element enters at the step's very end),
// over the relative distance `width` either side.
double force_step(const Foundation& foundation, double depth_start, double entry, double width = 1e-10) {
    return foundation.trial_force(depth_start, entry * (1.0 + width)) -
           foundation.trial_force(depth_start, entry * (1.0 - width));
}

TEST(FoundationEntryDashpot, TheForceStepsByTheDashpotUnderAPrescribedDepthAndNotWhereItIsSolved) {
    const auto sphere = profile::make_sphere(R);
    for (const auto& material : {rheology::Rheology::kelvin_voigt(1e6, eta),
                                 rheology::Rheology(1e6, eta, {{2e6, 1e-2}})}) {
        Foundation foundation(material, *sphere, spacing, 200);
        const auto coefficients = step_coefficients(material, time_step);
        const double entering = 30;  // the element that enters next: elements 0..29 are in contact
        const double g_entering = sphere->equivalent((entering + 0.5) * spacing);
        const double depth = 0.5 * (sphere->equivalent((entering - 0.5) * spacing) + g_entering);
        foundation.begin_step(coefficients);
        foundation.advance(0.0, depth);
        ASSERT_EQ(foundation.contact_count(), 30u);
        const double dashpot_step = 2.0 * 4.0 * spacing * eta * (g_entering - depth) / time_step;
        foundation.begin_step(coefficients, std::nullopt, DepthSource::prescribed);
        EXPECT_NEAR(force_step(foundation, depth, g_entering), dashpot_step, 1e-4 * dashpot_step);
        foundation.begin_step(coefficients, std::nullopt, DepthSource::solved);
        EXPECT_LT(std::abs(force_step(foundation, depth, g_entering)), 1e-4 * dashpot_step);
        foundation.begin_step(coefficients, 1.5 * (g_entering - depth) / time_step, DepthSource::solved);
        EXPECT_LT(std::abs(force_step(foundation, depth, g_entering)), 1e-4 * dashpot_step);  // trapezoidal
    }
}

TEST(FoundationEntryDashpot, AnElementCreepingBackEntersWithoutAForceStepWhereTheDepthIsSolved) {
    // A standard solid with a parallel dashpot: pressed, then withdrawn so that the outer elements leave contact
    // and creep back (w > 0, w' < 0); the depth then rises again to one of them.
    const auto sphere = profile::make_sphere(R);
    const rheology::Rheology material(1e6, eta, {{2e6, 1e-2}});
    Foundation foundation(material, *sphere, spacing, 200);
    const auto coefficients = step_coefficients(material, time_step);
    const double pressed = sphere->equivalent(40.0 * spacing), withdrawn = 0.8 * pressed;
    foundation.begin_step(coefficients);
    foundation.advance(0.0, pressed);
    foundation.begin_step(coefficients);
    foundation.advance(pressed, withdrawn);
    for (const std::optional<double> rate : {std::optional<double>(), std::optional<double>(1e-7)}) {
        foundation.begin_step(coefficients, rate, DepthSource::solved);
        // Where the free elements' surfaces g + w are at the step's end: a step lifted off the body, on a copy (a
        // free element's step does not depend on the depth). The one that enters next above the withdrawn depth:
        Foundation lifted = foundation;
        lifted.advance(withdrawn, 0.0);
        double entry = 2.0 * pressed;
        std::size_t entering = foundation.size();
        for (std::size_t i = 0; i < foundation.touched(); ++i) {
            const double surface = sphere->equivalent(foundation.position(i)) + lifted.displacements()[i];
            if (foundation.contact_flags()[i] == 0.0 && surface > withdrawn && surface < entry) {
                entry = surface;
                entering = i;
            }
        }
        ASSERT_LT(entering, foundation.size());
        ASSERT_GT(foundation.displacements()[entering], 0.0);  // it has left contact and creeps back
        const double dashpot_step = 2.0 * 4.0 * spacing * eta * (entry - withdrawn) / time_step;
        EXPECT_LT(std::abs(force_step(foundation, withdrawn, entry)), 1e-4 * dashpot_step);
        foundation.begin_step(coefficients, rate, DepthSource::prescribed);
        EXPECT_GT(force_step(foundation, withdrawn, entry), dashpot_step);  // 8 dx eta (s - w'), w' < 0
    }
}

}  // namespace
}  // namespace mdr::foundation
