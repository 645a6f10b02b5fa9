// The DEM contact law (include/mdr/dem/contact_law.hpp): cost per contact-step for N = 20, M = 1 and N = 50, M = 4
// over whole collisions (the overlap a half sine over 200 steps, the tangential displacement sliding and
// reversing), beside a Hertz spring F = (16/3) G sqrt(R) d^{3/2} for scale; and of a settled packing's held steps
// (374 contacts, N = 20, M = 1, friction 0.3) one by one (advance_spatial) and two at a time
// (advance_spatial_pair). Reported as time per contact-step.

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <random>
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

// A settled packing's contacts: each loaded to its overlap along its own normal, then held (the overlap wobbling by
// 1e-9 of itself, a tangential increment of 1e-10 m a step: every element sticks), stepped one by one (pairs 0) or
// in pairs (pairs 1).
void held_packing(benchmark::State& state) {
    const bool pairs = state.range(0) != 0;
    constexpr int contacts = 374;
    mdr::dem::ContactLaw law(prony(1), 1.0, 0.3, 20, 0.2, 1e-6);
    const std::size_t size = law.state_size();
    std::vector<double> states(size * contacts, 0.0);
    std::vector<mdr::dem::SpatialVector> normals(contacts);
    std::vector<double> overlaps(contacts);
    std::mt19937 random(1);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    const mdr::dem::SpatialVector increment{1e-10, -1e-10, 0.0};
    for (int c = 0; c < contacts; ++c) {
        const mdr::dem::SpatialVector direction{uniform(random), uniform(random), uniform(random)};
        const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                        direction[2] * direction[2]);
        normals[c] = {direction[0] / length, direction[1] / length, direction[2] / length};
        overlaps[c] = 5e-3 * (1.0 + 0.1 * uniform(random));
        const std::span<double> contact(states.data() + c * size, size);
        law.initialise(contact);
        for (int n = 1; n <= 200; ++n) {
            law.advance_spatial(contact, overlaps[c] * std::min(1.0, n / 100.0), normals[c], increment);
        }
    }
    double sum = 0.0;
    int step = 0;
    for (auto _ : state) {
        const double wobble = (++step % 2 == 0 ? 1e-9 : -1e-9);
        for (int c = 0; c < contacts; c += 2) {
            const mdr::dem::ContactLaw::SpatialStep first{{states.data() + c * size, size}, overlaps[c] * (1 + wobble),
                                                          normals[c], increment};
            const mdr::dem::ContactLaw::SpatialStep second{{states.data() + (c + 1) * size, size},
                                                           overlaps[c + 1] * (1 + wobble), normals[c + 1], increment};
            std::array<mdr::dem::ContactLaw::SpatialOutcome, 2> outcomes;
            if (!(pairs && law.advance_spatial_pair(first, second, outcomes))) {
                for (const auto* one : {&first, &second}) {
                    sum += law.advance_spatial(one->state, one->overlap, one->normal, one->increment)[0];
                }
                continue;
            }
            sum += outcomes[0].tangential_force[0] + outcomes[1].tangential_force[0];
        }
    }
    benchmark::DoNotOptimize(sum);
    state.counters["per_contact_step"] = benchmark::Counter(static_cast<double>(state.iterations()) * contacts,
                                                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(held_packing)->ArgNames({"pairs"})->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
