// Fits (mdr::fit) of rebound data e(v0): six impacts of a 10 g sphere (R = 10 mm) on a standard solid (G_inf = 1 MPa
// known, G1 = 3 MPa and tau1 = 1 ms free, started at 1 MPa and 3 ms), with and without the contact times, and the
// cost of one rebound impact at the fit's resolution. A fit costs its runs (one impact each: speeds x (1 + free
// parameters) per Jacobian) x the impact's time (`ms_per_run`).

#include <benchmark/benchmark.h>

#include <ctime>
#include <string>
#include <vector>

#include "mdr/fit/fit.hpp"
#include "mdr/fitcase/fit_case.hpp"
#include "mdr/fitcase/fit_case_run.hpp"

namespace {

// v0 [m/s], e, T [s] of the impact ODE (tests/support/reference/impact_ode.hpp) for the true material, as
// tests/cli/test_fit_rebound.py.
const std::vector<double> speeds{0.01, 0.025, 0.063, 0.16, 0.4, 1.0};
const std::vector<double> restitution{0.46350225373785503, 0.49280879724736437, 0.52989496325044505,
                                      0.57156247077271038, 0.61411456549911214, 0.65634187118429865};
const std::vector<double> contact_time{4.2031936840719544e-3, 3.3525438785399593e-3, 2.7052631626027814e-3,
                                       2.201352842638062e-3,  1.8101798037382471e-3, 1.4956086714586481e-3};

const char* fit_case_text = R"(
[material]
model = "standard"
G_inf = 1.0e6
G1 = 1.0e6
tau1 = 3.0e-3
[indenter]
shape = "sphere"
R = 0.01
mass = 0.01
[fit]
free = ["material.G1", "material.tau1"]
)";

void run_fit(benchmark::State& state, bool with_times) {
    const auto fit_case = mdr::fitcase::parse_fit_case(fit_case_text, "bench", ".");
    mdr::fit::ReboundArrays arrays{.name = "drops", .mass = 0.01, .velocity = speeds, .restitution = restitution};
    arrays.restitution_error = {0.005};
    if (with_times) {
        arrays.contact_time = contact_time;
        arrays.contact_time_error = {2e-5};
    }
    const auto problem = mdr::fitcase::make_problem(fit_case, {}, {mdr::fit::make_rebound(arrays)});
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
    state.counters["ms_per_run"] =
        1e3 * cpu_seconds / static_cast<double>(state.iterations()) / static_cast<double>(result.evaluations);
}

void BM_FitRebound(benchmark::State& state) { run_fit(state, false); }
BENCHMARK(BM_FitRebound)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_FitReboundWithContactTimes(benchmark::State& state) { run_fit(state, true); }
BENCHMARK(BM_FitReboundWithContactTimes)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
