// A caller's StepObserver attached to run_case: it sees every state once, in time order, after the result has
// recorded it; it changes nothing in the result; and it can end the run early, leaving what was recorded up to
// then exactly as the full run has it.

#include "mdr/drivers/step_observer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <vector>

#include "mdr/drivers/indentation.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {
namespace {

// A creep test on a Kelvin-Voigt body with two force jumps (each a state of its own at the jump's time) and
// rows every 7th step.
ContactCase creep_with_jumps() {
    ContactCase contact_case{
        .title = "creep with jumps",
        .material = rheology::Rheology::kelvin_voigt(1e6, 1e3),
        .indenter = profile::make_sphere(0.01),
        .control = ForceControl{},
        .load = {.history =
                     LoadHistory({{0.0, 0.0}, {0.0, 0.5}, {0.05, 0.5}, {0.05, 0.2}, {0.1, 0.2}}, "load.history")},
        .end_time = 0.1,
        .snapshots = {0.05}};
    contact_case.numerics.elements = 100;
    contact_case.numerics.output_every = 7;
    return contact_case;
}

// A standard solid hit by a sphere.
ContactCase impact() {
    ContactCase contact_case{.title = "impact",
                             .material = rheology::Rheology::standard(1e6, 4e6, 1e-3),
                             .indenter = profile::make_sphere(0.01),
                             .control = ImpactControl{.mass = 0.01, .velocity = 0.5},
                             .load = {.history = LoadHistory({{0.0, 0.0}}, "load.history")},
                             .end_time = 0.1};
    contact_case.numerics.elements = 100;
    contact_case.numerics.output_every = 1;  // every state a row: the deepest one among them
    return contact_case;
}

// Keeps every state it is shown, with what the result held by then.
class Watcher final : public StepObserver {
public:
    void observe(const StepState& state) override {
        states.push_back(state);
        contact_radii.push_back(state.contact_radius());
    }
    std::vector<StepState> states;
    std::vector<double> contact_radii;
};

// Ends the run at the first state whose force reaches `force`.
class StopAtForce final : public StepObserver {
public:
    explicit StopAtForce(double force) : force_(force) {}
    void observe(const StepState&) override {}
    bool stop(const StepState& state) override { return state.force >= force_; }

private:
    double force_;
};

// Ends an impact at its deepest state: the first whose velocity points away from the surface.
class StopAtRebound final : public StepObserver {
public:
    void observe(const StepState&) override {}
    bool stop(const StepState& state) override { return state.velocity <= 0.0; }
};

void expect_same_rows(const IndentationResult& a, const IndentationResult& b) {
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.force, b.force);
    EXPECT_EQ(a.radius, b.radius);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(a.steps, b.steps);
}

TEST(StepObserver, SeesEveryStateOnceInTimeOrderWithTheRowsRecorded) {
    const auto contact_case = creep_with_jumps();
    Watcher watcher;
    const auto result = run_case(contact_case, {}, {&watcher});
    const auto& states = watcher.states;
    ASSERT_EQ(states.size(), result.steps + 1);  // the initial state and one per step
    std::vector<double> row_times;
    std::size_t unsettled = 0;
    for (std::size_t i = 0; i < states.size(); ++i) {
        EXPECT_EQ(states[i].step, i);
        EXPECT_EQ(states[i].last, i + 1 == states.size());
        if (i > 0) {
            EXPECT_GE(states[i].time, states[i - 1].time);
            EXPECT_GE(states[i].fraction, states[i - 1].fraction);
        }
        if (!states[i].settled) {
            ++unsettled;
            ASSERT_LT(i + 1, states.size());
            EXPECT_EQ(states[i + 1].time, states[i].time);  // another step at the same time follows
        }
        if (states[i].row) row_times.push_back(states[i].time);
    }
    EXPECT_EQ(unsettled, 1u);  // the jump at 0.05 s (the one at t = 0 follows the initial state, which counts as settled)
    EXPECT_EQ(states.front().fraction, 0.0);
    EXPECT_EQ(states.back().fraction, 1.0);
    EXPECT_EQ(states.back().time, 0.1);
    EXPECT_EQ(row_times, result.time);  // the rows are the states marked as rows, the last one included
    EXPECT_EQ(states.back().force, result.force.back());
    EXPECT_EQ(watcher.contact_radii.back(), result.radius.back());
    EXPECT_FALSE(result.stopped);
}

TEST(StepObserver, ChangesNothingInTheResult) {
    for (const auto& contact_case : {creep_with_jumps(), impact()}) {
        Watcher watcher;
        const auto watched = run_case(contact_case, {}, {&watcher});
        const auto plain = run_case(contact_case);
        expect_same_rows(watched, plain);
        EXPECT_EQ(watched.snapshots.size(), plain.snapshots.size());
    }
}

TEST(StepObserver, AnImpactHandsOverItsVelocityAndEndsWhenTheContactEnds) {
    Watcher watcher;
    const auto result = run_case(impact(), {}, {&watcher});
    ASSERT_TRUE(result.impact);
    const auto& states = watcher.states;
    ASSERT_EQ(states.size(), result.steps + 1);
    EXPECT_EQ(states.front().velocity, 0.5);
    EXPECT_EQ(states.back().velocity, -result.impact->rebound_velocity);
    EXPECT_TRUE(states.back().last);
    EXPECT_EQ(states.back().force, 0.0);
    for (std::size_t i = 1; i < states.size(); ++i) EXPECT_GT(states[i].time, states[i - 1].time);
}

TEST(StepObserver, StopsARunEarlyWithTheRowsOfTheFullRunUpToThen) {
    // Force control: 0.5 N from the first jump, 0.2 N after the second at 0.05 s; stop at the second.
    class StopAfterUnloading final : public StepObserver {
    public:
        void observe(const StepState&) override {}
        bool stop(const StepState& state) override { return state.time >= 0.05 && state.force < 0.3; }
    } stop;
    const auto contact_case = creep_with_jumps();
    const auto stopped = run_case(contact_case, {}, {&stop});
    const auto full = run_case(contact_case);
    EXPECT_TRUE(stopped.stopped);
    EXPECT_LT(stopped.steps, full.steps);
    EXPECT_EQ(stopped.time.back(), 0.05);  // the state after the second jump, recorded as the last row
    EXPECT_EQ(stopped.force.back(), 0.2);  // the jump's force is the target itself
    const std::size_t kept = stopped.time.size() - 1;  // the rows before the stop's own row
    ASSERT_LE(kept, full.time.size());
    for (std::size_t i = 0; i < kept; ++i) {
        EXPECT_EQ(stopped.time[i], full.time[i]);
        EXPECT_EQ(stopped.depth[i], full.depth[i]);
        EXPECT_EQ(stopped.force[i], full.force[i]);
    }

    StopAtForce never(1.0);
    expect_same_rows(run_case(contact_case, {}, {&never}), full);
}

TEST(StepObserver, StopsAnImpactAtItsDeepestStateWithoutAnOutcome) {
    StopAtRebound stop;
    Watcher watcher;
    const auto stopped = run_case(impact(), {}, {&stop, &watcher});
    const auto full = run_case(impact());
    EXPECT_TRUE(stopped.stopped);
    EXPECT_FALSE(stopped.impact);
    EXPECT_TRUE(watcher.states.back().last);
    EXPECT_LE(stopped.velocity.back(), 0.0);
    EXPECT_EQ(stopped.depth.back(), *std::max_element(full.depth.begin(), full.depth.end()));
}

}  // namespace
}  // namespace mdr::drivers
