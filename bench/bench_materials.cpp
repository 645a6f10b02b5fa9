// Materials converted to a Prony series (issue 12): the power law (beta = 0.1) over 8 decades at the default
// tolerance 1e-4, a fractional Maxwell body over the same window, a table of 61 G(t) samples fitted by NNLS, and
// the run the power law serves (a sphere ramp over 1 s at default numerics: the window 1e-4 .. 1 s, 4 decades;
// the 8-decade conversion is the harder one), to compare within one run.

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "mdr/drivers/indentation.hpp"
#include "mdr/io/case_file.hpp"
#include "mdr/rheology/power_law.hpp"
#include "mdr/rheology/springpot.hpp"
#include "mdr/rheology/table_material.hpp"

namespace {

using namespace mdr::rheology;

void power_law_8_decades(benchmark::State& state) {
    const PowerLaw model{1.0e3, 0.1, 1.0};
    std::size_t terms = 0;
    for (auto _ : state) {
        const Approximation approximation = approximate(model, TimeWindow{1e-4, 1e4});
        terms = approximation.series.terms().size();
        benchmark::DoNotOptimize(approximation.certificate.error);
    }
    state.counters["terms"] = static_cast<double>(terms);
}
BENCHMARK(power_law_8_decades)->Unit(benchmark::kMicrosecond);

void fractional_maxwell_8_decades(benchmark::State& state) {
    const FractionalModel model{0.0, 1.0e4, 2.0e3, 0.1};
    for (auto _ : state) benchmark::DoNotOptimize(approximate(model, TimeWindow{1e-4, 1e4}).certificate.error);
}
BENCHMARK(fractional_maxwell_8_decades)->Unit(benchmark::kMillisecond);

void table_fit_61_points(benchmark::State& state) {
    const Rheology truth = Rheology::prony(1.0e5, {{3.0e5, 2.3e-3}, {1.0e6, 0.047}, {4.0e5, 1.9}});
    MaterialTable table{TableQuantity::relaxation, {}, {}, {}};
    for (int i = 0; i <= 60; ++i) {
        const double t = 1e-4 * std::pow(10.0, i / 10.0);
        table.abscissa.push_back(t);
        table.values.push_back(truth.relaxation(t));
    }
    for (auto _ : state) benchmark::DoNotOptimize(fit_table(table).certificate.error);
}
BENCHMARK(table_fit_61_points)->Unit(benchmark::kMillisecond);

const char* const power_law_case = R"(
[material]
model = "power_law"
G0 = 1.0e3
beta = 0.1
[indenter]
shape = "sphere"
R = 1.0e-5
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-6]]
)";

void power_law_case_parse(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(mdr::io::parse_case(power_law_case).material.terms().size());
}
BENCHMARK(power_law_case_parse)->Unit(benchmark::kMicrosecond);

void power_law_case_run(benchmark::State& state) {
    std::size_t steps = 0;
    for (auto _ : state) steps = mdr::drivers::run_indentation(mdr::io::parse_case(power_law_case)).steps;
    state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(power_law_case_run)->Unit(benchmark::kMillisecond);

}  // namespace
