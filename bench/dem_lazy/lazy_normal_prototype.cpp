// Prototype (issue 29, not used by the library): an O(M) normal step for a DEM contact, measured against the
// Foundation's step it would replace (docs/dem.md, "Speed").
//
// The rule. Over a step the overlap goes linearly from d0 to d1. An element in contact over the whole step follows
// the indenter, w = d - g_i (eq. 13), so its increment is dw = d1 - d0 for every such element, and each branch
// memory takes the same affine map h <- E_k h + B_k dw (the exact update, numerics notes eq. 16 and 18, E_k and B_k
// from foundation::StepCoefficients). Kept per branch: the composition h = A_k h^ + B_k of those maps since the
// last materialisation (h^ the memories then, left in the state) and S_k, the sum of h^ over the elements in
// contact. Then sigma_i = G_inf (d1 - g_i) + eta dw/dt + sum_k G_k (A_k h^_k,i + B_k) (eq. 16) and
// F = 8 dx sum_i sigma_i (eq. 21) = 8 dx [G_inf (n d1 - sum g_i) + n eta dw/dt + sum_k G_k (A_k S_k + n B_k)]: O(M).
// A free (force-free, creeping) element's update (Foundation::begin_step and plain_step: dw = -(G_inf w +
// sum_k G_k E_k h_k + [eta > 0] (G_inf w + sum_k G_k h_k)) / K_free, h_k <- E_k h_k + B_k dw) is one linear map F
// of (w, h) for every free element: kept is P, the product of those maps, (w, h) = P (w^, h^): O(M^2).
// The exit rule (eq. 20: an element in contact leaves when it would need a tensile force) and the entry rule (eq. 14:
// the indenter reaches a free element's surface) are checked on every touched element exactly as the Foundation
// does: lower bounds first, O(M^2), and where one is negative each element's by a read-only pass. A step with an
// entry or exit (or a composition factor below 1e-150) materialises the state (w, sigma, h) and is taken by the
// Foundation itself (attach, begin_step, advance): its split sub-steps are not duplicated here.
//
//     lazy_normal_prototype compare            # each scenario: forces against the Foundation's at every step
//     valgrind --tool=callgrind --toggle-collect='*step_foundation*' --toggle-collect='*step_lazy*'
//         --toggle-collect='*step_law*' lazy_normal_prototype count held 1   # one line; then callgrind_annotate
//                                                                          # --inclusive=yes
//
// Scenarios (sphere R = 5 mm, N = 20 elements on 1.2 sqrt(R d_max), d_max = 40 um, dt = 2 us, as
// bench/bench_contact_law.cpp): `held` loads over 100 steps and holds for 1000, `slow` loads linearly from
// d_max / 5 to d_max over 1000 steps, `impact` is a half sine over 200 steps, `long` holds for 40000 steps (400
// relaxation times) with a ripple of 1e-3, `cycles` five partial unloadings.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "mdr/dem/contact_law.hpp"
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

// Calls `kernel` with the branch count as a constant for M = 1, 2, 3 (its loops over the branches unrolled, the
// loop over the elements vectorised), else as a number.
template <class Kernel>
inline __attribute__((always_inline)) auto with_branches(std::size_t branches, Kernel kernel) {
    switch (branches) {
        case 1: return kernel(std::integral_constant<std::size_t, 1>{});
        case 2: return kernel(std::integral_constant<std::size_t, 2>{});
        case 3: return kernel(std::integral_constant<std::size_t, 3>{});
        default: return kernel(branches);
    }
}

// The state of one contact's elements in the Foundation's layout (Foundation::state_size): w, sigma, flags, then
// h branch-major, `stride` apart.
struct Elements {
    double* w;
    double* sigma;
    double* flags;
    double* h;
    std::size_t stride;
};

// Whether no element i < count enters or leaves contact over the step: one in contact keeps a compressive end
// stress, common - G_inf g_i + sum_k weight_k h^_k,i >= 0 (eq. 20), a free one stays clear of the indenter,
// g_i + row_0 w^_i + sum_k row_(k+1) h^_k,i >= depth (eq. 14). Read only; an integer count, so that it vectorises
// (GCC leaves a floating-point min reduction scalar).
__attribute__((noinline, target_clones("avx2", "default"))) bool no_event(
    std::size_t count, std::size_t branches, const Elements& state, double g_inf, double common, double depth,
    const double* __restrict g, const double* __restrict weight, const double* __restrict row) {
    return with_branches(branches, [&](auto m) {
        const double* __restrict w = state.w;
        const double* __restrict flags = state.flags;
        const double* __restrict h = state.h;
        const std::size_t stride = state.stride;
        std::int64_t events = 0;
        for (std::size_t i = 0; i < count; ++i) {
            double contact = common - g_inf * g[i];
            double free = g[i] - depth + row[0] * w[i];
            for (std::size_t k = 0; k < m; ++k) {
                contact += weight[k] * h[k * stride + i];
                free += row[k + 1] * h[k * stride + i];
            }
            events += (flags[i] != 0.0 ? contact : free) >= 0.0 ? 0 : 1;
        }
        return events == 0;
    });
}

// The state brought up to date in place: an element in contact w = depth - g_i, h_k = scale_k h^_k + shift_k,
// sigma = G_inf w + dashpot + sum_k G_k h_k (eq. 16); a free one (w, h) = P (w^, h^) (`map` row-major, order
// M + 1), sigma = 0. The new memories go through `fresh` (M count doubles): each reads all of the old ones.
__attribute__((noinline, target_clones("avx2", "default"))) void materialise_elements(
    std::size_t count, std::size_t branches, const Elements& state, double depth, double g_inf, double dashpot,
    const double* __restrict g, const double* __restrict moduli, const double* __restrict scale,
    const double* __restrict shift, const double* __restrict map, double* __restrict fresh) {
    with_branches(branches, [&](auto m) {
        const std::size_t order = m + 1, stride = state.stride;
        double* __restrict w = state.w;
        double* __restrict sigma = state.sigma;
        const double* __restrict flags = state.flags;
        double* __restrict h = state.h;
        for (std::size_t i = 0; i < count; ++i) {
            const bool contact = flags[i] != 0.0;
            double free_w = map[0] * w[i];
            for (std::size_t j = 1; j < order; ++j) free_w += map[j] * h[(j - 1) * stride + i];
            const double contact_w = depth - g[i];
            double stress = g_inf * contact_w + dashpot;
            for (std::size_t k = 0; k < m; ++k) {
                double free_h = map[(k + 1) * order] * w[i];
                for (std::size_t j = 1; j < order; ++j) free_h += map[(k + 1) * order + j] * h[(j - 1) * stride + i];
                const double contact_h = scale[k] * h[k * stride + i] + shift[k];
                stress += moduli[k] * contact_h;
                fresh[k * count + i] = contact ? contact_h : free_h;
            }
            w[i] = contact ? contact_w : free_w;
            sigma[i] = contact ? stress : 0.0;
        }
        for (std::size_t k = 0; k < m; ++k) {
            for (std::size_t i = 0; i < count; ++i) h[k * stride + i] = fresh[k * count + i];
        }
    });
}

// What the lazy step needs of the elements i < count, from the state as it stands (fresh: h^ = h, w^ = w).
struct Summary {
    double contacts = 0.0;         // elements in contact
    double free = 0.0;             // touched elements out of contact
    double profile_sum = 0.0;      // sum of g_i over the elements in contact
    double outermost = 0.0;        // max g_i over the elements in contact
    double innermost_free = 0.0;   // min g_i over the free elements
};

Summary summarise(std::size_t count, std::size_t branches, const Elements& state, const double* g, double* hat_sum,
                  double* hat_floor, double* free_floor, double* free_ceiling) {
    Summary summary;
    summary.innermost_free = INFINITY;
    std::fill(hat_sum, hat_sum + branches, 0.0);
    std::fill(hat_floor, hat_floor + branches, INFINITY);
    std::fill(free_floor, free_floor + branches + 1, INFINITY);
    std::fill(free_ceiling, free_ceiling + branches + 1, -INFINITY);
    for (std::size_t i = 0; i < count; ++i) {
        if (state.flags[i] != 0.0) {
            summary.contacts += 1.0;
            summary.profile_sum += g[i];
            summary.outermost = std::max(summary.outermost, g[i]);
            for (std::size_t k = 0; k < branches; ++k) {
                const double h = state.h[k * state.stride + i];
                hat_sum[k] += h;
                hat_floor[k] = std::min(hat_floor[k], h);
            }
            continue;
        }
        summary.free += 1.0;
        summary.innermost_free = std::min(summary.innermost_free, g[i]);
        for (std::size_t j = 0; j <= branches; ++j) {
            const double value = j == 0 ? state.w[i] : state.h[(j - 1) * state.stride + i];
            free_floor[j] = std::min(free_floor[j], value);
            free_ceiling[j] = std::max(free_ceiling[j], value);
        }
    }
    return summary;
}

// One contact's normal problem stepped lazily while no element enters or leaves contact, else by the Foundation.
// The state is the Foundation's; in the lazy form its w, h of an element hold w^, h^ and its sigma is stale.
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
    std::size_t lazy_steps = 0, eager_steps = 0, element_passes = 0, renormalisations = 0;

private:
    bool try_lazy(double overlap);
    template <class Branches>
    bool try_lazy_with(double overlap, Branches branches);  // the branch count a constant or a number
    void step_eager(double overlap);
    void bring_up_to_date();  // w, sigma, h in the state from the composition (which then no longer holds)
    void restart_composition();
    std::size_t active() const { return static_cast<std::size_t>(state_[2]); }
    Elements elements_view() {
        const std::size_t n = foundation_.size();
        double* w = state_.data() + 3;
        return {w, w + n, w + 2 * n, w + 3 * n, n};
    }

    Rheology material_;
    Foundation foundation_;
    mdr::foundation::StepCoefficients coefficients_;
    std::size_t branches_;
    std::vector<double> state_;
    std::vector<double> moduli_;         // G_k
    std::vector<double> scale_, shift_;  // A_k, B_k
    std::vector<double> hat_sum_;        // S_k = sum over the elements in contact of h^_k,i
    std::vector<double> hat_floor_;      // min over the elements in contact of h^_k,i
    std::vector<double> weight_;         // G_k A_k of the step being taken
    std::vector<double> free_diagonal_, free_gain_, free_increment_;  // F = diag(D) + u c^T (see the file's top)
    std::vector<double> free_map_;       // P, row-major, order M + 1
    std::vector<double> next_map_;       // F P of the step being taken
    std::vector<double> free_floor_, free_ceiling_;  // min and max over the free elements of (w^, h^_k)
    std::vector<double> fresh_;          // materialise_elements' new memories
    Summary summary_;
    double rate_ = 0.0;  // dw/dt of the last lazy step (its dashpot's share of sigma)
    bool stale_ = false;
    double deepest_;
};

LazyNormalContact::LazyNormalContact(const Rheology& material, std::size_t count, double spacing)
    : material_(material),
      foundation_(material, *mdr::profile::make_sphere(radius), spacing, count),
      coefficients_(mdr::foundation::step_coefficients(material, time_step)),
      branches_(material.terms().size()),
      state_(Foundation::state_size(count, branches_), 0.0),
      scale_(branches_, 1.0),
      shift_(branches_, 0.0),
      hat_sum_(branches_, 0.0),
      hat_floor_(branches_, 0.0),
      weight_(branches_, 0.0),
      free_diagonal_(branches_ + 1, 1.0),
      free_gain_(branches_ + 1, 1.0),
      free_increment_(branches_ + 1, 0.0),
      free_map_((branches_ + 1) * (branches_ + 1), 0.0),
      next_map_((branches_ + 1) * (branches_ + 1), 0.0),
      free_floor_(branches_ + 1, 0.0),
      free_ceiling_(branches_ + 1, 0.0),
      fresh_(branches_ * count, 0.0),
      deepest_(mdr::foundation::deepest_depth(*mdr::profile::make_sphere(radius), spacing * double(count))) {
    foundation_.reserve_events();
    const auto& terms = material.terms();
    const double eta = material.viscosity(), dashpot = eta > 0.0 ? 1.0 : 0.0;
    // K_free = G_inf + sum_k G_k B_k + 2 eta / dt (Foundation::begin_step's free_stiffness_).
    const double free_stiffness = coefficients_.stiffness + eta / coefficients_.time_step;
    free_increment_[0] = -material.equilibrium_modulus() * (1.0 + dashpot) / free_stiffness;
    for (std::size_t k = 0; k < branches_; ++k) {
        moduli_.push_back(terms[k].modulus);
        free_diagonal_[k + 1] = coefficients_.decay[k];
        free_gain_[k + 1] = coefficients_.gain[k];
        free_increment_[k + 1] = -terms[k].modulus * (coefficients_.decay[k] + dashpot) / free_stiffness;
    }
    for (std::size_t r = 0; r <= branches_; ++r) free_map_[r * (branches_ + 1) + r] = 1.0;
}

__attribute__((noinline)) bool LazyNormalContact::try_lazy(double overlap) {
    return with_branches(branches_, [&](auto branches) { return try_lazy_with(overlap, branches); });
}

template <class Branches>
bool LazyNormalContact::try_lazy_with(double overlap, Branches branches) {
    const std::size_t n = foundation_.size(), touched = active(), m = branches + 1;
    const double* g = foundation_.equivalent_profile().data();
    // Not lazy: a new element reached (Foundation::reach: g_i < d), the end of the foundation reached (the
    // Foundation throws).
    if ((touched < n && g[touched] < overlap) || overlap > deepest_) return false;
    // The workspace's arrays, distinct vectors: restrict pointers, so that no store reloads them.
    const double* __restrict decay = coefficients_.decay.data();
    const double* __restrict gain = coefficients_.gain.data();
    const double* __restrict moduli = moduli_.data();
    double* __restrict weight = weight_.data();
    double* __restrict scale = scale_.data();
    double* __restrict shift = shift_.data();
    const double* __restrict map = free_map_.data();
    double* __restrict next = next_map_.data();
    const double g_inf = material_.equilibrium_modulus();
    const double depth = state_[0], increment = overlap - depth;
    const double rate = increment / coefficients_.time_step;
    const Summary summary = summary_;
    // The composed maps after this step and the stress part common to every element in contact (eq. 16).
    double common = g_inf * overlap + material_.viscosity() * rate;
    double smallest_scale_now = 1.0;
    for (std::size_t k = 0; k < branches; ++k) {
        common += moduli[k] * (decay[k] * shift[k] + gain[k] * increment);
        weight[k] = moduli[k] * decay[k] * scale[k];
        smallest_scale_now = std::min(smallest_scale_now, decay[k] * scale[k]);
    }
    const bool free = summary.free > 0.0;
    double largest_map = 0.0;
    if (free) {  // P <- F P = D P + u (c^T P)
        const double* __restrict diagonal = free_diagonal_.data();
        const double* __restrict unit_gain = free_gain_.data();
        const double* __restrict free_increment = free_increment_.data();
        for (std::size_t j = 0; j < m; ++j) {
            double projection = 0.0;
            for (std::size_t l = 0; l < m; ++l) projection += free_increment[l] * map[l * m + j];
            for (std::size_t r = 0; r < m; ++r) {
                next[r * m + j] = diagonal[r] * map[r * m + j] + unit_gain[r] * projection;
                largest_map = std::max(largest_map, std::abs(next[r * m + j]));
            }
        }
    }
    // Lower bounds of the elements' end stresses and free gaps (G_k A_k > 0: each sum_k G_k A_k h^_k,i - G_inf g_i
    // is at least sum_k G_k A_k min_i h^_k,i - G_inf max_i g_i; each free surface g_i + w_i likewise from the
    // extremes of w^, h^ by the signs of P's first row); where one is negative, each element's (no_event). Both
    // exact: the bounds only decide whether the pass is needed.
    bool certain = true;
    if (summary.contacts > 0.0) {
        double lower = common - g_inf * summary.outermost;
        for (std::size_t k = 0; k < branches; ++k) lower += weight[k] * hat_floor_[k];
        certain = lower >= 0.0;
    }
    if (certain && free) {
        double lower = summary.innermost_free - overlap;
        for (std::size_t j = 0; j < m; ++j) lower += next[j] * (next[j] >= 0.0 ? free_floor_[j] : free_ceiling_[j]);
        certain = lower >= 0.0;
    }
    if (!certain) {
        ++element_passes;
        if (!no_event(touched, branches, elements_view(), g_inf, common, overlap, g, weight, free ? next : map)) {
            return false;  // an entry or exit inside the step: the Foundation splits it
        }
    }
    double sum = summary.contacts * common - g_inf * summary.profile_sum;
    for (std::size_t k = 0; k < branches; ++k) {
        scale[k] *= decay[k];
        shift[k] = decay[k] * shift[k] + gain[k] * increment;
        sum += weight[k] * hat_sum_[k];
    }
    if (free) free_map_.swap(next_map_);
    state_[0] = overlap;
    state_[1] = 2.0 * normal_stiffness_factor * foundation_.spacing() * sum;  // eq. 21, both halves
    rate_ = rate;
    stale_ = true;
    ++lazy_steps;
    if (smallest_scale_now < smallest_scale || (free && largest_map < smallest_scale)) {
        ++renormalisations;
        materialise();
    }
    return true;
}

void LazyNormalContact::bring_up_to_date() {
    if (!stale_) return;
    materialise_elements(active(), branches_, elements_view(), state_[0], material_.equilibrium_modulus(),
                         material_.viscosity() * rate_, foundation_.equivalent_profile().data(), moduli_.data(),
                         scale_.data(), shift_.data(), free_map_.data(), fresh_.data());
    stale_ = false;
}

void LazyNormalContact::materialise() {
    if (!stale_) return;
    bring_up_to_date();
    restart_composition();
}

void LazyNormalContact::restart_composition() {
    const std::size_t m = branches_ + 1;
    std::fill(scale_.begin(), scale_.end(), 1.0);
    std::fill(shift_.begin(), shift_.end(), 0.0);
    std::fill(free_map_.begin(), free_map_.end(), 0.0);
    for (std::size_t r = 0; r < m; ++r) free_map_[r * m + r] = 1.0;
    summary_ = summarise(active(), branches_, elements_view(), foundation_.equivalent_profile().data(),
                         hat_sum_.data(), hat_floor_.data(), free_floor_.data(), free_ceiling_.data());
}

void LazyNormalContact::step_eager(double overlap) {
    bring_up_to_date();
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

// The whole frictionless contact-step of the law now (ContactLaw::advance: the state's checks, the Foundation's
// step, the tangential layer skipped), for scale.
class LawContact {
public:
    LawContact(const Rheology& material, std::size_t count)
        : law_(material, radius, 0.0, count, half_width(), time_step), state_(law_.state_size(), 0.0) {}
    __attribute__((noinline)) double step_law(double overlap) {
        law_.advance(state_, overlap, {0.0, 0.0});
        return law_.normal_force(state_);
    }

private:
    mdr::dem::ContactLaw law_;
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
        {"long", 40000,  // held with a ripple of 1e-3 for 400 relaxation times: the composition renormalised
         [=](int n) {
             const double ripple = 1.0 + 1e-3 * std::sin(2.0 * pi * n / 500.0);
             return peak_overlap * (n < 100 ? std::sin(0.5 * pi * n / 100.0) : ripple);
         }},
        {"cycles", 1000,
         [=](int n) {
             return peak_overlap * (0.75 + 0.25 * std::cos(2.0 * pi * n / 200.0)) * std::min(1.0, n / 50.0);
         }},
    };
}

std::vector<Rheology> materials() {
    return {Rheology::standard(1e6, 1e6, 1e-4),                                // the law's bench, M = 1
            Rheology(1e6, 20.0, {{1e6, 1e-4}, {5e5, 3e-3}}),                  // a dashpot, M = 2
            Rheology::prony(1e6, {{1e6, 4e-5}, {1e6, 1.3e-3}, {1e6, 4e-2}}),   // bench_contact_law's M = 3
            Rheology(5e5, 5.0, {{1e6, 4e-5}, {1e6, 4e-4}, {1e6, 4e-3}, {1e6, 4e-2}})};  // M = 4, a dashpot
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
            std::printf("M=%zu eta=%-4g %-7s steps %5d lazy %5zu (element passes %4zu, renormalised %zu) eager %4zu "
                        " max|dF|/max|F| %.2e  state %.2e  %s\n",
                        material.terms().size(), material.viscosity(), scenario.name, scenario.steps,
                        lazy.lazy_steps, lazy.element_passes, lazy.renormalisations, lazy.eager_steps, relative,
                        state_relative, ok ? "ok" : "FAIL");
        }
    }
    return failures == 0 ? 0 : 1;
}

// Steps both forms through one scenario (for callgrind: their step functions' inclusive counts per step).
int count(const std::string& name, std::size_t branches) {
    const auto all = scenarios();
    const auto found = std::find_if(all.begin(), all.end(), [&](const Scenario& s) { return name == s.name; });
    if (found == all.end()) return 2;
    const auto material = materials()[std::min<std::size_t>(std::max<std::size_t>(branches, 1), 4) - 1];
    const double spacing = half_width() / elements;
    FoundationContact reference(material, elements, spacing);
    LazyNormalContact lazy(material, elements, spacing);
    LawContact law(material, elements);
    double sum = 0.0;
    for (int n = 1; n <= found->steps; ++n) {
        const double d = found->overlap(n);
        sum += reference.step_foundation(d) - lazy.step_lazy(d) + 0.0 * law.step_law(d);
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
