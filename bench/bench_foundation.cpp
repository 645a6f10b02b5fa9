// Throughput of the foundation's inner loops: element-branch updates per second for 1, 3 and 10 relaxation
// branches at 10^3 and 10^4 elements, every element in contact under a flat punch (no entry or exit events),
// and the cost of one trial force (the force-control solver calls it several times per step).

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace {

constexpr double punch_radius = 1e-3;  // m
constexpr double mean_depth = 1e-5;    // m
constexpr double depth_swing = 1e-8;   // m, small enough that every element stays in contact
constexpr double time_step = 1e-3;    // s

// A Prony series with `branches` terms of 1 MPa, relaxation times spread over decades from 10 ms.
mdr::rheology::Rheology prony_material(std::size_t branches) {
    std::vector<mdr::rheology::RelaxationTerm> terms;
    for (std::size_t k = 0; k < branches; ++k) {
        terms.push_back({1e6, 1e-2 * std::pow(10.0, 0.5 * static_cast<double>(k))});
    }
    return mdr::rheology::Rheology::prony(0.5e6, std::move(terms));
}

// A foundation of `elements` elements all under the punch, pressed to the mean depth.
struct PressedFoundation {
    mdr::rheology::Rheology material;
    std::unique_ptr<mdr::profile::Profile> punch = mdr::profile::make_flat_punch(punch_radius);
    mdr::foundation::Foundation foundation;
    mdr::foundation::StepCoefficients coefficients;

    PressedFoundation(std::size_t branches, std::size_t elements)
        : material(prony_material(branches)),
          foundation(material, *punch, punch_radius / static_cast<double>(elements), elements),
          coefficients(mdr::foundation::step_coefficients(material, time_step)) {
        foundation.begin_step(coefficients);
        foundation.advance(0.0, mean_depth);
    }
};

void set_rates(benchmark::State& state, std::size_t elements, std::size_t branches) {
    const auto iterations = static_cast<double>(state.iterations());
    state.counters["element_branch_updates"] =
        benchmark::Counter(iterations * static_cast<double>(elements * branches), benchmark::Counter::kIsRate);
    state.counters["elements"] =
        benchmark::Counter(iterations * static_cast<double>(elements), benchmark::Counter::kIsRate);
}

// One displacement-controlled step: begin_step + advance, the depth swinging around the mean.
void foundation_step(benchmark::State& state) {
    const auto branches = static_cast<std::size_t>(state.range(0));
    const auto elements = static_cast<std::size_t>(state.range(1));
    PressedFoundation pressed(branches, elements);
    double depth = mean_depth;
    double sign = 1.0;
    for (auto _ : state) {
        const double next = depth + sign * depth_swing;
        pressed.foundation.begin_step(pressed.coefficients);
        pressed.foundation.advance(depth, next);
        benchmark::DoNotOptimize(pressed.foundation.total_force());
        depth = next;
        sign = -sign;
    }
    if (pressed.foundation.contact_count() != elements) state.SkipWithError("an element left contact");
    set_rates(state, elements, branches);
}
BENCHMARK(foundation_step)->ArgNames({"branches", "elements"})->ArgsProduct({{1, 3, 10}, {1000, 10000}});

// One trial force of a prepared step, the unit of work of the force-control depth solver.
void foundation_trial_force(benchmark::State& state) {
    const auto branches = static_cast<std::size_t>(state.range(0));
    const auto elements = static_cast<std::size_t>(state.range(1));
    PressedFoundation pressed(branches, elements);
    pressed.foundation.begin_step(pressed.coefficients);
    double next = mean_depth;
    for (auto _ : state) {
        next += 1e-3 * depth_swing;
        benchmark::DoNotOptimize(pressed.foundation.trial_force(mean_depth, next));
    }
    const auto iterations = static_cast<double>(state.iterations());
    state.counters["elements"] =
        benchmark::Counter(iterations * static_cast<double>(elements), benchmark::Counter::kIsRate);
}
BENCHMARK(foundation_trial_force)->ArgNames({"branches", "elements"})->ArgsProduct({{1, 3, 10}, {1000, 10000}});

}  // namespace
