// TangentialLayer::begin_jump: the tangential layer's step of no time at a force jump against the parallel dashpot
// (docs/theory.md section 4b, eq. T1). No element moves (u_i, h_{k,i} stay); in contact t_i' = clamp(t_i + s,
// +-mu F_N,i' / ((8/3) dx)), out of contact 0; checked on a loaded state (a standard solid with a dashpot, one
// branch) against T1 written here, element by element.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "mdr/foundation/tangential_layer.hpp"
#include "mdr/rheology/rheology.hpp"

namespace mdr::foundation {
namespace {

constexpr double spacing = 1e-6, friction = 0.3;
constexpr std::size_t count = 6;
// The state before the jump: u_i, t_i (its dashpot's part included: t_i is not G_inf u_i + G_1 h_i) and h_i; the
// elements 0-4 were in contact, 5 untouched.
const std::vector<double> displacements = {2e-9, 2e-9, 1.5e-9, 1e-9, 0.5e-9};
const std::vector<double> stresses = {4.0, 3.5, 3.0, -1.0, 0.8};
const std::vector<double> memories = {1e-9, 1e-9, 0.7e-9, 0.4e-9, 0.1e-9};
// After the jump: the normal line loads q_z,i and the contact flags (element 4 left).
const std::vector<double> normal_loads = {40.0, 20.0, 8.0, 12.0, 0.0, 0.0};
const std::vector<double> contact = {1.0, 1.0, 1.0, 1.0, 0.0, 0.0};

double limit(std::size_t i) { return contact[i] * friction * normal_loads[i] / (8.0 / 3.0); }

TangentialLayer loaded() {
    TangentialLayer layer(rheology::Rheology(1e6, 1e3, {{3e6, 0.1}}), friction, spacing, count);
    std::vector<double> state(TangentialLayer::state_size(count, 1), 0.0);
    state[1] = static_cast<double>(displacements.size());
    for (std::size_t i = 0; i < displacements.size(); ++i) {
        state[2 + i] = displacements[i];
        state[2 + count + i] = stresses[i];
        state[2 + 2 * count + i] = static_cast<double>(TangentialState::stick);
        state[2 + 3 * count + i] = 10.0;
        state[2 + 4 * count + i] = memories[i];
    }
    layer.load_state(state);
    return layer;
}

void expect_jump(double increment) {
    TangentialLayer layer = loaded();
    layer.begin_jump();
    std::vector<double> before(TangentialLayer::state_size(count, 1), 0.0);
    layer.save_state(before);
    const double trial = layer.trial_force(increment, normal_loads, contact);
    layer.advance(increment, normal_loads, contact);
    std::vector<double> after(before.size(), 0.0);
    layer.save_state(after);
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double t = i < stresses.size() ? stresses[i] : 0.0;
        const double expected = std::clamp(t + increment, -limit(i), limit(i));
        EXPECT_DOUBLE_EQ(layer.line_loads()[i] / (8.0 / 3.0), expected) << i;
        EXPECT_EQ(after[2 + i], before[2 + i]) << i;                          // u_i
        EXPECT_EQ(after[2 + 4 * count + i], before[2 + 4 * count + i]) << i;  // h_i
        const bool at_limit = contact[i] != 0.0 && std::abs(expected) >= limit(i);
        const auto state = contact[i] == 0.0 ? TangentialState::free
                                             : (at_limit ? TangentialState::slip : TangentialState::stick);
        EXPECT_EQ(layer.states()[i], state) << i;
        sum += expected;
    }
    const double force = 2.0 * (8.0 / 3.0) * spacing * sum;
    EXPECT_NEAR(layer.total_force(), force, 1e-14 * std::abs(force));
    EXPECT_NEAR(trial, force, 1e-14 * std::abs(force));
    EXPECT_EQ(layer.material_work(), 0.0);  // nothing moves
    EXPECT_EQ(layer.friction_work(), 0.0);
}

TEST(TangentialJump, HeldRateClampsToTheNewLimitsAndFreesTheElementsThatLeft) {
    // Limits 4.5, 2.25, 0.9, 1.35, 0: element 0 keeps 4.0, 1 and 2 slip at 2.25 and 0.9, 3 keeps -1.0, 4 is free.
    expect_jump(0.0);
}

TEST(TangentialJump, ARateChangeAddsItsStressToEveryElementInContact) {
    // eta du' = 0.6 and -0.6: 4.6 -> 4.5 at its limit, -1.0 + 0.6 within it; -1.0 - 0.6 -> -1.35.
    expect_jump(0.6);
    expect_jump(-0.6);
}

TEST(TangentialJump, TheSlidingIncrementSaturatesEveryElementInContact) {
    TangentialLayer layer = loaded();
    layer.begin_jump();
    // The largest limit - t_i over the elements in contact: element 3, 1.35 + 1.0.
    EXPECT_DOUBLE_EQ(layer.sliding_increment(1.0, normal_loads, contact), limit(3) + 1.0);
    EXPECT_DOUBLE_EQ(layer.trial_force(limit(3) + 1.0, normal_loads, contact),
                     layer.sliding_force(normal_loads, contact));
}

}  // namespace
}  // namespace mdr::foundation
