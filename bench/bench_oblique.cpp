// Oblique impact (issue 13): one oblique impact with partial slip at default numerics beside the same normal impact
// (the issue asks for at most twice its cost).

#include <benchmark/benchmark.h>

#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"

namespace {

// examples/restitution_map.toml's impact.
const std::string normal_case = R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 3.0e6
tau1 = 1.0e-3
[indenter]
shape = "sphere"
R = 0.01
mass = 3.27e-2
[load]
control = "impact"
velocity = 0.1
)";

// The same at v_t0 = 2 mu v_n0: partial slip, the stick zone opens and closes.
const std::string oblique_case = normal_case + "tangential_velocity = 0.06\n[tangential]\nfriction = 0.3\n";

void run(benchmark::State& state, const std::string& text) {
    const auto contact_case = mdr::io::parse_case(text);
    for (auto _ : state) {
        const auto result = mdr::drivers::run_case(contact_case);
        benchmark::DoNotOptimize(result.impact->restitution);
    }
}

void normal_impact_at_defaults(benchmark::State& state) { run(state, normal_case); }
BENCHMARK(normal_impact_at_defaults)->Unit(benchmark::kMillisecond);

void oblique_impact_at_defaults(benchmark::State& state) { run(state, oblique_case); }
BENCHMARK(oblique_impact_at_defaults)->Unit(benchmark::kMillisecond);

}  // namespace
