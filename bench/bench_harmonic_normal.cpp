// Dynamic indentation (eq. 12, 17): a sphere pre-indented into a standard solid, then 100 cycles of a harmonic
// normal displacement (and of a harmonic force, and of a harmonic base displacement through a spring) at default
// numerics: 200 steps per period, 2000 elements, the last-cycle stiffness measured.

#include <benchmark/benchmark.h>

#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"

namespace {

std::string harmonic_case(const std::string& load) {
    return R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 2.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
)" + load;
}

void run(benchmark::State& state, const std::string& text) {
    const auto contact_case = mdr::io::parse_case(text);
    std::size_t steps = 0, elements = 0;
    for (auto _ : state) {
        const auto result = mdr::drivers::run_case(contact_case);
        steps = result.steps;
        elements = result.numerics.elements;
        benchmark::DoNotOptimize(result.harmonic);
    }
    state.counters["steps"] = static_cast<double>(steps);
    state.counters["elements"] = static_cast<double>(elements);
}

// 100 cycles at 100 Hz after a 0.1 s pre-indentation to d0 = 1e-4 (a0 = 1 mm), amplitude d0 / 10.
void harmonic_displacement_100_cycles(benchmark::State& state) {
    run(state, harmonic_case(R"(control = "displacement"
history = [[0.0, 0.0], [0.1, 1.0e-4], [1.1, 1.0e-4]]
harmonic = { amplitude = 1.0e-5, frequency = 100.0, start = 0.1, end = 1.1 }
)"));
}
BENCHMARK(harmonic_displacement_100_cycles)->Unit(benchmark::kMillisecond);

void harmonic_force_100_cycles(benchmark::State& state) {
    run(state, harmonic_case(R"(control = "force"
history = [[0.0, 0.0], [0.1, 1.0], [1.1, 1.0]]
harmonic = { amplitude = 0.1, frequency = 100.0, start = 0.1, end = 1.1 }
)"));
}
BENCHMARK(harmonic_force_100_cycles)->Unit(benchmark::kMillisecond);

void harmonic_spring_100_cycles(benchmark::State& state) {
    run(state, harmonic_case(R"(control = "spring"
spring_constant = 1.0e4
history = [[0.0, 0.0], [0.1, 2.0e-4], [1.1, 2.0e-4]]
harmonic = { amplitude = 2.0e-5, frequency = 100.0, start = 0.1, end = 1.1 }
)"));
}
BENCHMARK(harmonic_spring_100_cycles)->Unit(benchmark::kMillisecond);

}  // namespace
