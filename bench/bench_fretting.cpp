// Fretting (section 6): a sphere held at a fixed depth in a standard solid, then 20 cycles of a harmonic
// tangential displacement, at default numerics; and the same at 2x elements, to show the cost stays linear.

#include <benchmark/benchmark.h>

#include <string>

#include <fmt/format.h>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"

namespace {

std::string fretting_case(const std::string& numerics = "") {
    return R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-4], [1.0, 1.0e-4]]
end = 3.0
[tangential]
friction = 0.3
control = "displacement"
amplitude = 5.0e-6
frequency = 10.0
start = 1.0
end = 3.0
)" + numerics;
}

void run(benchmark::State& state, const std::string& text) {
    const auto contact_case = mdr::io::parse_case(text);
    std::size_t steps = 0, elements = 0;
    for (auto _ : state) {
        const auto result = mdr::drivers::run_case(contact_case);
        steps = result.steps;
        elements = result.numerics.elements;
        benchmark::DoNotOptimize(result.tangential_force.data());
    }
    state.counters["steps"] = static_cast<double>(steps);
    state.counters["elements"] = static_cast<double>(elements);
    state.counters["step_elements"] = benchmark::Counter(static_cast<double>(state.iterations() * steps * elements),
                                                         benchmark::Counter::kIsRate);
}

void fretting_20_cycles(benchmark::State& state) { run(state, fretting_case()); }
BENCHMARK(fretting_20_cycles)->Unit(benchmark::kMillisecond);

void fretting_20_cycles_elements(benchmark::State& state) {
    run(state, fretting_case(fmt::format("[numerics]\nelements = {}\n", state.range(0))));
}
BENCHMARK(fretting_20_cycles_elements)->Arg(1000)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond);

}  // namespace
