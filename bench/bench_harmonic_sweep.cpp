// A dynamic-indentation spectrum from the command line's sweep (issue 11): the case of
// examples/dynamic_indentation.toml (a sphere pre-indented to 0.1 mm in a standard solid, tau1 = 10 ms, a harmonic
// depth to 0.3 s) at 40 frequencies, log-spaced from 16 to 1600 Hz (omega tau1 = 1 to 100), as
// `mdr sweep CASE --vary load.harmonic.frequency=16:1600:40:log` runs them (io::run_sweep), on one thread and on
// every core. Wall time: the point of the sweep is the cores.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <thread>

#include "mdr/io/sweep.hpp"

namespace {

constexpr const char* dynamic_indentation = R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 2.0e6
tau1 = 0.01
[indenter]
shape = "sphere"
R = 0.01
[load]
control = "displacement"
history = [[0.0, 0.0], [0.01, 1.0e-4], [0.3, 1.0e-4]]
harmonic = { amplitude = 1.0e-7, frequency = 15.915494309189533, start = 0.01, end = 0.3 }
)";

void frequency_sweep_40(benchmark::State& state) {
    const auto jobs = static_cast<unsigned>(state.range(0));
    const std::vector<mdr::io::SweepAxis> axes{mdr::io::parse_sweep_axis("load.harmonic.frequency=16:1600:40:log")};
    std::size_t failed = 0;
    for (auto _ : state) {
        const auto rows = mdr::io::run_sweep(dynamic_indentation, "bench", axes, jobs, {});
        failed = static_cast<std::size_t>(
            std::count_if(rows.begin(), rows.end(), [](const auto& row) { return !row.error.empty(); }));
    }
    state.counters["jobs"] = jobs;
    state.counters["failed_points"] = static_cast<double>(failed);
}
BENCHMARK(frequency_sweep_40)
    ->Arg(1)
    ->Arg(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())))
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace
