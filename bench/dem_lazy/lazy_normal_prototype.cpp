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

// Whether no element i < count enters or leaves contact over the step: one in contact (flag 1) keeps a
// compressive end stress, common - G_inf g_i + sum_k weight_k h^_k,i >= 0 (eq. 20), a free one stays clear of the
// indenter, g_i + row_0 w^_i + sum_k row_(k+1) h^_k,i >= depth (eq. 14). w^, h^ branch-major, `stride` apart.
// Passes of restrict pointers and an integer count, so that GCC 12 vectorises them (a floating-point min reduction
// it leaves scalar).
__attribute__((noinline, target_clones("avx2", "default"))) bool no_event(
    std::size_t count, std::size_t branches, std::size_t stride, double g_inf, double common, double depth,
    const double* __restrict g, const double* __restrict flags, const double* __restrict w,
    const double* __restrict hat, const double* __restrict weight, const double* __restrict row,
    double* __restrict contact_part, double* __restrict free_part) {
    for (std::size_t i = 0; i < count; ++i) {
        contact_part[i] = common - g_inf * g[i];
        free_part[i] = g[i] - depth + row[0] * w[i];
    }
    for (std::size_t k = 0; k < branches; ++k) {
        const double* __restrict h = hat + k * stride;
        const double contact_factor = weight[k], free_factor = row[k + 1];
        for (std::size_t i = 0; i < count; ++i) {
            contact_part[i] += contact_factor * h[i];
            free_part[i] += free_factor * h[i];
        }
    }
    std::int64_t events = 0;
    for (std::size_t i = 0; i < count; ++i) events += (flags[i] != 0.0 ? contact_part[i] : free_part[i]) >= 0.0 ? 0 : 1;
    return events == 0;
}

// One contact's normal problem stepped lazily while no element enters or leaves contact, else by the Foundation.
// The state is the Foundation's (Foundation::state_size). In the lazy form an element in contact has h = A h^ + B
// (its memories in the state are h^, its w and sigma stale) and a free one (w, h) = P (w^, h^): the force-free
// update (Foundation::begin_step and plain_step: dw = -(G_inf w + sum_k G_k E_k h_k + [eta > 0] (G_inf w +
// sum_k G_k h_k)) / K_free, h_k <- E_k h_k + B_k dw) is the same linear map F for every free element, and P the
// product of those since the last materialisation.
class LazyNormalContact {
public:
    LazyNormalContact(const Rheology& material, std::size_t count, double spacing);

    // One step to `overlap`; returns the normal force.
    __attribute__((noinline)) double step_lazy(double overlap) {
        if (!try_lazy(overlap)) step_eager(overlap);
        return state_[1];
    }
    // Brings w, sigma and h up to date in the state and restarts the composition.
    void materialise();
    std::span<const double> state() const { return state_; }
    std::size_t lazy_steps = 0, eager_steps = 0, element_passes = 0;

private:
    bool try_lazy(double overlap);
    void step_eager(double overlap);
    void restart_composition();
    std::size_t active() const { return static_cast<std::size_t>(state_[2]); }
    std::size_t order() const { return scale_.size() + 1; }  // (w, h_1 .. h_M)

    Rheology material_;
    Foundation foundation_;
    mdr::foundation::StepCoefficients coefficients_;
    std::vector<double> state_;
    std::vector<double> scale_, shift_;  // A_k, B_k
    std::vector<double> hat_sum_;        // S_k = sum over the elements in contact of h^_k,i
    std::vector<double> hat_floor_;      // min over the elements in contact of h^_k,i
    std::vector<double> weight_;         // G_k A_k of the step being taken
    std::vector<double> free_step_;      // F, row-major (M + 1)^2
    std::vector<double> free_map_;       // P, row-major
    std::vector<double> next_map_;       // F P of the step being taken
    std::vector<double> free_floor_, free_ceiling_;  // min and max over the free elements of (w^, h^_k)
    std::vector<double> contact_part_, free_part_, column_;
    double profile_sum_ = 0.0;   // sum over the elements in contact of g_i
    double outermost_ = 0.0;     // max over the elements in contact of g_i
    double innermost_free_ = 0.0;  // min over the free elements of g_i
    double contacts_ = 0.0;      // elements in contact
    double free_ = 0.0;          // touched elements out of contact
    double rate_ = 0.0;          // dw/dt of the last lazy step (its dashpot's share of sigma)
    bool stale_ = false;
    double deepest_;
};

LazyNormalContact::LazyNormalContact(const Rheology& material, std::size_t count, double spacing)
    : material_(material),
      foundation_(material, *mdr::profile::make_sphere(radius), spacing, count),
      coefficients_(mdr::foundation::step_coefficients(material, time_step)),
      state_(Foundation::state_size(count, material.terms().size()), 0.0),
      scale_(material.terms().size(), 1.0),
      shift_(material.terms().size(), 0.0),
      hat_sum_(material.terms().size(), 0.0),
      hat_floor_(material.terms().size(), 0.0),
      weight_(material.terms().size(), 0.0),
      free_floor_(material.terms().size() + 1, 0.0),
      free_ceiling_(material.terms().size() + 1, 0.0),
      contact_part_(count, 0.0),
      free_part_(count, 0.0),
      column_(material.terms().size() + 1, 0.0),
      deepest_(mdr::foundation::deepest_depth(*mdr::profile::make_sphere(radius), spacing * double(count))) {
    foundation_.reserve_events();
    // F = D + u c^T: D = diag(1, E_k), u = (1, B_k), c the force-free increment's coefficients (see the class).
    const auto& terms = material.terms();
    const std::size_t m = order();
    const double g_inf = material.equilibrium_modulus(), eta = material.viscosity();
    const double dashpot = eta > 0.0 ? 1.0 : 0.0;
    const double free_stiffness = coefficients_.stiffness + eta / coefficients_.time_step;  // G_inf + sum G_k B_k
                                                                                          // + 2 eta / dt
    std::vector<double> diagonal(m, 1.0), gain(m, 1.0), increment(m, 0.0);
    increment[0] = -g_inf * (1.0 + dashpot) / free_stiffness;
    for (std::size_t k = 0; k < terms.size(); ++k) {
        diagonal[k + 1] = coefficients_.decay[k];
        gain[k + 1] = coefficients_.gain[k];
        increment[k + 1] = -terms[k].modulus * (coefficients_.decay[k] + dashpot) / free_stiffness;
    }
    free_step_.assign(m * m, 0.0);
    for (std::size_t r = 0; r < m; ++r) {
        for (std::size_t j = 0; j < m; ++j) free_step_[r * m + j] = (r == j ? diagonal[r] : 0.0) + gain[r] * increment[j];
    }
    free_map_.assign(m * m, 0.0);
    next_map_.assign(m * m, 0.0);
    for (std::size_t r = 0; r < m; ++r) free_map_[r * m + r] = 1.0;
}

__attribute__((noinline)) bool LazyNormalContact::try_lazy(double overlap) {
    const std::size_t n = foundation_.size(), touched = active(), m = order();
    const auto g = foundation_.equivalent_profile();
    // Not lazy: a new element reached (Foundation::reach: g_i < d), the end of the foundation reached (the
    // Foundation throws).
    if ((touched < n && g[touched] < overlap) || overlap > deepest_) return false;
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
    double largest_map = 0.0;
    if (free_ > 0.0) {  // P <- F P
        for (std::size_t r = 0; r < m; ++r) {
            for (std::size_t j = 0; j < m; ++j) {
                double entry = 0.0;
                for (std::size_t l = 0; l < m; ++l) entry += free_step_[r * m + l] * free_map_[l * m + j];
                next_map_[r * m + j] = entry;
                largest_map = std::max(largest_map, std::abs(entry));
            }
        }
    }
    // The exit rule (eq. 20) on the elements in contact and the entry rule (eq. 14) on the free ones: lower bounds
    // first, O(M^2) (G_k A_k > 0: each element's sum_k G_k A_k h^_k,i - G_inf g_i is at least sum_k G_k A_k
    // min_i h^_k,i - G_inf max_i g_i; likewise each free surface g_i + w_i from the extremes of w^, h^ by the signs
    // of P's first row); where one is negative, each element's. Both exact: the bounds only decide whether the pass
    // is needed.
    bool certain = true;
    if (contacts_ > 0.0) {
        double lower = common - material_.equilibrium_modulus() * outermost_;
        for (std::size_t k = 0; k < branches; ++k) lower += weight_[k] * hat_floor_[k];
        certain = lower >= 0.0;
    }
    if (certain && free_ > 0.0) {
        double lower = innermost_free_ - overlap;
        for (std::size_t j = 0; j < m; ++j) {
            lower += next_map_[j] * (next_map_[j] >= 0.0 ? free_floor_[j] : free_ceiling_[j]);
        }
        certain = lower >= 0.0;
    }
    if (!certain) {
        ++element_passes;
        const double* w = state_.data() + 3;
        const double* free_row = free_ > 0.0 ? next_map_.data() : free_map_.data();
        if (!no_event(touched, branches, n, material_.equilibrium_modulus(), common, overlap, g.data(), w + 2 * n,
                      w, w + 3 * n, weight_.data(), free_row, contact_part_.data(), free_part_.data())) {
            return false;  // an entry or exit inside the step: the Foundation splits it
        }
    }
    double sum = contacts_ * common - material_.equilibrium_modulus() * profile_sum_;
    for (std::size_t k = 0; k < branches; ++k) {
        scale_[k] *= coefficients_.decay[k];
        shift_[k] = coefficients_.decay[k] * shift_[k] + coefficients_.gain[k] * increment;
        sum += weight_[k] * hat_sum_[k];
    }
    if (free_ > 0.0) free_map_.swap(next_map_);
    state_[0] = overlap;
    state_[1] = 2.0 * normal_stiffness_factor * foundation_.spacing() * sum;  // eq. 21, both halves
    rate_ = rate;
    stale_ = true;
    ++lazy_steps;
    if (smallest_scale_now < smallest_scale || (free_ > 0.0 && largest_map < smallest_scale)) materialise();
    return true;
}

void LazyNormalContact::materialise() {
    if (!stale_) return;
    const std::size_t n = foundation_.size(), touched = active(), branches = material_.terms().size(), m = order();
    const auto g = foundation_.equivalent_profile();
    const double depth = state_[0];
    double* w = state_.data() + 3;
    double* sigma = w + n;
    const double* flags = w + 2 * n;
    double* h = w + 3 * n;
    for (std::size_t i = 0; i < touched; ++i) {
        if (flags[i] != 0.0) {  // h = A h^ + B, w = d - g_i, sigma (eq. 16)
            w[i] = depth - g[i];
            sigma[i] = material_.equilibrium_modulus() * w[i] + material_.viscosity() * rate_;
            for (std::size_t k = 0; k < branches; ++k) {
                h[k * n + i] = scale_[k] * h[k * n + i] + shift_[k];
                sigma[i] += material_.terms()[k].modulus * h[k * n + i];
            }
            continue;
        }
        column_[0] = w[i];  // (w, h) = P (w^, h^), force-free
        for (std::size_t k = 0; k < branches; ++k) column_[k + 1] = h[k * n + i];
        for (std::size_t r = 0; r < m; ++r) {
            double entry = 0.0;
            for (std::size_t j = 0; j < m; ++j) entry += free_map_[r * m + j] * column_[j];
            (r == 0 ? w[i] : h[(r - 1) * n + i]) = entry;
        }
        sigma[i] = 0.0;
    }
    restart_composition();
}

void LazyNormalContact::restart_composition() {
    const std::size_t n = foundation_.size(), touched = active(), branches = material_.terms().size(), m = order();
    const auto g = foundation_.equivalent_profile();
    const double* w = state_.data() + 3;
    const double* flags = w + 2 * n;
    const double* h = w + 3 * n;
    std::fill(scale_.begin(), scale_.end(), 1.0);
    std::fill(shift_.begin(), shift_.end(), 0.0);
    std::fill(free_map_.begin(), free_map_.end(), 0.0);
    for (std::size_t r = 0; r < m; ++r) free_map_[r * m + r] = 1.0;
    contacts_ = free_ = profile_sum_ = outermost_ = 0.0;
    innermost_free_ = INFINITY;
    std::fill(hat_sum_.begin(), hat_sum_.end(), 0.0);
    std::fill(hat_floor_.begin(), hat_floor_.end(), INFINITY);
    std::fill(free_floor_.begin(), free_floor_.end(), INFINITY);
    std::fill(free_ceiling_.begin(), free_ceiling_.end(), -INFINITY);
    for (std::size_t i = 0; i < touched; ++i) {
        if (flags[i] != 0.0) {
            contacts_ += 1.0;
            profile_sum_ += g[i];
            outermost_ = std::max(outermost_, g[i]);
            for (std::size_t k = 0; k < branches; ++k) {
                hat_sum_[k] += h[k * n + i];
                hat_floor_[k] = std::min(hat_floor_[k], h[k * n + i]);
            }
            continue;
        }
        free_ += 1.0;
        innermost_free_ = std::min(innermost_free_, g[i]);
        for (std::size_t j = 0; j < m; ++j) {
            const double value = j == 0 ? w[i] : h[(j - 1) * n + i];
            free_floor_[j] = std::min(free_floor_[j], value);
            free_ceiling_[j] = std::max(free_ceiling_[j], value);
        }
    }
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
