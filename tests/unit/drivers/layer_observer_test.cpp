// A caller's StepObserver on a [layer] (issue 27): run_case hands it every state of the run that gives the result, in
// time order, with the values of the result's rows (every state a row here), on Ting's path (one maximum of the
// contact radius, eq. L12), on the cells (a reload, eq. L16) and in an impact; a stop ends the run with its state,
// leaving the rows of the full run up to then.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/step_observer.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {
namespace {

// A standard solid on a bonded 1 mm layer under displacement `history`, every state a row.
ContactCase on_layer(LoadControl control, std::vector<LoadPoint> history) {
    ContactCase contact_case{.title = "layer",
                             .material = rheology::Rheology::standard(1e6, 2e6, 0.3),
                             .indenter = profile::make_sphere(0.01),
                             .control = control,
                             .load = {.history = LoadHistory(std::move(history), "load.history")},
                             .end_time = 0.0};
    contact_case.layer = contact::Layer{.thickness = 1e-3};
    contact_case.end_time = contact_case.load.history->end_time();
    contact_case.numerics.elements = 40;
    contact_case.numerics.output_every = 1;
    return contact_case;
}

ContactCase loading() { return on_layer(DisplacementControl{}, {{0.0, 0.0}, {1.0, 5e-5}, {2.0, 5e-5}}); }
ContactCase reloading() { return on_layer(DisplacementControl{}, {{0.0, 0.0}, {1.0, 5e-5}, {2.0, 2e-5}, {3.0, 6e-5}}); }
ContactCase impact() {
    auto contact_case = on_layer(ImpactControl{.mass = 1e-3, .velocity = 0.05}, {{0.0, 0.0}});
    contact_case.end_time = 0.1;
    return contact_case;
}

class Watcher final : public StepObserver {
public:
    void observe(const StepState& state) override { states.push_back(state); }
    std::vector<StepState> states;
};

// Ends the run at the first state at or after `time`.
class StopAtTime final : public StepObserver {
public:
    explicit StopAtTime(double time) : time_(time) {}
    void observe(const StepState&) override {}
    bool stop(const StepState& state) override { return state.time >= time_; }

private:
    double time_;
};

class LayerObserver : public testing::TestWithParam<ContactCase (*)()> {};

TEST_P(LayerObserver, SeesEveryStateOnceInTimeOrderWithTheRowsRecorded) {
    Watcher watcher;
    const auto result = run_case(GetParam()(), {}, {&watcher});
    const auto& states = watcher.states;
    ASSERT_EQ(states.size(), result.time.size());
    ASSERT_EQ(states.size(), result.steps + 1);
    for (std::size_t i = 0; i < states.size(); ++i) {
        EXPECT_EQ(states[i].step, i);
        EXPECT_TRUE(states[i].row);
        EXPECT_EQ(states[i].last, i + 1 == states.size());
        EXPECT_EQ(states[i].foundation, nullptr);
        EXPECT_EQ(states[i].time, result.time[i]);
        EXPECT_EQ(states[i].depth, result.depth[i]);
        EXPECT_EQ(states[i].force, result.force[i]);
        EXPECT_EQ(states[i].contact_radius, result.radius[i]);
    }
    EXPECT_FALSE(result.stopped);
}

TEST_P(LayerObserver, ChangesNothingInTheResult) {
    Watcher watcher;
    const auto observed = run_case(GetParam()(), {}, {&watcher});
    const auto plain = run_case(GetParam()());
    EXPECT_EQ(observed.time, plain.time);
    EXPECT_EQ(observed.force, plain.force);
    EXPECT_EQ(observed.radius, plain.radius);
}

TEST_P(LayerObserver, StopsTheRunWithTheRowsOfTheFullRunUpToThen) {
    const auto full = run_case(GetParam()());
    const std::size_t middle = full.time.size() / 2;
    StopAtTime stop(full.time[middle]);
    Watcher watcher;
    const auto stopped = run_case(GetParam()(), {}, {&stop, &watcher});
    EXPECT_TRUE(stopped.stopped);
    ASSERT_EQ(stopped.time.size(), middle + 1);
    EXPECT_EQ(stopped.steps, middle);
    EXPECT_FALSE(stopped.impact.has_value());
    for (std::size_t i = 0; i <= middle; ++i) {
        EXPECT_EQ(stopped.time[i], full.time[i]);
        EXPECT_EQ(stopped.force[i], full.force[i]);
    }
    ASSERT_EQ(watcher.states.size(), middle + 1);
    EXPECT_TRUE(watcher.states.back().last);
}

// Only asks to stop, as a sweep's observer: it may see the abandoned run of Ting's class before the cells' run.
class StopOnly final : public StepObserver {
public:
    void observe(const StepState& state) override { steps.push_back(state.step); }
    bool needs_one_run() const override { return false; }
    std::vector<std::size_t> steps;
};

TEST(LayerObserverOfOneRun, SeesTheCellsRunAloneWhereAnObserverWithoutTheNeedSeesTingsRunFirst) {
    Watcher watcher;
    StopOnly stop_only;
    const auto alone = run_case(reloading(), {}, {&stop_only});
    const auto both = run_case(reloading(), {}, {&stop_only, &watcher});
    ASSERT_EQ(watcher.states.size(), both.time.size());
    EXPECT_EQ(alone.force, both.force);
    // Alone it was shown the states of Ting's run up to the regrowth, then the cells' from their start.
    const auto restarts = std::count(stop_only.steps.begin(), stop_only.steps.end(), std::size_t{0});
    EXPECT_EQ(restarts, 3);  // twice alone (Ting's, the cells'), once with the watcher (the cells' only)
    EXPECT_GT(stop_only.steps.size(), 2 * both.time.size());
}

INSTANTIATE_TEST_SUITE_P(TingCellsImpact, LayerObserver, testing::Values(&loading, &reloading, &impact));

}  // namespace
}  // namespace mdr::drivers
