// Fits (mdr::fit) of synthetic load-hold-unload curves: a standard solid and a 3-term Prony series, the issue's
// targets (2000 points: <= 50 ms and <= 200 ms of CPU), and how a fit's cost grows with the curve's points and the
// model's elements. Each fit reports its forward-model runs (`runs`) and the CPU time per run (`ms_per_run`): a fit
// costs runs x (points x elements). bench/classic_fit.py times the classic scipy Lee-Radok fit of the same curve.

#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

#include "mdr/drivers/indentation.hpp"
#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"

namespace {

// The synthetic curve (also bench/classic_fit.py): sphere R = 10 um; the depth approaches from -0.4 um over 0.2 s,
// loads to 2 um over 0.5 s, holds 1 s and unloads to 0 over 0.5 s; `points` rows, uniform in time; Gaussian noise of
// 1 nN (about 0.7 % of the peak force) and a force baseline of 5 nN.
constexpr double radius = 10e-6;
constexpr double noise = 1e-9;
constexpr double baseline = 5e-9;

double depth_at(double t) {
    if (t < 0.2) return -0.4e-6 + 2e-6 * t;
    if (t < 0.7) return 4e-6 * (t - 0.2);
    if (t < 1.7) return 2e-6;
    return 2e-6 - 4e-6 * (t - 1.7);
}

std::string standard_solid(double g_inf, double g1, double tau1) {
    return "[material]\nmodel = \"standard\"\nG_inf = " + std::to_string(g_inf) + "\nG1 = " + std::to_string(g1) +
           "\ntau1 = " + std::to_string(tau1) + "\n";
}

std::string prony3(double scale) {
    return "[material]\nmodel = \"prony\"\nG_inf = " + std::to_string(1e3 * scale) + "\nterms = [[" +
           std::to_string(2e3 * scale) + ", 0.02], [" + std::to_string(1.5e3 * scale) + ", 0.2], [" +
           std::to_string(1e3 * scale) + ", 1.0]]\n";
}

std::string fit_case_text(const std::string& material, const std::string& free) {
    return material + "[indenter]\nshape = \"sphere\"\nR = 1.0e-5\n[fit]\nbaseline = \"fit\"\nfree = [" + free + "]\n";
}

// The measured curve: the exact model (2000 elements) at the true material, with noise and baseline.
mdr::fit::Curve synthetic_curve(const std::string& true_material, std::size_t points) {
    const auto truth = mdr::fitcase::parse_fit_case(fit_case_text(true_material, "\"material.G_inf\""), "bench", ".");
    mdr::drivers::ContactCase model = truth.model.build();
    std::vector<double> time(points), depth(points), force(points);
    std::vector<mdr::drivers::LoadPoint> history{{-1e-3, 0.0}};
    for (std::size_t i = 0; i < points; ++i) {
        time[i] = 2.2 * static_cast<double>(i) / static_cast<double>(points - 1);
        depth[i] = depth_at(time[i]);
        history.push_back({time[i], std::max(depth[i], 0.0)});
    }
    model.load.history = mdr::drivers::LoadHistory(std::move(history), "load.history");
    model.end_time = time.back();
    model.numerics.elements = 2000;
    model.numerics.time_step = 2.2 / static_cast<double>(points - 1);
    const auto result = mdr::drivers::run_case(model);
    std::mt19937 generator(7);
    std::normal_distribution<double> gaussian(0.0, noise);
    std::size_t row = 0;
    for (std::size_t i = 0; i < points; ++i) {
        while (row + 1 < result.time.size() && result.time[row + 1] <= time[i]) ++row;
        force[i] = result.force[row] + baseline + gaussian(generator);
    }
    return mdr::fit::make_curve("synthetic", std::move(time), std::move(depth), std::move(force));
}

void run_fit(benchmark::State& state, const std::string& true_material, const std::string& start_material,
             const std::string& free) {
    const auto points = static_cast<std::size_t>(state.range(0));
    const auto elements = static_cast<std::size_t>(state.range(1));
    auto fit_case = mdr::fitcase::parse_fit_case(fit_case_text(start_material, free), "bench", ".");
    fit_case.settings.elements = elements;
    const auto problem = mdr::fitcase::make_problem(fit_case, {synthetic_curve(true_material, points)});
    mdr::fit::FitResult result;
    double cpu_seconds = 0.0;
    for (auto _ : state) {
        const std::clock_t begin = std::clock();
        result = mdr::fit::fit(problem);
        cpu_seconds += static_cast<double>(std::clock() - begin) / CLOCKS_PER_SEC;
        benchmark::DoNotOptimize(result.values.data());
    }
    if (!result.converged) state.SkipWithError(result.status.c_str());
    state.counters["runs"] = static_cast<double>(result.evaluations);
    state.counters["iterations"] = static_cast<double>(result.iterations);
    state.counters["residual_to_noise"] = result.rms_residual / result.noise;
    state.counters["noise_nN"] = result.noise * 1e9;
    state.counters["ms_per_run"] =
        1e3 * cpu_seconds / static_cast<double>(state.iterations()) / static_cast<double>(result.evaluations);
}

// Standard solid G_inf = 1 kPa, G1 = 2 kPa, tau1 = 0.2 s, fitted from start values off by 2x and 0.5x; contact point
// and baseline fitted too (`baseline = "fit"`, as measured in docs/performance.md; the default is "constant").
void BM_FitStandardSolid(benchmark::State& state) {
    run_fit(state, standard_solid(1e3, 2e3, 0.2), standard_solid(2e3, 1e3, 0.5),
            "\"material.G_inf\", \"material.G1\", \"material.tau1\"");
}
BENCHMARK(BM_FitStandardSolid)
    ->ArgNames({"points", "elements"})
    ->Args({2000, 1000})
    ->Args({500, 1000})
    ->Args({8000, 1000})
    ->Args({2000, 250})
    ->Args({2000, 4000})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

// 3-term Prony series G_inf = 1 kPa, (2 kPa, 0.02 s), (1.5 kPa, 0.2 s), (1 kPa, 1 s), from moduli off by 2x and times
// 0.05, 0.5, 3 s: seven parameters.
void BM_FitProny3(benchmark::State& state) {
    const std::string start = "[material]\nmodel = \"prony\"\nG_inf = 2000.0\n"
                              "terms = [[1000.0, 0.05], [3000.0, 0.5], [2000.0, 3.0]]\n";
    std::string free = "\"material.G_inf\"";
    for (int i = 0; i < 3; ++i) {
        free += ", \"material.terms[" + std::to_string(i) + "][0]\", \"material.terms[" + std::to_string(i) + "][1]\"";
    }
    run_fit(state, prony3(1.0), start, free);
}
BENCHMARK(BM_FitProny3)->ArgNames({"points", "elements"})->Args({2000, 1000})->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
