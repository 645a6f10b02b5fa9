// Foundation::jump: a force jump in no time against the parallel dashpot (docs/theory.md section 3, eq. J1, J2). The
// elements whose stress sigma_i + eta dr would pull leave, the others take sigma_i + eta dr, and 8 dx times their sum
// is the new force; checked on stresses loaded out of order (J1 does not assume a monotone profile) against a
// bisection of J1 written here, and the edge (J2) between the outermost element kept and its neighbour that left.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "mdr/foundation/foundation.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {
namespace {

constexpr double spacing = 1e-6, viscosity = 1e3;
constexpr std::size_t count = 10, active = 8;
// The stresses of the elements in contact [0, 7), out of order; element 7 touched and free, 8 and 9 untouched.
const std::vector<double> stresses = {5.0, 1.0, 4.0, 0.5, 3.0, 2.0, 0.2};

// A Kelvin-Voigt foundation under a sphere with the stresses above loaded (w_i = 1e-9 each; no branches).
Foundation loaded() {
    const auto sphere = profile::make_sphere(1e-3);
    Foundation foundation(rheology::Rheology::kelvin_voigt(1e6, viscosity), *sphere, spacing, count);
    std::vector<double> state(Foundation::state_size(count, 0), 0.0);
    double sum = 0.0;
    for (const double sigma : stresses) sum += sigma;
    state[0] = 1e-9;
    state[1] = 8.0 * spacing * sum;
    state[2] = static_cast<double>(active);
    for (std::size_t i = 0; i < active; ++i) {
        state[3 + i] = 1e-9;
        state[3 + count + i] = i < stresses.size() ? stresses[i] : 0.0;
        state[3 + 2 * count + i] = i < stresses.size() ? 1.0 : 0.0;
    }
    foundation.load_state(state);
    return foundation;
}

// J1 by bisection: the dr at which 8 dx sum_i max(sigma_i + eta dr, 0) is `force` (> 0).
double bisected_rate_change(double force) {
    const auto total = [](double rate_change) {
        double sum = 0.0;
        for (const double sigma : stresses) sum += std::max(sigma + viscosity * rate_change, 0.0);
        return 8.0 * spacing * sum;
    };
    double low = -10.0 / viscosity, high = 10.0 / viscosity;
    for (int k = 0; k < 200; ++k) {
        const double middle = 0.5 * (low + high);
        (total(middle) < force ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

TEST(FoundationJump, ADownJumpKeepsTheElementsThatDoNotPullWhereverTheyLie) {
    // eta dr = -1.5: the elements at 5, 4, 3, 2 stay (sum 8), those at 1, 0.5, 0.2 leave.
    Foundation foundation = loaded();
    const double force = 8.0 * spacing * 8.0;
    const auto rate_change = foundation.jump(force);
    ASSERT_TRUE(rate_change.has_value());
    EXPECT_NEAR(*rate_change, bisected_rate_change(force), 1e-12 / viscosity);
    EXPECT_NEAR(viscosity * *rate_change, -1.5, 1e-12);
    const auto flags = foundation.contact_flags();
    const auto loads = foundation.line_loads();
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const bool kept = i < stresses.size() && stresses[i] + viscosity * *rate_change >= 0.0;
        EXPECT_EQ(flags[i], kept ? 1.0 : 0.0) << i;
        EXPECT_NEAR(loads[i] / 4.0, kept ? stresses[i] + viscosity * *rate_change : 0.0, 1e-12) << i;
        EXPECT_EQ(foundation.displacements()[i], i < active ? 1e-9 : 0.0) << i;  // no time passes
        sum += loads[i] / 4.0;
    }
    EXPECT_NEAR(8.0 * spacing * sum, force, 1e-12 * force);
    EXPECT_EQ(foundation.total_force(), force);
    EXPECT_EQ(foundation.contact_count(), 4u);
    // J2: between element 5 (0.5 after the jump) and element 6, which left (0.2 - 1.5 = -1.3 had it stayed).
    EXPECT_NEAR(foundation.contact_radius(), foundation.position(5) + spacing * 0.5 / (0.5 + 1.3), 1e-12 * spacing);
}

TEST(FoundationJump, AnUpJumpKeepsEveryElementAndSharesTheForce) {
    Foundation foundation = loaded();
    const double before = foundation.total_force();
    const double force = 2.0 * before;
    const auto rate_change = foundation.jump(force);
    ASSERT_TRUE(rate_change.has_value());
    EXPECT_DOUBLE_EQ(*rate_change, (force - before) / (8.0 * spacing * viscosity * 7.0));  // dF = 8 dx eta n dr
    EXPECT_EQ(foundation.contact_count(), 7u);
    EXPECT_EQ(foundation.total_force(), force);
}

TEST(FoundationJump, AJumpToZeroKeepsTheStateAndCarriesTheSharedRate) {
    Foundation foundation = loaded();
    const double before = foundation.total_force();
    const auto rate_change = foundation.jump(0.0);
    ASSERT_TRUE(rate_change.has_value());
    EXPECT_DOUBLE_EQ(*rate_change, -before / (8.0 * spacing * viscosity * 7.0));
    EXPECT_EQ(foundation.contact_count(), 7u);
    EXPECT_EQ(foundation.line_loads()[0], 4.0 * stresses[0]);
    EXPECT_EQ(foundation.total_force(), 0.0);
    EXPECT_EQ(foundation.contact_radius(), 0.0);
}

TEST(FoundationJump, WithNothingInContactTheRateIsUnknown) {
    const auto sphere = profile::make_sphere(1e-3);
    Foundation foundation(rheology::Rheology::kelvin_voigt(1e6, viscosity), *sphere, spacing, count);
    EXPECT_FALSE(foundation.jump(1e-9).has_value());
    EXPECT_EQ(foundation.total_force(), 0.0);
}

}  // namespace
}  // namespace mdr::foundation
