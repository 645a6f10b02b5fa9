// The AFM creep segment of docs/examples.md (examples/afm_creep_pause.toml: spring approach, 10 s at constant force,
// retract) at default numerics, beside the same history without the pause (the base held instead): what the
// feedback's force-controlled steps cost against spring-controlled ones.

#include <benchmark/benchmark.h>

#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"

namespace {

const std::string afm_case = R"(
units = "um-nN-s"
[material]
model = "standard"
G_inf = 0.3
G1 = 0.7
tau1 = 1.0
[indenter]
shape = "sphere"
R = 5.0
[load]
control = "spring"
spring_constant = 100.0
history = [[0.0, -0.3], [1.0, 0.25], [11.0, 0.25], [12.0, -0.75]]
)";

void run(benchmark::State& state, const std::string& text) {
    std::size_t steps = 0;
    for (auto _ : state) {
        const auto result = mdr::drivers::run_case(mdr::io::parse_case(text));
        steps = result.steps;
        benchmark::DoNotOptimize(result.depth);
    }
    state.counters["steps"] = static_cast<double>(steps);
}

void afm_creep_pause(benchmark::State& state) { run(state, afm_case + "force_pauses = [[1.0, 11.0]]\n"); }
void afm_constant_height(benchmark::State& state) { run(state, afm_case); }
BENCHMARK(afm_creep_pause)->Unit(benchmark::kMillisecond);
BENCHMARK(afm_constant_height)->Unit(benchmark::kMillisecond);

}  // namespace
