// The DEM contact law's composed normal step (foundation::ComposedNormalStep): while no element enters or leaves
// contact it steps a contact through its state's header alone, and its forces are the Foundation's to round-off.

#include "mdr/dem/contact_law.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/planar_tangential_layer.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::dem {
namespace {

constexpr double radius = 0.005, peak_overlap = 4e-5, time_step = 2e-6, pi = 3.141592653589793;
constexpr std::size_t elements = 20;
const double half_width = 1.2 * std::sqrt(radius * peak_overlap);

struct Motion {
    const char* name;
    int steps;
    std::function<double(int)> overlap;
};

// Held after loading, loaded slowly, an impact, a long hold with a ripple (400 relaxation times of the standard
// solid: the composition factors fall below 1e-150 and the elements are written again), partial unloadings.
std::vector<Motion> motions() {
    return {
        {"held", 1100, [](int n) { return peak_overlap * std::sin(0.5 * pi * std::min(n, 100) / 100.0); }},
        {"slow", 1000, [](int n) { return peak_overlap * (0.2 + 0.8 * n / 1000.0); }},
        {"impact", 200, [](int n) { return peak_overlap * std::sin(pi * n / 200.0); }},
        {"long", 40000,
         [](int n) {
             const double ripple = 1.0 + 1e-3 * std::sin(2.0 * pi * n / 500.0);
             return peak_overlap * (n < 100 ? std::sin(0.5 * pi * n / 100.0) : ripple);
         }},
        {"cycles", 1000,
         [](int n) { return peak_overlap * (0.75 + 0.25 * std::cos(2.0 * pi * n / 200.0)) * std::min(1.0, n / 50.0); }},
    };
}

// M = 1 to 4, with and without a parallel dashpot.
std::vector<rheology::Rheology> materials() {
    return {rheology::Rheology::standard(1e6, 1e6, 1e-4), rheology::Rheology(1e6, 20.0, {{1e6, 1e-4}, {5e5, 3e-3}}),
            rheology::Rheology::prony(1e6, {{1e6, 4e-5}, {1e6, 1.3e-3}, {1e6, 4e-2}}),
            rheology::Rheology(5e5, 5.0, {{1e6, 4e-5}, {1e6, 4e-4}, {1e6, 4e-3}, {1e6, 4e-2}})};
}

// The reference: the library's Foundation stepping its own buffers (eq. 13-22), every element every step.
TEST(DemComposedNormalStep, ForcesAreTheFoundationsToRoundOff) {
    for (const auto& material : materials()) {
        for (const auto& motion : motions()) {
            foundation::Foundation reference(material, *profile::make_sphere(radius), half_width / elements, elements);
            const auto coefficients = foundation::step_coefficients(material, time_step);
            ContactLaw law(material, radius, 0.0, elements, half_width, time_step);
            std::vector<double> state(law.state_size());
            law.initialise(state);
            double depth = 0.0, largest = 0.0, deviation = 0.0;
            for (int n = 1; n <= motion.steps; ++n) {
                const double overlap = motion.overlap(n);
                reference.begin_step(coefficients);
                reference.advance(depth, overlap);
                depth = overlap;
                law.advance(state, overlap, {0.0, 0.0});
                largest = std::max(largest, std::abs(reference.total_force()));
                deviation = std::max(deviation, std::abs(law.normal_force() - reference.total_force()));
                ASSERT_EQ(law.contact_count(), reference.contact_count()) << motion.name << " step " << n;
                ASSERT_EQ(law.normal_force(state), law.normal_force());
            }
            EXPECT_LE(deviation, 1e-12 * largest) << "M = " << material.terms().size() << ", " << motion.name;
            EXPECT_NO_THROW(law.check(state));
        }
    }
}

// A held contact (no element enters or leaves) is stepped in its header: the elements' w, flags and h in the
// state stay as they were, bit for bit, while the force relaxes as the Foundation's.
TEST(DemComposedNormalStep, AHeldContactsStepsLeaveItsElementsAsTheyWere) {
    const auto material = rheology::Rheology::standard(1e6, 1e6, 1e-4);
    ContactLaw law(material, radius, 0.0, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    for (int n = 1; n <= 100; ++n) law.advance(state, peak_overlap * n / 100.0, {0.0, 0.0});
    const std::size_t start = 6 + foundation::ComposedNormalStep::header_size(1) + 3;  // w_0 (contact_law.hpp)
    const std::vector<double> before(state.begin() + static_cast<std::ptrdiff_t>(start),
                                     state.begin() + static_cast<std::ptrdiff_t>(start + elements * 3));
    const double loaded = law.normal_force(state);
    for (int n = 0; n < 50; ++n) law.advance(state, peak_overlap, {0.0, 0.0});
    const std::vector<double> after(state.begin() + static_cast<std::ptrdiff_t>(start),
                                    state.begin() + static_cast<std::ptrdiff_t>(start + elements * 3));
    EXPECT_EQ(after, before);
    EXPECT_LT(law.normal_force(state), loaded);  // the standard solid relaxes (tau = 0.1 ms = 50 steps)
    EXPECT_GT(law.contact_count(), 0u);
}

// held_step_size() names every double a held step without friction touches (what a pair style prefetches): the rest
// of the state stays bit for bit, while the force within it relaxes.
TEST(DemComposedNormalStep, AHeldFrictionlessStepTouchesItsLeadingDoublesOnly) {
    const auto material = rheology::Rheology::standard(1e6, 1e6, 1e-4);
    ContactLaw law(material, radius, 0.0, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    for (int n = 1; n <= 100; ++n) {
        law.advance_spatial(state, peak_overlap * n / 100.0, {0.0, 0.0, 1.0}, {0.0, 0.0, 0.0});
    }
    const std::vector<double> before = state;
    for (int n = 0; n < 50; ++n) law.advance_spatial(state, peak_overlap, {0.0, 0.0, 1.0}, {1e-9, 0.0, 0.0});
    ASSERT_LT(law.held_step_size(), state.size());
    for (std::size_t i = law.held_step_size(); i < state.size(); ++i) EXPECT_EQ(state[i], before[i]) << i;
    EXPECT_LT(law.normal_force(state), law.normal_force(std::span<const double>(before)));  // relaxed
    EXPECT_EQ(law.held_step_size(), 6 + foundation::ComposedNormalStep::header_size(1) + 3);  // contact_law.hpp
}

// A held step without friction reads nothing beyond held_step_size() and the held_tangential range (the layer's
// count): every other double of its state made NaN, the step gives the force, the element count and the leading
// doubles to the bit, and writes nothing else (what a pair style prefetches covers what the step reads).
TEST(DemComposedNormalStep, AHeldFrictionlessStepReadsItsHeldRangesOnly) {
    const auto material = rheology::Rheology::prony(1e6, {{1e6, 1e-4}, {1e6, 1.3e-3}});
    ContactLaw law(material, radius, 0.0, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    for (int n = 1; n <= 100; ++n) {
        law.advance_spatial(state, peak_overlap * n / 100.0, {0.0, 0.0, 1.0}, {0.0, 0.0, 0.0});
    }
    for (int n = 0; n < 5; ++n) law.advance_spatial(state, peak_overlap, {0.0, 0.0, 1.0}, {1e-9, 0.0, 0.0});
    const std::size_t leading = law.held_step_size(), first = law.held_tangential_offset();
    const std::size_t last = first + law.held_tangential_size();
    ASSERT_GT(first, leading);
    ASSERT_LE(last, state.size());
    auto poisoned = state;
    for (std::size_t i = leading; i < state.size(); ++i) {
        if (i < first || i >= last) poisoned[i] = std::numeric_limits<double>::quiet_NaN();
    }
    for (int n = 0; n < 20; ++n) {
        law.advance_spatial(state, peak_overlap, {0.0, 0.0, 1.0}, {1e-9, 0.0, 0.0});
        const double force = law.normal_force(state);
        const std::size_t contacts = law.contact_count();
        law.advance_spatial(poisoned, peak_overlap, {0.0, 0.0, 1.0}, {1e-9, 0.0, 0.0});
        ASSERT_EQ(law.normal_force(std::span<const double>(poisoned)), force) << "step " << n;
        ASSERT_EQ(law.contact_count(), contacts) << "step " << n;
    }
    for (std::size_t i = 0; i < state.size(); ++i) {
        if (i < leading || (i >= first && i < last)) {
            EXPECT_EQ(poisoned[i], state[i]) << i;
        } else {
            EXPECT_TRUE(std::isnan(poisoned[i])) << i;
        }
    }
}

// A DEM code may change its time step between steps (LAMMPS's fix dt/reset) while a contact is held in the composed
// form: the header's maps are products of past steps' maps, each of its own dt, so the following steps compose with
// the new step's map. The reference: the Foundation with each step's own coefficients (eq. 13-22). M = 0 too (an
// elastic and a Kelvin-Voigt contact: the free elements' map alone composes).
TEST(DemComposedNormalStep, AChangingTimeStepComposesAsTheFoundationSteps) {
    auto cases = materials();
    cases.push_back(rheology::Rheology::elastic(1e6));
    cases.push_back(rheology::Rheology::kelvin_voigt(1e6, 20.0));
    for (const auto& material : cases) {
        for (const auto& motion : motions()) {
            foundation::Foundation reference(material, *profile::make_sphere(radius), half_width / elements, elements);
            ContactLaw law(material, radius, 0.0, elements, half_width, time_step);
            std::vector<double> state(law.state_size());
            law.initialise(state);
            double depth = 0.0, largest = 0.0, deviation = 0.0;
            for (int n = 1; n <= std::min(motion.steps, 3000); ++n) {
                const double step = time_step * (n % 7 == 0 ? 2.5 : n % 3 == 0 ? 0.4 : 1.0);
                const double overlap = motion.overlap(n);
                reference.begin_step(foundation::step_coefficients(material, step));
                reference.advance(depth, overlap);
                depth = overlap;
                law.set_time_step(step);
                law.advance(state, overlap, {0.0, 0.0});
                largest = std::max(largest, std::abs(reference.total_force()));
                deviation = std::max(deviation, std::abs(law.normal_force() - reference.total_force()));
                ASSERT_EQ(law.contact_count(), reference.contact_count()) << motion.name << " step " << n;
            }
            EXPECT_LE(deviation, 1e-12 * largest) << "M = " << material.terms().size() << ", " << motion.name;
        }
    }
}

// With friction the tangential layer reads the line loads the composed form derives (G_inf (d - g_i) + eta rate + sum
// G_k (A_k h^_k + C_k), eq. 16, 22): the reference is the Foundation's line loads on its own buffers driving a
// PlanarTangentialLayer of its own (eq. 41-50), every element every step; materials with a parallel dashpot.
TEST(DemComposedNormalStep, TangentialForcesWithFrictionAreTheFoundationsToRoundOff) {
    const auto all = materials();
    for (const auto& material : {all[1], all[3]}) {
        for (const auto& motion : motions()) {
            foundation::Foundation reference(material, *profile::make_sphere(radius), half_width / elements, elements);
            foundation::PlanarTangentialLayer layer(material, 0.3, half_width / elements, elements);
            const auto coefficients = foundation::step_coefficients(material, time_step);
            ContactLaw law(material, radius, 0.3, elements, half_width, time_step);
            std::vector<double> state(law.state_size()), loads(elements);
            law.initialise(state);
            double depth = 0.0, shift = 0.0, largest = 0.0, deviation = 0.0;
            for (int n = 1; n <= std::min(motion.steps, 3000); ++n) {
                const double overlap = motion.overlap(n), displacement = 3e-6 * std::sin(2.0 * pi * n / 300.0);
                reference.begin_step(coefficients);
                reference.advance(depth, overlap);
                reference.line_loads(loads);
                layer.begin_step(coefficients, reference.entries());
                layer.advance({displacement - shift, 0.0}, loads, reference.contact_flags());
                depth = overlap;
                shift = displacement;
                law.advance(state, overlap, {displacement, 0.0});
                largest = std::max(largest, std::abs(layer.total_force()[0]));
                deviation = std::max(deviation, std::abs(law.tangential_force()[0] - layer.total_force()[0]));
            }
            EXPECT_GT(largest, 0.0);
            EXPECT_LE(deviation, 1e-12 * largest) << "M = " << material.terms().size() << ", " << motion.name;
        }
    }
}

}  // namespace
}  // namespace mdr::dem
