// Impact (eq. 37-39): one impact at ~1e-4 accuracy in e, one at default numerics (normal and oblique), and the
// 100 x 4 restitution map of Fig. 3 on 1 and 2 threads (the map should scale with the cores).

#include <benchmark/benchmark.h>

#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/io/sweep.hpp"

namespace {

// examples/restitution_map.toml.
const std::string impact_case = R"(
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

// 200 elements and ~200 steps per contact: e within 3e-5 of its converged value (tests/verification/test_impact).
const std::string coarse_numerics = "[numerics]\nelements = 200\ntime_step = 2e-5\n";

void run_impact(benchmark::State& state, const std::string& text) {
    const auto contact_case = mdr::io::parse_case(text);
    for (auto _ : state) {
        const auto result = mdr::drivers::run_case(contact_case);
        benchmark::DoNotOptimize(result.impact->restitution);
    }
}

void impact_at_1e4(benchmark::State& state) { run_impact(state, impact_case + coarse_numerics); }
BENCHMARK(impact_at_1e4)->Unit(benchmark::kMicrosecond);

void impact_at_defaults(benchmark::State& state) { run_impact(state, impact_case); }
BENCHMARK(impact_at_defaults)->Unit(benchmark::kMillisecond);

// The same impact oblique at v_t0 = 2 mu v_n0 (issue 13: at most twice the normal impact's cost): partial slip, the
// stick zone opens and closes.
void oblique_impact_at_defaults(benchmark::State& state) {
    run_impact(state, impact_case + "tangential_velocity = 0.06\n[tangential]\nfriction = 0.3\n");
}
BENCHMARK(oblique_impact_at_defaults)->Unit(benchmark::kMillisecond);

// p1 from 1e-3 to 1e2 (tau1 = p1 / 439.56 s^-1 for this case) and p2 = 0.5, 1, 3, 9, at the coarse numerics.
void restitution_map(benchmark::State& state) {
    const std::vector<mdr::io::SweepAxis> axes{
        mdr::io::parse_sweep_axis("material.tau1=2.275e-6:0.2275:100:log"),
        mdr::io::parse_sweep_axis("material.G1=0.5e6,1e6,3e6,9e6")};
    const auto jobs = static_cast<unsigned>(state.range(0));
    for (auto _ : state) {
        const auto rows = mdr::io::run_sweep(impact_case + coarse_numerics, "map", axes, jobs, {});
        benchmark::DoNotOptimize(rows.data());
    }
}
BENCHMARK(restitution_map)->ArgName("jobs")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
