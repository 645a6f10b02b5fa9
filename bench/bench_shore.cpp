// The Shore A test of docs/examples.md (examples/shore_a_filled_rubber.toml: a five-branch Prony series, 15 s) at
// default numerics: what one durometer reading costs (parse, the standard's indenter, the run).

#include <benchmark/benchmark.h>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"

namespace {

void shore_a_filled_rubber_15s(benchmark::State& state) {
    constexpr const char* text = R"(
[material]
model = "prony"
G_inf = 1.0e6
terms = [[1.2e6, 0.01], [0.6e6, 0.1], [0.4e6, 1.0], [0.25e6, 10.0], [0.15e6, 100.0]]
[load]
control = "shore"
scale = "A"
)";
    std::size_t steps = 0;
    for (auto _ : state) {
        const auto result = mdr::drivers::run_case(mdr::io::parse_case(text));
        steps = result.steps;
        benchmark::DoNotOptimize(result.shore_readings);
    }
    state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(shore_a_filled_rubber_15s)->Unit(benchmark::kMillisecond);

}  // namespace
