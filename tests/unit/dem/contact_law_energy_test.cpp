// The DEM contact law's energy: the elastic energy stored in a contact's state and the work done on it per step,
// against the closed forms of the discrete MDR foundation (elements at x_i = (i + 1/2) dx under g(x) = x^2 / R).

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "mdr/dem/contact_law.hpp"
#include "mdr/error.hpp"

namespace mdr::dem {
namespace {

constexpr double radius = 0.005, half_width = 1e-3, overlap = 4e-5;
constexpr std::size_t elements = 50;

// sum_i 4 dx (d - g_i)^2 over the elements in contact at overlap d: the energy of unit-modulus normal springs
// compressed by w_i = d - x_i^2 / R (eq. 11, 13; both halves: 2 (4 dx) w^2 / 2).
double unit_normal_energy(double d) {
    const double dx = half_width / static_cast<double>(elements);
    double sum = 0.0;
    for (std::size_t i = 0; i < elements; ++i) {
        const double x = (static_cast<double>(i) + 0.5) * dx;
        const double w = d - x * x / radius;
        if (w > 0.0) sum += 4.0 * dx * w * w;
    }
    return sum;
}

// Loads a contact from its state's overlap to `target` in `steps` equal steps; returns the work done on it.
double load(ContactLaw& law, std::vector<double>& state, double target, int steps) {
    const double start = law.overlap(state);
    double work = 0.0;
    for (int n = 1; n <= steps; ++n) {
        law.advance(state, start + (target - start) * n / steps, law.displacement(state));
        work += law.step_work();
    }
    return work;
}

TEST(DemContactLawEnergy, AnElasticContactStoresItsWorkAndGivesItBack) {
    constexpr double modulus = 1e6;
    ContactLaw law(rheology::Rheology::prony(modulus, {}), radius, 0.3, elements, half_width, 1e-6);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    const double loading = load(law, state, overlap, 4000);
    const double expected = modulus * unit_normal_energy(overlap);
    EXPECT_NEAR(law.stored_energy(state), expected, 1e-12 * expected);
    EXPECT_NEAR(loading, expected, 1e-5 * expected);  // the trapezoidal rule's error
    const double unloading = load(law, state, 0.0, 4000);
    EXPECT_NEAR(law.stored_energy(state), 0.0, 1e-12 * expected);
    EXPECT_NEAR(loading + unloading, 0.0, 1e-5 * expected);  // nothing dissipated over the closed cycle
}

TEST(DemContactLawEnergy, AShortStateIsRefusedNamingItsSize) {
    ContactLaw law(rheology::Rheology::prony(1e6, {}), radius, 0.3, elements, half_width, 1e-6);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    const std::span<const double> short_state(state.data(), state.size() - 1);
    try {
        (void)law.stored_energy(short_state);
        FAIL() << "a state one double short was read";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(std::string(error.what()).rfind("state = " + std::to_string(state.size() - 1) + " doubles", 0), 0u)
            << error.what();
    }
}

TEST(DemContactLawEnergy, AStickingTangentialShiftStoresItsSprings) {
    // At overlap d the 22 elements in contact have w_i >= 3.0e-6 m; a tangential shift s = 1e-7 m keeps every one
    // inside its friction limit mu 4 G w_i / (8/3) (eq. 50): each sticks with u_i = s, storing 2 (8/3) dx G s^2 / 2.
    constexpr double modulus = 1e6, shift = 1e-7;
    ContactLaw law(rheology::Rheology::prony(modulus, {}), radius, 0.3, elements, half_width, 1e-6);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    load(law, state, overlap, 1000);
    double work = 0.0;
    for (int n = 1; n <= 100; ++n) {
        law.advance(state, overlap, {shift * n / 100.0, 0.0});
        work += law.step_work();
    }
    const double dx = half_width / static_cast<double>(elements);
    const double tangential = 8.0 / 3.0 * dx * modulus * 22.0 * shift * shift;
    EXPECT_NEAR(law.stored_energy(state) - modulus * unit_normal_energy(overlap), tangential, 1e-9 * tangential);
    EXPECT_NEAR(work, tangential, 1e-9 * tangential);  // a linear spring: the trapezoidal rule is exact
}

TEST(DemContactLawEnergy, AStandardSolidHeldAfterAFastLoadDissipatesItsRelaxingBranch) {
    // G(t) = G_inf + G_1 exp(-t / tau): loaded in 1 us (1e-6 tau, glassy, G_inf + G_1) and held for 50 tau, the
    // contact keeps G_inf's share of the work and has dissipated G_1's (the branch springs relax to zero).
    constexpr double equilibrium = 1e6, relaxing = 3e6, relaxation_time = 1.0;
    ContactLaw law(rheology::Rheology::prony(equilibrium, {{relaxing, relaxation_time}}), radius, 0.3, elements,
                   half_width, 1e-9);
    std::vector<double> state(law.state_size());
    law.initialise(state);
    double work = load(law, state, overlap, 1000);
    const double glassy = (equilibrium + relaxing) * unit_normal_energy(overlap);
    EXPECT_NEAR(law.stored_energy(state), glassy, 1e-5 * glassy);
    law.set_time_step(0.01);
    work += load(law, state, overlap, 5000);
    const double kept = equilibrium * unit_normal_energy(overlap);
    const double dissipated = relaxing * unit_normal_energy(overlap);
    EXPECT_NEAR(law.stored_energy(state), kept, 1e-9 * kept);
    EXPECT_NEAR(work - law.stored_energy(state), dissipated, 1e-5 * dissipated);
}

}  // namespace
}  // namespace mdr::dem
