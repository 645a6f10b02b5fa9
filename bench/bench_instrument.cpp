// Instrument files: opening a JPK force map and reading all its curves (issue 26: a 4 096-curve map in at most
// 2 s on one core). The map is built by `scripts/make_instrument_test_files.py map 4096 OUT` and named by the
// environment variable MDR_BENCH_JPK_MAP; without it the benchmarks are skipped.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "mdr/instrument/read_curves.hpp"

namespace {

std::string jpk_map() {
    const char* path = std::getenv("MDR_BENCH_JPK_MAP");
    return path != nullptr && std::filesystem::exists(path) ? path : "";
}

void instrument_open_jpk_map(benchmark::State& state) {
    const std::string path = jpk_map();
    if (path.empty()) return state.SkipWithError("MDR_BENCH_JPK_MAP names no file");
    std::size_t curves = 0;
    for (auto _ : state) curves = mdr::instrument::CurveFile(path).size();
    state.counters["curves"] = static_cast<double>(curves);
}
BENCHMARK(instrument_open_jpk_map)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

void instrument_read_jpk_map(benchmark::State& state) {
    const std::string path = jpk_map();
    if (path.empty()) return state.SkipWithError("MDR_BENCH_JPK_MAP names no file");
    std::size_t samples = 0;
    for (auto _ : state) {
        mdr::instrument::CurveFile file(path);
        samples = 0;
        for (std::size_t i = 0; i < file.size(); ++i) samples += file.read(i).force.size();
    }
    state.counters["samples"] = static_cast<double>(samples);
}
BENCHMARK(instrument_read_jpk_map)->Unit(benchmark::kSecond)->MeasureProcessCPUTime()->Iterations(1);

}  // namespace
