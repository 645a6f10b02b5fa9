// Measured curves: loading the Chiaro curve of the shared data (13 827 rows, 11 columns, raw AFM columns) with its
// checks and estimates, and the estimates alone (estimate_contact), so that the CSV reading is their difference.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "mdr/fit/curve.hpp"
#include "mdr/fitcase/curve_source.hpp"

namespace {

mdr::fitcase::CurveSource chiaro() {
    mdr::fitcase::CurveSource source;
    source.file = std::filesystem::path(MDR_MEASURED_DATA) / "chiaro_AEBP1_002.csv";
    source.time_column = "t_s";
    source.piezo_column = "z_piezo_m";
    source.deflection_column = "deflection_m";
    source.spring_constant = 0.019;
    return source;
}

void fit_load_curve(benchmark::State& state) {
    const mdr::fitcase::CurveSource source = chiaro();
    if (!std::filesystem::exists(source.file)) return state.SkipWithError("no shared data");
    std::size_t rows = 0;
    for (auto _ : state) rows = mdr::fitcase::load_curve(source).time.size();
    state.counters["rows"] = static_cast<double>(rows);
}
BENCHMARK(fit_load_curve)->Unit(benchmark::kMillisecond);

void fit_estimate_contact(benchmark::State& state) {
    const mdr::fitcase::CurveSource source = chiaro();
    if (!std::filesystem::exists(source.file)) return state.SkipWithError("no shared data");
    mdr::fit::Curve curve = mdr::fitcase::load_curve(source);
    for (auto _ : state) {
        mdr::fit::estimate_contact(curve);
        benchmark::DoNotOptimize(curve.contact_depth);
    }
}
BENCHMARK(fit_estimate_contact)->Unit(benchmark::kMillisecond);

}  // namespace
