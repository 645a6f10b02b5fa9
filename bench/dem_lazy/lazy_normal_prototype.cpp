// Prototype (issue 29, not used by the library): an O(M) normal step for a DEM contact whose touched elements are
// all in contact, measured against the Foundation's step it would replace.
//
// The rule. Over a step the overlap goes linearly from d0 to d1. An element in contact over the whole step follows
// the indenter, w = d - g_i (eq. 13), so its increment is dw = d1 - d0 for every such element, and each branch
// memory takes the same affine map h <- E_k h + B_k dw (the exact update, numerics notes eq. 16 and 18, with
// E_k and B_k from foundation::StepCoefficients). Kept per branch: the composition h = A_k h^ + B_k of those maps
// since the last materialisation (h^ the memories then, left in the state), and S_k = sum over the elements in
// contact of h^. Then sigma_i = G_inf (d1 - g_i) + eta dw/dt + sum_k G_k (A_k h^_k,i + B_k) (eq. 16) and
// F = 8 dx sum_i sigma_i (eq. 21) = 8 dx [G_inf (n d1 - sum g_i) + n eta dw/dt + sum_k G_k (A_k S_k + n B_k)]: O(M).
// The exit rule (eq. 20: an element leaves when it would need a tensile force) is checked on every element in
// contact, exactly as the Foundation does, by one read-only pass: min_i (sum_k G_k A_k h^_k,i - G_inf g_i) plus
// the common part >= 0. A step that is not of this kind (an element would leave or be reached, a touched element
// is free, a composition factor falls below 1e-150) materialises the state (h = A h^ + B, w = d - g_i, sigma) and
// is taken by the Foundation itself (attach, begin_step, advance): its entries, exits and split sub-steps are not
// duplicated here.
//
//     lazy_normal_prototype compare            # each scenario: forces against the Foundation's at every step
//     valgrind --tool=callgrind --toggle-collect='*step_foundation*' --toggle-collect='*step_lazy*'
//         lazy_normal_prototype count held     # one line; then callgrind_annotate --inclusive=yes
//
// Scenarios (sphere R = 5 mm, N = 20 elements on 1.2 sqrt(R d_max), d_max = 40 um, dt = 2 us, as
// bench/bench_contact_law.cpp): `held` loads over 100 steps and holds for 1000, `slow` loads linearly from
// d_max / 5 to d_max over 1000 steps, `impact` is a half sine over 200 steps, `cycles` five partial unloadings.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "mdr/foundation/foundation.hpp"
#include "mdr/foundation/step_coefficients.hpp"
#include "mdr/profile/profile.hpp"
#include "mdr/rheology/rheology.hpp"

namespace {

using mdr::foundation::Foundation;
using mdr::rheology::Rheology;

constexpr double radius = 0.005, peak_overlap = 4e-5, time_step = 2e-6;
constexpr std::size_t elements = 20;
constexpr double normal_stiffness_factor = 4.0;  // k_z = 4 G dx, eq. (11)
constexpr double smallest_scale = 1e-150;        // a composition factor below: materialise

double half_width() { return 1.2 * std::sqrt(radius * peak_overlap); }

// Whether every element i < count keeps a compressive end stress, sum_k weight_k h^_k,i - G_inf g_i + common >= 0
// (h^ branch-major, `stride` apart; eq. 20). Passes of restrict pointers and an integer count, so that GCC 12
// vectorises them (a floating-point min reduction it leaves scalar).
__attribute__((noinline, target_clones("avx2", "default"))) bool all_compressive(
    std::size_t count, std::size_t branches, std::size_t stride, double g_inf, double common,
    const double* __restrict g, const double* __restrict hat, const double* __restrict weight,
    double* __restrict scratch) {
    for (std::size_t i = 0; i < count; ++i) scratch[i] = common - g_inf * g[i];
    for (std::size_t k = 0; k < branches; ++k) {
        const double* __restrict h = hat + k * stride;
        const double factor = weight[k];
        for (std::size_t i = 0; i < count; ++i) scratch[i] += factor * h[i];
    }
    std::int64_t tensile = 0;
    for (std::size_t i = 0; i < count; ++i) tensile += scratch[i] >= 0.0 ? 0 : 1;
    return tensile == 0;
}

// One contact's normal problem stepped lazily while every touched element is in contact, else by the Foundation.
// The state is the Foundation's (Foundation::state_size); in the lazy form its memories hold h^ and its w, sigma
// are stale until materialise().
class LazyNormalContact {
public:
    LazyNormalContact(const Rheology& material, std::size_t count, double spacing)
        : material_(material),
          foundation_(material, *mdr::profile::make_sphere(radius), spacing, count),
          coefficients_(mdr::foundation::step_coefficients(material, time_step)),
          state_(Foundation::state_size(count, material.terms().size()), 0.0),
          scale_(material.terms().size(), 1.0),
          shift_(material.terms().size(), 0.0),
          hat_sum_(material.terms().size(), 0.0),
          hat_floor_(material.terms().size(), 0.0),
          weight_(material.terms().size(), 0.0),
          scratch_(count, 0.0),
          deepest_(mdr::foundation::deepest_depth(*mdr::profile::make_sphere(radius), spacing * double(count))) {
        foundation_.reserve_events();
    }

    // One step to `overlap`; returns the normal force.
    __attribute__((noinline)) double step_lazy(double overlap) {
        if (!try_lazy(overlap)) step_eager(overlap);
        return state_[1];
    }
    // Brings w, sigma and h up to date in the state (h = A h^ + B) and restarts the composition.
    void materialise();
    std::span<const double> state() const { return state_; }
    std::size_t lazy_steps = 0, eager_steps = 0, element_passes = 0;

private:
    bool try_lazy(double overlap);
    void step_eager(double overlap);
    void restart_composition();
    std::size_t active() const { return static_cast<std::size_t>(state_[2]); }

    Rheology material_;
    Foundation foundation_;
    mdr::foundation::StepCoefficients coefficients_;
    std::vector<double> state_;
    std::vector<double> scale_, shift_;  // A_k, B_k
    std::vector<double> hat_sum_;        // S_k = sum over the elements in contact of h^_k,i
    std::vector<double> hat_floor_;      // min over the elements in contact of h^_k,i
    std::vector<double> weight_, scratch_;
    double profile_sum_ = 0.0;  // sum over the elements in contact of g_i
    double outermost_ = 0.0;    // max over the elements in contact of g_i
    double contacts_ = 0.0;     // elements in contact; the lazy form needs all touched ones in contact
    double rate_ = 0.0;         // dw/dt of the last lazy step (its dashpot's share of sigma)
    bool all_in_contact_ = true;
    bool stale_ = false;
    double deepest_;
};

bool LazyNormalContact::try_lazy(double overlap) {
    const std::size_t n = foundation_.size(), touched = active();
    const auto g = foundation_.equivalent_profile();
    // Not lazy: a touched element free, a new element reached (Foundation::reach: g_i < d), the end of the
    // foundation reached (the Foundation throws).
    if (!all_in_contact_ || (touched < n && g[touched] < overlap) || overlap > deepest_) return false;
    const auto& terms = material_.terms();
    const std::size_t branches = terms.size();
    const double depth = state_[0], increment = overlap - depth;
    const double rate = increment / coefficients_.time_step;
    // The composed maps after this step and the stress part common to every element in contact (eq. 16).
    double common = material_.equilibrium_modulus() * overlap + material_.viscosity() * rate;
    double smallest_scale_now = 1.0;
    for (std::size_t k = 0; k < branches; ++k) {
        const double scale = coefficients_.decay[k] * scale_[k];
        const double shift = coefficients_.decay[k] * shift_[k] + coefficients_.gain[k] * increment;
        common += terms[k].modulus * shift;
        weight_[k] = terms[k].modulus * scale;
        smallest_scale_now = std::min(smallest_scale_now, scale);
    }
    // The exit rule (eq. 20) on every element in contact: a lower bound of their end stresses first (G_k A_k > 0:
    // each sum_k G_k A_k h^_k,i - G_inf g_i is at least sum_k G_k A_k min_i h^_k,i - G_inf max_i g_i), O(M); where
    // it is negative, each element's. Both exact: the bound only decides whether the pass is needed.
    double lower = common - material_.equilibrium_modulus() * outermost_;
    for (std::size_t k = 0; k < branches; ++k) lower += weight_[k] * hat_floor_[k];
    if (touched > 0 && !(lower >= 0.0)) {
        ++element_passes;
        const double* hat = state_.data() + 3 + 3 * n;
        // An exit inside the step: the Foundation splits it.
        if (!all_compressive(touched, branches, n, material_.equilibrium_modulus(), common, g.data(), hat,
                             weight_.data(), scratch_.data())) {
            return false;
        }
    }
    double sum = contacts_ * common - material_.equilibrium_modulus() * profile_sum_;
    for (std::size_t k = 0; k < branches; ++k) {
        scale_[k] *= coefficients_.decay[k];
        shift_[k] = coefficients_.decay[k] * shift_[k] + coefficients_.gain[k] * increment;
        sum += weight_[k] * hat_sum_[k];
    }
    state_[0] = overlap;
    state_[1] = 2.0 * normal_stiffness_factor * foundation_.spacing() * sum;  // eq. 21, both halves
    rate_ = rate;
    stale_ = true;
    ++lazy_steps;
    if (smallest_scale_now < smallest_scale) materialise();
    return true;
}

void LazyNormalContact::materialise() {
    if (!stale_) return;
    const std::size_t n = foundation_.size(), touched = active(), branches = material_.terms().size();
    const auto g = foundation_.equivalent_profile();
    const double depth = state_[0];
    double* w = state_.data() + 3;
    double* sigma = w + n;
    double* h = w + 3 * n;
    for (std::size_t i = 0; i < touched; ++i) {  // all in contact (the lazy form's condition)
        w[i] = depth - g[i];
        sigma[i] = material_.equilibrium_modulus() * w[i] + material_.viscosity() * rate_;
    }
    for (std::size_t k = 0; k < branches; ++k) {
        const double modulus = material_.terms()[k].modulus;
        for (std::size_t i = 0; i < touched; ++i) {
            h[k * n + i] = scale_[k] * h[k * n + i] + shift_[k];
            sigma[i] += modulus * h[k * n + i];
        }
    }
    restart_composition();
}

void LazyNormalContact::restart_composition() {
    const std::size_t n = foundation_.size(), touched = active(), branches = material_.terms().size();
    const auto g = foundation_.equivalent_profile();
    const double* flags = state_.data() + 3 + 2 * n;
    const double* h = state_.data() + 3 + 3 * n;
    std::fill(scale_.begin(), scale_.end(), 1.0);
    std::fill(shift_.begin(), shift_.end(), 0.0);
    contacts_ = profile_sum_ = outermost_ = 0.0;
    for (std::size_t i = 0; i < touched; ++i) {
        contacts_ += flags[i];
        profile_sum_ += flags[i] * g[i];
        if (flags[i] != 0.0) outermost_ = std::max(outermost_, g[i]);
    }
    for (std::size_t k = 0; k < branches; ++k) {
        hat_sum_[k] = 0.0;
        hat_floor_[k] = contacts_ > 0.0 ? INFINITY : 0.0;
        for (std::size_t i = 0; i < touched; ++i) {
            hat_sum_[k] += flags[i] * h[k * n + i];
            if (flags[i] != 0.0) hat_floor_[k] = std::min(hat_floor_[k], h[k * n + i]);
        }
    }
    all_in_contact_ = contacts_ == static_cast<double>(touched);
    stale_ = false;
}

void LazyNormalContact::step_eager(double overlap) {
    materialise();
    const double depth = state_[0];
    foundation_.attach(state_);
    foundation_.begin_step(coefficients_);
    foundation_.advance(depth, overlap);
    restart_composition();
    ++eager_steps;
}

// The law's normal step as ContactLaw does it now: the state attached and stepped in place by the Foundation.
class FoundationContact {
public:
    FoundationContact(const Rheology& material, std::size_t count, double spacing)
        : foundation_(material, *mdr::profile::make_sphere(radius), spacing, count),
          coefficients_(mdr::foundation::step_coefficients(material, time_step)),
          state_(Foundation::state_size(count, material.terms().size()), 0.0) {
        foundation_.reserve_events();
    }
    __attribute__((noinline)) double step_foundation(double overlap) {
        const double depth = state_[0];
        foundation_.attach(state_);
        foundation_.begin_step(coefficients_);
        foundation_.advance(depth, overlap);
        return state_[1];
    }
    std::span<const double> state() const { return state_; }

private:
    Foundation foundation_;
    mdr::foundation::StepCoefficients coefficients_;
    std::vector<double> state_;
};

struct Scenario {
    const char* name;
    int steps;
    std::function<double(int)> overlap;
};

std::vector<Scenario> scenarios() {
    const double pi = 3.141592653589793;
    return {
        {"held", 1100, [=](int n) { return peak_overlap * std::sin(0.5 * pi * std::min(n, 100) / 100.0); }},
        {"slow", 1000, [=](int n) { return peak_overlap * (0.2 + 0.8 * n / 1000.0); }},
        {"impact", 200, [=](int n) { return peak_overlap * std::sin(pi * n / 200.0); }},
        {"cycles", 1000,
         [=](int n) { return peak_overlap * (0.75 + 0.25 * std::cos(2.0 * pi * n / 200.0)) * std::min(1.0, n / 50.0); }},
    };
}

std::vector<Rheology> materials() {
    return {Rheology::standard(1e6, 1e6, 1e-4),                                // the law's bench, M = 1
            Rheology(1e6, 20.0, {{1e6, 1e-4}, {5e5, 3e-3}}),                  // a dashpot, M = 2
            Rheology::prony(1e6, {{1e6, 4e-5}, {1e6, 1.3e-3}, {1e6, 4e-2}})};  // bench_contact_law's M = 3
}

int compare() {
    int failures = 0;
    for (const Rheology& material : materials()) {
        for (const Scenario& scenario : scenarios()) {
            const double spacing = half_width() / elements;
            FoundationContact reference(material, elements, spacing);
            LazyNormalContact lazy(material, elements, spacing);
            double largest = 0.0, deviation = 0.0;
            for (int n = 1; n <= scenario.steps; ++n) {
                const double d = scenario.overlap(n);
                const double expected = reference.step_foundation(d), got = lazy.step_lazy(d);
                largest = std::max(largest, std::abs(expected));
                deviation = std::max(deviation, std::abs(got - expected));
            }
            lazy.materialise();
            double state_deviation = 0.0, state_scale = 0.0;
            const std::size_t n = elements;
            bool same_flags = true;
            for (std::size_t j = 3; j < reference.state().size(); ++j) {
                const double expected = reference.state()[j], got = lazy.state()[j];
                if (j >= 3 + n && j < 3 + 2 * n) continue;  // sigma: compared through the forces
                if (j >= 3 + 2 * n && j < 3 + 3 * n) {      // the contact flags: the same
                    same_flags = same_flags && got == expected;
                    continue;
                }
                state_scale = std::max(state_scale, std::abs(expected));  // w and h [m]
                state_deviation = std::max(state_deviation, std::abs(got - expected));
            }
            const double relative = deviation / largest, state_relative = state_deviation / state_scale;
            const bool ok = relative <= 1e-12 && state_relative <= 1e-12 && same_flags;
            failures += ok ? 0 : 1;
            std::printf("M=%zu eta=%-4g %-7s steps %5d lazy %5zu (element passes %4zu) eager %4zu  "
                        "max|dF|/max|F| %.2e  state %.2e  %s\n",
                        material.terms().size(), material.viscosity(), scenario.name, scenario.steps,
                        lazy.lazy_steps, lazy.element_passes, lazy.eager_steps, relative, state_relative,
                        ok ? "ok" : "FAIL");
        }
    }
    return failures == 0 ? 0 : 1;
}

// Steps both forms through one scenario (for callgrind: their step functions' inclusive counts per step).
int count(const std::string& name, std::size_t branches) {
    const auto all = scenarios();
    const auto found = std::find_if(all.begin(), all.end(), [&](const Scenario& s) { return name == s.name; });
    if (found == all.end()) return 2;
    const auto material = materials()[branches <= 1 ? 0 : branches == 2 ? 1 : 2];
    const double spacing = half_width() / elements;
    FoundationContact reference(material, elements, spacing);
    LazyNormalContact lazy(material, elements, spacing);
    double sum = 0.0;
    for (int n = 1; n <= found->steps; ++n) {
        const double d = found->overlap(n);
        sum += reference.step_foundation(d) - lazy.step_lazy(d);
    }
    std::printf("%s: %d steps, lazy %zu (element passes %zu), eager %zu, sum of differences %.3e\n", found->name,
                found->steps, lazy.lazy_steps, lazy.element_passes, lazy.eager_steps, sum);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::strcmp(argv[1], "compare") == 0) return compare();
    if (argc >= 3 && std::strcmp(argv[1], "count") == 0) {
        return count(argv[2], argc >= 4 ? static_cast<std::size_t>(std::stoul(argv[3])) : 1);
    }
    std::fprintf(stderr, "usage: lazy_normal_prototype compare | count held|slow|impact|cycles [M]\n");
    return 2;
}
