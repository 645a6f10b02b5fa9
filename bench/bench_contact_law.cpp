// The DEM contact law (include/mdr/dem/contact_law.hpp): cost per contact-step for N = 20, M = 1 and N = 50, M = 4
// over whole collisions (the overlap a half sine over 200 steps, the tangential displacement sliding and
// reversing), beside a Hertz spring F = (16/3) G sqrt(R) d^{3/2} for scale. Reported as time per contact-step.

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "mdr/dem/contact_law.hpp"

namespace {

constexpr int steps_per_contact = 200;
constexpr double radius = 0.005, peak_overlap = 4e-5, time_step = 2e-6;

double overlap_at(int n) { return peak_overlap * std::sin(3.141592653589793 * n / steps_per_contact); }
double displacement_at(int n) { return 1e-6 * std::sin(6.283185307179586 * n / steps_per_contact); }

// M relaxation branches spread over three decades around the contact time.
mdr::rheology::Rheology prony(int branches) {
    std::vector<mdr::rheology::RelaxationTerm> terms;
    for (int k = 0; k < branches; ++k) terms.push_back({1e6, 4e-5 * std::pow(10.0, 3.0 * k / std::max(branches, 2))});
    return mdr::rheology::Rheology::prony(1e6, std::move(terms));
}

void contact_law(benchmark::State& state) {
    const auto elements = static_cast<std::size_t>(state.range(0));
    const int branches = static_cast<int>(state.range(1));
    // The half-width covers the largest contact radius sqrt(R d_max) with 20 %.
    mdr::dem::ContactLaw law(prony(branches), radius, 0.3, elements, 1.2 * std::sqrt(radius * peak_overlap),
                             time_step);
    std::vector<double> contact(law.state_size());
    double sum = 0.0;
    for (auto _ : state) {
        law.initialise(contact);
        for (int n = 1; n < steps_per_contact; ++n) {
            law.advance(contact, overlap_at(n), {displacement_at(n), 0.0});
            sum += law.normal_force(contact) + law.tangential_force(contact)[0];
        }
    }
    benchmark::DoNotOptimize(sum);
    state.counters["state_doubles"] = static_cast<double>(law.state_size());
    state.counters["per_contact_step"] = benchmark::Counter(
        static_cast<double>(state.iterations()) * (steps_per_contact - 1),
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(contact_law)->ArgNames({"N", "M"})->Args({20, 1})->Args({50, 4})->Unit(benchmark::kMicrosecond);

void hertz_spring(benchmark::State& state) {
    const double stiffness = 16.0 / 3.0 * 1e6 * std::sqrt(radius);
    double sum = 0.0;
    for (auto _ : state) {
        for (int n = 1; n < steps_per_contact; ++n) {
            const double d = overlap_at(n);
            sum += stiffness * d * std::sqrt(d);
            benchmark::DoNotOptimize(sum);
        }
    }
    state.counters["per_contact_step"] = benchmark::Counter(
        static_cast<double>(state.iterations()) * (steps_per_contact - 1),
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(hertz_spring)->Unit(benchmark::kMicrosecond);

}  // namespace
