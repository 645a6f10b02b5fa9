// A caller's StepObserver on a [layer] (issue 27): run_case hands it every state of the run that gives the result, in
// time order, with the values of the result's rows (every state a row here), on Ting's path (one maximum of the
// contact radius, eq. L12), on the cells (a reload, eq. L16) and in an impact; a stop ends the run with its state,
// leaving the rows of the full run up to then. An observer that needs one run is shown Ting's states once that run
// has ended in Ting's class (one run, not a run without observers first); its stop ends the result as one asked at
// once.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "mdr/contact/layer.hpp"
#include "mdr/drivers/indentation.hpp"
#include "mdr/drivers/step_observer.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/io/case_file.hpp"
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
        EXPECT_EQ(states[i].contact_radius(), result.radius[i]);
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

// The progress of a run on a layer is the half-space's report (ProgressReport, in the one loop run_stepping): the
// fraction of the state observed (StepState::fraction), each time another hundredth of the run is done (an impact's
// against its expected end of contact, impact_progress). Before, the layer's drivers reported their own way: an
// impact at every step, a history (i + 1) / nodes after state i, which no state says.
TEST(LayerProgress, ReportsTheObservedFractionEachHundredthAsOnTheHalfSpace) {
    auto on_cells = reloading();
    on_cells.numerics.cells_from_start = true;
    for (const ContactCase& contact_case : {loading(), on_cells, impact()}) {
        Watcher watcher;
        std::vector<double> fractions;
        const auto result = run_case(contact_case, [&](double fraction) { fractions.push_back(fraction); }, {&watcher});
        ASSERT_GT(result.steps, 100u);  // more states than reports
        ASSERT_FALSE(fractions.empty());
        EXPECT_LE(fractions.size(), 100u);
        EXPECT_EQ(std::adjacent_find(fractions.begin(), fractions.end(), std::greater_equal<>()), fractions.end());
        for (const double fraction : fractions) {
            EXPECT_TRUE(std::any_of(watcher.states.begin(), watcher.states.end(),
                                    [&](const StepState& state) { return state.fraction == fraction; }))
                << fraction;
        }
    }
}

// A history's last state has fraction 1, which the report reaches: on a layer (Ting's path, the cells) and on the
// half-space, with more than 100 states (a sum of hundredths, 0.01 added 100 times, exceeds 1: the report counted
// that way left 1 out after a state past 0.99). An impact's, once its contact has ended (before, its time over the
// time limit, which it never reached).
TEST(LayerProgress, EndsAtOneWhereTheRunEnds) {
    auto on_cells = reloading();
    on_cells.numerics.cells_from_start = true;
    auto half_space = loading();
    half_space.layer.reset();
    for (const ContactCase& contact_case : {loading(), on_cells, half_space, impact()}) {
        std::vector<double> fractions;
        const auto result = run_case(contact_case, [&](double fraction) { fractions.push_back(fraction); });
        ASSERT_GT(result.steps, 100u);
        ASSERT_FALSE(fractions.empty());
        EXPECT_EQ(fractions.back(), 1.0) << contact_case.title;
    }
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

// The progress reports of a run: one run of Ting's class reports each hundredth of its grid once.
std::size_t progress_reports(const ContactCase& contact_case, const StepObservers& observers) {
    std::size_t reports = 0;
    run_case(contact_case, [&](double) { ++reports; }, observers);
    return reports;
}

TEST(LayerObserverOfOneRun, RunsTingsClassOnceAndShowsItsStatesOnce) {
    // Before, an observer that needs one run made Ting's class run twice (once without observers, to find whether
    // the contact grows again): twice the reports.
    Watcher watcher;
    const std::size_t unobserved = progress_reports(loading(), {});
    EXPECT_EQ(progress_reports(loading(), {&watcher}), unobserved);
    const auto result = run_case(loading());
    ASSERT_EQ(watcher.states.size(), result.steps + 1);
    for (std::size_t i = 0; i < watcher.states.size(); ++i) EXPECT_EQ(watcher.states[i].step, i);
}

// numerics.max_memory counts what the run would hold (estimate_work) and, with an observer that needs one run, a copy
// of each of the states of Ting's class kept for it (StateLog: sizeof(StepState) bytes a state, one a node of the
// grid), before they are kept. Before, the bound counted 16 bytes a step and the copies not at all: the run with the
// watcher ran.
TEST(LayerObserverOfOneRun, KeepsItsStatesOnlyWithinTheMemoryBound) {
    auto contact_case = loading();
    const auto plain = run_case(contact_case);  // Ting's class throughout (no observer: nothing kept)
    const double states = static_cast<double>(plain.steps + 1);
    const double state_bytes = static_cast<double>(sizeof(StepState));
    const double run_memory = estimate_work(contact_case, resolve_numerics(contact_case)).memory;
    ASSERT_GT(states * state_bytes, 1000.0);
    contact_case.numerics.max_memory = run_memory + states * state_bytes - 1000.0;
    EXPECT_NO_THROW(run_case(contact_case));  // the run itself is within the bound
    Watcher watcher;
    try {
        run_case(contact_case, {}, {&watcher});
        ADD_FAILURE() << "a run whose kept states exceed numerics.max_memory ran";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "numerics.max_memory");
    }
    EXPECT_TRUE(watcher.states.empty());  // refused before the run
    contact_case.numerics.max_memory = run_memory + states * state_bytes;  // room for them all
    const auto observed = run_case(contact_case, {}, {&watcher});
    EXPECT_EQ(watcher.states.size(), plain.steps + 1);
    EXPECT_EQ(observed.force, plain.force);
}

// Ends the run at step `step`; `at_once` says it needs no one run (asked at once on Ting's class, as a sweep's).
class StopAtStep final : public StepObserver {
public:
    StopAtStep(std::size_t step, bool at_once) : step_(step), at_once_(at_once) {}
    void observe(const StepState&) override {}
    bool stop(const StepState& state) override { return state.step == step_; }
    bool needs_one_run() const override { return !at_once_; }

private:
    std::size_t step_;
    bool at_once_;
};

// Cases of Ting's class with rows every third state, snapshots or Shore readings, stopped between rows.
ContactCase spring_with_snapshots() {  // the base driven in, then held: the contact grows as the layer creeps
    auto contact_case = on_layer(SpringControl{.spring_constant = 200.0}, {{0.0, 0.0}, {1.0, 8e-5}, {2.0, 8e-5}});
    contact_case.snapshots = {0.4, 0.5, 1.2, 1.9};
    contact_case.numerics.output_every = 3;
    contact_case.numerics.time_step = 0.02;
    return contact_case;
}
ContactCase shore_on_sheet() {
    return io::parse_case(
        "[material]\nmodel = \"standard\"\nG_inf = 1.0e6\nG1 = 1.0e6\ntau1 = 2.0\n[load]\ncontrol = \"shore\"\n"
        "scale = \"A\"\n[layer]\nthickness = 6e-3\ninterface = \"bonded\"\n[numerics]\noutput_every = 3\n");
}

class LayerStopShownOnce : public testing::TestWithParam<ContactCase (*)()> {};

TEST_P(LayerStopShownOnce, EndsTheResultAtItsStateAsAStopAskedAtOnce) {
    Watcher every_state;
    const auto full = run_case(GetParam()(), {}, {&every_state});
    const std::size_t later = 2 * every_state.states.size() / 3;
    const std::size_t end = later % 3 == 0 ? later + 1 : later;  // not a row of its own (every third)
    const StepState& at_end = every_state.states[end];
    StopAtStep once(end, false), at_once(end, true);
    const auto replayed = run_case(GetParam()(), {}, {&once});
    const auto live = run_case(GetParam()(), {}, {&at_once});
    // Independent of the live stop: the full run's rows up to the state, then the state itself.
    const std::size_t rows = end / 3 + 1;  // steps 0, 3, 6, ... up to the stop's
    ASSERT_EQ(replayed.time.size(), rows + 1);
    for (std::size_t i = 0; i < rows; ++i) {
        EXPECT_EQ(replayed.time[i], full.time[i]);
        EXPECT_EQ(replayed.force[i], full.force[i]);
    }
    EXPECT_EQ(replayed.time.back(), at_end.time);
    EXPECT_EQ(replayed.depth.back(), at_end.depth);
    EXPECT_EQ(replayed.force.back(), at_end.force);
    EXPECT_EQ(replayed.radius.back(), at_end.contact_radius());
    EXPECT_EQ(replayed.steps, end);
    EXPECT_TRUE(replayed.stopped);
    // As the stop asked at once.
    EXPECT_TRUE(live.stopped);
    EXPECT_EQ(replayed.steps, live.steps);
    EXPECT_EQ(replayed.time, live.time);
    EXPECT_EQ(replayed.depth, live.depth);
    EXPECT_EQ(replayed.force, live.force);
    EXPECT_EQ(replayed.radius, live.radius);
    EXPECT_EQ(replayed.base, live.base);
    EXPECT_EQ(replayed.shore, live.shore);
    ASSERT_EQ(replayed.shore_readings.size(), live.shore_readings.size());
    for (std::size_t n = 0; n < live.shore_readings.size(); ++n) {
        EXPECT_EQ(replayed.shore_readings[n].time, live.shore_readings[n].time);
        EXPECT_EQ(replayed.shore_readings[n].reading, live.shore_readings[n].reading);
    }
    ASSERT_EQ(replayed.snapshots.size(), live.snapshots.size());
    for (std::size_t n = 0; n < live.snapshots.size(); ++n) {
        EXPECT_EQ(replayed.snapshots[n].time, live.snapshots[n].time);
        EXPECT_EQ(replayed.snapshots[n].pressure, live.snapshots[n].pressure);
    }
    // Some of the full run's snapshots or readings fall after the stop, some before.
    EXPECT_LT(live.snapshots.size() + live.shore_readings.size(), full.snapshots.size() + full.shore_readings.size());
    EXPECT_GT(live.snapshots.size() + live.shore_readings.size(), 0u);
}

INSTANTIATE_TEST_SUITE_P(SpringShore, LayerStopShownOnce, testing::Values(&spring_with_snapshots, &shore_on_sheet));

}  // namespace
}  // namespace mdr::drivers
