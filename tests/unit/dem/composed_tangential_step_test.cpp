// The DEM contact law's composed tangential step (foundation::ComposedTangentialStep): while the normal step is
// composed and every element in contact sticks, a contact's tangential step goes through its state's header alone,
// and its forces are those of the layer's element-by-element step to round-off.

#include "mdr/dem/contact_law.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mdr/error.hpp"
#include "thrown_key.hpp"
#include "mdr/foundation/composed_tangential_step.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/planar_tangential_layer.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::dem {
namespace {

constexpr double radius = 0.005, peak = 4e-5, time_step = 2e-6, friction = 0.3, pi = 3.141592653589793;
constexpr std::size_t elements = 20;
const double half_width = 1.2 * std::sqrt(radius * peak);
const double spacing = half_width / elements;

// M = 0 to 3, with and without a parallel dashpot.
std::vector<rheology::Rheology> materials() {
    return {rheology::Rheology::elastic(1e6),
            rheology::Rheology::kelvin_voigt(1e6, 20.0),
            rheology::Rheology::standard(1e6, 1e6, 1e-4),
            rheology::Rheology(1e6, 20.0, {{1e6, 1e-4}, {5e5, 3e-3}}),
            rheology::Rheology::prony(1e6, {{1e6, 4e-5}, {1e6, 1.3e-3}, {1e6, 4e-2}}),
            rheology::Rheology(5e5, 5.0, {{1e6, 4e-5}, {1e6, 4e-4}, {1e6, 4e-3}})};
}

// A held contact's history: loaded in 100 steps, then held; a small circling tangential motion (every element in
// contact sticks), a slide (the elements slip) from step 800 to 1100, held there with the small motion again (stick),
// a partial unloading at step 1800 (elements leave contact: free touched elements while the steps compose), held.
double overlap_at(int n) {
    const double loaded = peak * std::sin(0.5 * pi * std::min(n, 100) / 100.0);
    if (n < 1800) return loaded;
    return loaded * (1.0 - 0.15 * std::min(1.0, (n - 1800) / 40.0));
}
PlanarVector displacement_at(int n, double wobble) {
    const double slide = 4e-6 * std::clamp((n - 800) / 300.0, 0.0, 1.0);
    const double angle = 2.0 * pi * n / 400.0;
    return {slide + wobble * std::sin(angle), 0.5 * slide + wobble * (1.0 - std::cos(angle))};
}

// The time step of step n: fixed, or changing (a DEM code's fix dt/reset).
double step_at(int n, bool changing) {
    if (!changing) return time_step;
    return time_step * (n % 7 == 0 ? 2.5 : n % 3 == 0 ? 0.4 : 1.0);
}

// The elastic energy of a Foundation's and a layer's saved states, sum_i 2 c dx (G_inf |w_i|^2 + sum_k G_k
// |h_k,i|^2) / 2 (c = 4 normal, 8/3 tangential, eq. 11, 41; Foundation::save_state: depth, force, count, w, sigma,
// flags, h; PlanarTangentialLayer::save_state: force (2), count, u_x, u_y, then h_x, h_y per branch).
double reference_energy(const rheology::Rheology& material, const std::vector<double>& normal,
                        const std::vector<double>& tangential) {
    const auto& terms = material.terms();
    const std::size_t n = elements, m = terms.size();
    const auto springs = [&](const double* w, const double* h, std::size_t count) {
        double sum = material.equilibrium_modulus() * w[0] * w[0];
        for (std::size_t k = 0; k < m; ++k) sum += terms[k].modulus * h[k * count * n] * h[k * count * n];
        return sum;
    };
    double normal_sum = 0.0, tangential_sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        normal_sum += springs(&normal[3 + i], &normal[3 + 3 * n + i], 1);
        for (std::size_t c = 0; c < 2; ++c) {
            tangential_sum += springs(&tangential[3 + c * n + i], &tangential[3 + (2 + c) * n + i], 2);
        }
    }
    return spacing * (4.0 * normal_sum + 8.0 / 3.0 * tangential_sum);
}

struct Deviations {
    double force = 0.0, largest = 0.0, energy = 0.0, largest_energy = 0.0;
    int composed[3] = {0, 0, 0};  ///< steps begun composed: before the slide, after it, after the unloading
    int written = 0;
};

// The reference: a Foundation and a PlanarTangentialLayer on their own buffers, every element every step (the
// layer's element pass, eq. 41-50, verified against TangentialLayer), against the law on a state; the law's
// tangential trial must be its step's force to the bit. At step 1000 the state is mirrored (its components stay);
// at step 1500 it is checked and copied into a new law's keeping (a restart).
Deviations run(const rheology::Rheology& material, bool changing, double wobble) {
    foundation::Foundation reference(material, *profile::make_sphere(radius), spacing, elements);
    foundation::PlanarTangentialLayer layer(material, friction, spacing, elements);
    auto law = std::make_unique<ContactLaw>(material, radius, friction, elements, half_width, time_step);
    std::vector<double> state(law->state_size()), loads(elements), normal_saved, layer_saved;
    normal_saved.resize(foundation::Foundation::state_size(elements, material.terms().size()));
    layer_saved.resize(foundation::PlanarTangentialLayer::state_size(elements, material.terms().size()));
    law->initialise(state);
    const std::size_t flag = law->held_tangential_offset() + foundation::ComposedTangentialStep::composed_offset;
    Deviations result;
    double depth = 0.0;
    PlanarVector shift{0.0, 0.0};
    for (int n = 1; n <= 2400; ++n) {
        const double dt = step_at(n, changing), overlap = overlap_at(n);
        const PlanarVector displacement = displacement_at(n, wobble);
        const auto coefficients = foundation::step_coefficients(material, dt);
        reference.begin_step(coefficients);
        reference.advance(depth, overlap);
        reference.line_loads(loads);
        layer.begin_step(coefficients, reference.entries());
        layer.advance({displacement[0] - shift[0], displacement[1] - shift[1]}, loads, reference.contact_flags());
        depth = overlap;
        shift = displacement;
        const bool composes = state[flag] != 0.0;
        law->set_time_step(dt);
        law->begin(state);
        law->advance_normal(overlap);
        const PlanarVector trial = law->tangential_trial(displacement);
        law->advance_tangential(displacement);
        law->end(state);
        EXPECT_EQ(trial, law->tangential_force()) << "step " << n;
        EXPECT_EQ(law->tangential_force(state), law->tangential_force()) << "step " << n;
        (composes ? result.composed[n < 800 ? 0 : n < 1800 ? 1 : 2] : result.written) += 1;
        const PlanarVector expected = layer.total_force(), got = law->tangential_force();
        result.largest = std::max(result.largest, std::hypot(expected[0], expected[1]));
        result.force = std::max(result.force, std::hypot(got[0] - expected[0], got[1] - expected[1]));
        reference.save_state(normal_saved);
        layer.save_state(layer_saved);
        const double energy = reference_energy(material, normal_saved, layer_saved);
        result.largest_energy = std::max(result.largest_energy, energy);
        result.energy = std::max(result.energy, std::abs(law->stored_energy(state) - energy));
        if (n == 1000) ContactLaw::mirror(state);
        if (n == 1500) {
            law->check(state);
            std::vector<double> copy(state);
            state.swap(copy);
            law = std::make_unique<ContactLaw>(material, radius, friction, elements, half_width, time_step);
        }
    }
    EXPECT_NO_THROW(law->check(state));
    return result;
}

TEST(DemComposedTangentialStep, ForcesAndEnergiesAreTheLayersToRoundOff) {
    for (const auto& material : materials()) {
        for (const bool changing : {false, true}) {
            const std::string name =
                "M = " + std::to_string(material.terms().size()) + (changing ? ", changing dt" : ", fixed dt");
            const Deviations d = run(material, changing, 2e-8);
            EXPECT_LE(d.force, 1e-12 * d.largest) << name;
            EXPECT_LE(d.energy, 1e-11 * d.largest_energy) << name;
            // held and sticking: composed (stick, then slip, then stick again; then with free touched elements)
            for (const int composed : d.composed) EXPECT_GT(composed, 400) << name;
            EXPECT_GT(d.written, 400) << name;  // loading, the slide, the unloading: element by element
        }
    }
}

// The composed tangential step reads and writes the leading doubles (held_step_size: the normal header, the
// Foundation's overlap, force and count) and the tangential header only (held_tangential_offset and _size): a held
// contact whose elements all stick leaves the rest of its state as it was, bit for bit, while its tangential force
// changes.
TEST(DemComposedTangentialStep, AHeldStickingStepTouchesItsHeldRangesOnly) {
    for (const auto& material : materials()) {
        ContactLaw law(material, radius, friction, elements, half_width, time_step);
        std::vector<double> state(law.state_size());
        law.initialise(state);
        for (int n = 1; n <= 120; ++n) law.advance(state, overlap_at(n), displacement_at(n, 2e-8));
        const std::vector<double> before = state;
        for (int n = 121; n <= 220; ++n) law.advance(state, overlap_at(n), displacement_at(n, 2e-8));
        const std::size_t tangential = law.held_tangential_offset();
        ASSERT_GT(tangential, law.held_step_size());
        for (std::size_t i = law.held_step_size(); i < state.size(); ++i) {
            if (i >= tangential && i < tangential + law.held_tangential_size()) continue;
            ASSERT_EQ(state[i], before[i]) << "M = " << material.terms().size() << ", state[" << i << "]";
        }
        EXPECT_NE(law.tangential_force(state), law.tangential_force(std::span<const double>(before)));
        EXPECT_NO_THROW(law.check(state));
    }
}

// advance_if_certain is prepare and, where its bound holds, advance in one call: the same bytes of the state as the
// two calls where every element in contact certainly sticks (a large least line load), the state untouched and the
// answer false where the bound fails (a least line load of zero), for M = 0 to 3 on a held contact's header.
TEST(DemComposedTangentialStep, AdvanceIfCertainIsPrepareThenAdvance) {
    for (const auto& material : materials()) {
        const std::string name = "M = " + std::to_string(material.terms().size());
        ContactLaw law(material, radius, friction, elements, half_width, time_step);
        std::vector<double> state(law.state_size());
        law.initialise(state);
        for (int n = 1; n <= 220; ++n) law.advance(state, overlap_at(n), displacement_at(n, 2e-8));
        // The layout from the law's public sizes: the tangential header (held_tangential_offset, with friction)
        // before the layer's force and count, u_x, u_y and h; the Foundation's depth, force and count end the
        // leading doubles, its w and flags follow.
        const std::size_t m = material.terms().size();
        const std::size_t header = law.held_tangential_offset();
        const std::size_t header_size = foundation::ComposedTangentialStep::header_size(m);
        const std::size_t normal = law.held_step_size() - 3;
        ASSERT_EQ(state[header + foundation::ComposedTangentialStep::composed_offset], 1.0) << name;
        foundation::ComposedTangentialStep step(material, friction, spacing);
        foundation::StepCoefficients coefficients;
        foundation::fill_step_coefficients(material, time_step, coefficients);
        step.set_step(coefficients);
        const auto elements_of = [&](std::vector<double>& s) {
            double* u = s.data() + header + header_size + 3;
            return foundation::PlanarElements{u, u + 2 * elements, s.data() + normal + 3 + elements, elements,
                                              static_cast<std::size_t>(s[normal + 2])};
        };
        const PlanarVector increment{3e-9, -2e-9};
        for (const double least_load : {1e12, 0.0}) {
            std::vector<double> two_calls = state, one_call = state;
            foundation::ComposedTangentialStep::Step prepared, certain;
            const std::span<double> first(two_calls.data() + header, header_size);
            const bool sticks = step.prepare(first, increment, least_load, prepared);
            if (sticks) step.advance(first, elements_of(two_calls), prepared);
            const bool advanced = step.advance_if_certain(std::span<double>(one_call.data() + header, header_size),
                                                          elements_of(one_call), increment, least_load, certain);
            EXPECT_EQ(advanced, least_load > 0.0) << name;
            EXPECT_EQ(advanced, sticks) << name;
            EXPECT_EQ(certain.common, prepared.common) << name;
            EXPECT_EQ(one_call, two_calls) << name << ", least load " << least_load;
            if (!advanced) {
                EXPECT_EQ(one_call, state) << name;
            }
        }
    }
}

using testing::thrown_key;

// check() (a restart) validates the tangential header: its flag, its count of the elements in contact, its
// composition factors, and its summary of the written elements, which the composed steps read in their place.
TEST(DemComposedTangentialStep, ACorruptedTangentialHeaderRaisesNamingTheEntry) {
    const auto material = rheology::Rheology::prony(1e6, {{1e6, 4e-5}, {1e6, 1.3e-3}});
    ContactLaw law(material, radius, friction, elements, half_width, time_step);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    for (int n = 1; n <= 300; ++n) law.advance(state, overlap_at(n), displacement_at(n, 2e-8));
    const std::size_t header = law.held_tangential_offset();
    ASSERT_EQ(state[header + foundation::ComposedTangentialStep::composed_offset], 1.0);
    EXPECT_NO_THROW(law.check(state));
    const auto key = [](std::size_t i) { return "state[" + std::to_string(i) + "]"; };
    const std::size_t factor = header + foundation::ComposedTangentialStep::factors_offset;
    // the flag, the count in contact, a factor, the sums and the largest |u^|, the sums and largest |h^_k|
    const std::vector<std::pair<std::size_t, double>> corruptions = {
        {header + 0, 0.5},         {header + 3, 1.0},         {factor + 1, 1.5},
        {header + 6, 1e-9},        {header + 7, 1e-9},        {header + 8, 1e-9},
        {factor + 6, 1e-9},        {factor + 9, 1e-9},        {factor + 11, 1e-9}};
    for (const auto& [entry, change] : corruptions) {
        auto corrupted = state;
        corrupted[entry] += change;
        EXPECT_EQ(thrown_key([&] { law.check(corrupted); }), key(entry)) << entry;
    }
}

}  // namespace
}  // namespace mdr::dem
