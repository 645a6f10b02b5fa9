// Whole cases at default numerics (parse + run): the Ting triangle, a 20-cycle load-unload and the bundled default
// example; and the cost of the triangle over elements and steps, which should grow as elements x steps.

#include <benchmark/benchmark.h>

#include <cstddef>
#include <string>

#include <fmt/format.h>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"

namespace {

// Sphere R = 1 cm into a standard solid, 0 -> 0.1 mm -> 0 over 2 s (Ting's triangle, tests/verification).
std::string triangle_case(const std::string& numerics = "") {
    return R"(
title = "Ting triangle"
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.5
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-4], [2.0, 0.0]]
)" + numerics;
}

// Sphere into a 3-term Prony series, 0 -> 0.1 mm -> 0 twenty times, one cycle per second.
std::string cycles_case() {
    std::string history = "[0.0, 0.0]";
    for (int cycle = 0; cycle < 20; ++cycle) {
        history += fmt::format(", [{}, 1.0e-4], [{}, 0.0]", cycle + 0.5, cycle + 1.0);
    }
    return R"(
title = "20 load-unload cycles"
[material]
model = "prony"
G_inf = 0.5e6
terms = [[1.0e6, 1.0e-2], [0.8e6, 1.0e-1], [0.6e6, 1.0]]
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [)" + history + "]\n";
}

// examples/default.toml.
const char* const default_case = R"(
title = "steel sphere on rubber: load and unload"
[material]
model = "prony"
G_inf = 0.5e6
terms = [[1.0e6, 1.0e-3], [0.8e6, 1.0e-2], [0.6e6, 1.0e-1], [0.4e6, 1.0]]
[indenter]
shape = "sphere"
R = 5.0e-3
[load]
control = "displacement"
history = [[0.0, 0.0], [0.5, 2.0e-4], [1.0, 0.0]]
[output]
snapshots = [0.25, 0.5, 0.6]
)";

// Runs `toml` once per iteration; reports steps, elements and steps x elements per second.
void run_case(benchmark::State& state, const std::string& toml) {
    std::size_t steps = 0;
    std::size_t elements = 0;
    for (auto _ : state) {
        const auto result = mdr::drivers::run_indentation(mdr::io::parse_case(toml));
        steps = result.steps;
        elements = result.numerics.elements;
        benchmark::DoNotOptimize(result.force.data());
    }
    const auto iterations = static_cast<double>(state.iterations());
    state.counters["steps"] = static_cast<double>(steps);
    state.counters["elements"] = static_cast<double>(elements);
    state.counters["step_elements"] =
        benchmark::Counter(iterations * static_cast<double>(steps * elements), benchmark::Counter::kIsRate);
}

void case_ting_triangle(benchmark::State& state) { run_case(state, triangle_case()); }
BENCHMARK(case_ting_triangle)->Unit(benchmark::kMillisecond);

void case_twenty_cycles(benchmark::State& state) { run_case(state, cycles_case()); }
BENCHMARK(case_twenty_cycles)->Unit(benchmark::kMillisecond);

void case_default_example(benchmark::State& state) { run_case(state, default_case); }
BENCHMARK(case_default_example)->Unit(benchmark::kMillisecond);

// The triangle (2 s long) with `elements` elements and `steps` steps; complexity against elements x steps.
void triangle_scaling(benchmark::State& state) {
    const auto elements = state.range(0);
    const auto steps = state.range(1);
    run_case(state, triangle_case(fmt::format("[numerics]\nelements = {}\ntime_step = {}\n", elements,
                                              2.0 / static_cast<double>(steps))));
    state.SetComplexityN(elements * steps);
}
BENCHMARK(triangle_scaling)
    ->ArgNames({"elements", "steps"})
    ->Args({1000, 1000})
    ->Args({2000, 1000})
    ->Args({4000, 1000})
    ->Args({8000, 1000})
    ->Args({2000, 2000})
    ->Args({2000, 4000})
    ->Args({2000, 8000})
    ->Complexity(benchmark::oN)
    ->Unit(benchmark::kMillisecond);

}  // namespace
