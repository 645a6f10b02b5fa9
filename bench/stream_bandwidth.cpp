// One core's memory bandwidth for the working sets of bench/lammps_pair_cost.py (docs/dem-performance.md, "Is the step
// memory-bound?"): a read pass (a sum) and a read-modify-write pass (x <- a x + b, in place, as a contact law steps
// its state) over arrays of 0.5 MB (a core's L2 holds it), 33 MB (the 20^3 lattice's mdr/visco histories) and
// 512 MB (beyond the L3). Bytes per second counts bytes read plus bytes written; take the best of repetitions (the
// host is shared):
//
//     build/bin/mdr_bench --benchmark_filter=Stream --benchmark_repetitions=5

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace {

std::vector<double> stream_array(const benchmark::State& state) {
    return std::vector<double>(static_cast<std::size_t>(state.range(0)) * 1000 / sizeof(double), 1.0);
}

void StreamRead(benchmark::State& state) {
    const auto data = stream_array(state);
    for (auto _ : state) {
        double sums[8] = {};  // eight chains, so that the adds' latency does not bound the pass
        for (std::size_t i = 0; i + 8 <= data.size(); i += 8) {
            for (std::size_t lane = 0; lane < 8; ++lane) sums[lane] += data[i + lane];
        }
        benchmark::DoNotOptimize(sums);
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(data.size() * sizeof(double)));
}

void StreamReadModifyWrite(benchmark::State& state) {
    auto data = stream_array(state);
    for (auto _ : state) {
        for (double& value : data) value = 0.999 * value + 0.001;
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(2 * data.size() * sizeof(double)));
}

// The array's size in kB: 0.5 MB, 33 MB, 512 MB.
BENCHMARK(StreamRead)->Arg(500)->Arg(33000)->Arg(512000)->Unit(benchmark::kMillisecond);
BENCHMARK(StreamReadModifyWrite)->Arg(500)->Arg(33000)->Arg(512000)->Unit(benchmark::kMillisecond);

}  // namespace
