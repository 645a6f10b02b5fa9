// Foundation::begin_step's RateAtEntry: an element entering contact inside a step with a parallel dashpot. Where the
// indenter's rate is continuous (a prescribed depth) the entering element follows it at once, so the force steps by
// its dashpot's, 8 dx eta s (s the step's secant rate, both halves): exact for the element. Where the rate breaks (a
// massless indenter under a force: the depth is solved from a balance) the force must not step, or the balance has no
// root (a row missed it by up to that step): the entering element's dashpot takes its own rate over the step (the
// trapezoidal with a start rate, else the secant), which at an entry at the step's very end is the free element's, so
// the trial force is continuous in the end depth. Checked at the exact entry depth of an untouched element (g(x_j))
// and of one that left contact and creeps back (its free surface at the step's end); and Foundation::contact_rate,
// the mean rate of the dashpots in contact.

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
        foundation.begin_step(coefficients, std::nullopt, RateAtEntry::continuous);
        EXPECT_NEAR(force_step(foundation, depth, g_entering), dashpot_step, 1e-4 * dashpot_step);
        foundation.begin_step(coefficients, std::nullopt, RateAtEntry::breaks);
        EXPECT_LT(std::abs(force_step(foundation, depth, g_entering)), 1e-4 * dashpot_step);
        foundation.begin_step(coefficients, 1.5 * (g_entering - depth) / time_step, RateAtEntry::breaks);
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
        foundation.begin_step(coefficients, rate, RateAtEntry::breaks);
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
        foundation.begin_step(coefficients, rate, RateAtEntry::continuous);
        EXPECT_GT(force_step(foundation, withdrawn, entry), dashpot_step);  // 8 dx eta (s - w'), w' < 0
    }
}

TEST(FoundationEntryDashpot, ContactRateIsTheMeanOfTheRatesTheDashpotsInContactSaw) {
    // Elements 0..29 in contact at rate0; the step's trapezoidal end rate r1 = 2 s - rate0 for them, and for each
    // element j that enters at fraction f_j its own 2 (w1 - w0)/dt = 2 (1 - f_j) s (never touched: w0 = 0 at rest,
    // and d1 - g_j = (1 - f_j)(d1 - d0)).
    const auto sphere = profile::make_sphere(R);
    const auto material = rheology::Rheology::kelvin_voigt(1e6, eta);
    Foundation foundation(material, *sphere, spacing, 200);
    const auto coefficients = step_coefficients(material, time_step);
    const double depth = sphere->equivalent(29.7 * spacing), deeper = sphere->equivalent(36.2 * spacing);
    foundation.begin_step(coefficients);
    foundation.advance(0.0, depth);
    ASSERT_EQ(foundation.contact_count(), 30u);
    const double rate0 = 0.3 * (deeper - depth) / time_step, secant = (deeper - depth) / time_step;
    for (const RateAtEntry rate_at_entry : {RateAtEntry::continuous, RateAtEntry::breaks}) {
        Foundation stepped = foundation;
        stepped.begin_step(coefficients, rate0, rate_at_entry);
        stepped.advance(depth, deeper);
        ASSERT_EQ(stepped.entries().size(), 6u);
        const double end_rate = 2.0 * secant - rate0;
        double sum = 30.0 * end_rate;
        for (const Entry& entry : stepped.entries()) {
            sum += rate_at_entry == RateAtEntry::breaks ? 2.0 * (1.0 - entry.fraction) * secant : end_rate;
        }
        EXPECT_NEAR(stepped.contact_rate(), sum / 36.0, 1e-12 * secant);
    }
}

}  // namespace
}  // namespace mdr::foundation
