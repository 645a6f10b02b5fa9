#include "mdr/drivers/contact_case.hpp"

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/rheology/compressible.hpp"
#include "default_numerics.hpp"
#include "every_control.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <utility>

namespace mdr::drivers {
namespace {

// 10-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 5> gauss_nodes{0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                            0.8650633666889845, 0.9739065285171717};
constexpr std::array<double, 5> gauss_weights{0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                              0.1494513491505806, 0.0666713443086881};

double integrate(const auto& f, double lower, double upper, int panels) {
    double sum = 0.0;
    const double width = (upper - lower) / panels;
    for (int p = 0; p < panels; ++p) {
        const double mid = lower + (p + 0.5) * width;
        for (std::size_t j = 0; j < gauss_nodes.size(); ++j) {
            const double dx = 0.5 * width * gauss_nodes[j];
            sum += gauss_weights[j] * (f(mid - dx) + f(mid + dx));
        }
    }
    return 0.5 * width * sum;
}

// Contact radius at which the elastic force with the given modulus reaches `force`.
double elastic_radius(const profile::Profile& indenter, double modulus, double force) {
    double lower = 0.0;
    double upper = 1.0;
    while (elastic_force(indenter, modulus, upper) < force && upper < 1e30) {
        lower = upper;
        upper *= 2.0;
    }
    while (lower == 0.0 && elastic_force(indenter, modulus, 0.5 * upper) >= force && upper > 1e-30) upper *= 0.5;
    for (int i = 0; i < 200 && upper - lower > 1e-12 * upper; ++i) {
        const double mid = 0.5 * (lower + upper);
        (elastic_force(indenter, modulus, mid) < force ? lower : upper) = mid;
    }
    return upper;
}

// Elastic work W(a) = int_0^a F_el(a') g'(a') da' done by the indenter up to contact radius a (trapezoidal in a;
// an estimate for the defaults, good to ~1e-3).
double elastic_work(const profile::Profile& indenter, double modulus, double radius) {
    constexpr int panels = 20;
    double work = 0.0, previous_force = 0.0, previous_depth = indenter.equivalent(0.0);
    for (int i = 1; i <= panels; ++i) {
        const double a = radius * i / panels;
        const double force = elastic_force(indenter, modulus, a);
        const double depth = indenter.equivalent(a);
        work += 0.5 * (force + previous_force) * (depth - previous_depth);
        previous_force = force;
        previous_depth = depth;
    }
    return work;
}

// The exponent p of the steps graded towards a time T at which a falling force reaches zero (cuts_towards_zeros,
// t = T - L s^p, s uniform). The contact ends at T, and its depth recedes as D ~ (T - t)^(1/m), where F_el ~ D^m
// at small depth (a profile g ~ |x|^n: m = 1 + 1/n; docs/theory.md section 3). The trapezoidal rule on the graded
// nodes errs by O(h^(p (1 + 1/m))) in the step ending at T and by sum h^3 s^(p (1 + 1/m) - 3) over the others:
// second order for p > 2m / (m + 1) (at equality h^2 ln h). p = m makes D linear in s (its increments uniform) and
// exceeds that bound for every m > 1; at most 2 (a profile sharper than a cone), and 2 where the profile is no power
// law (2 exceeds the bound for every m). 0 for a flat end (m = 1, F_el ~ D: nothing singular).
double zero_grading_exponent(const profile::Profile& indenter) {
    if (indenter.is_flat_punch() || indenter.flat_radius() > 0.0) return 0.0;
    const auto n = indenter.power_law_exponent();
    return n ? std::min(1.0 + 1.0 / *n, 2.0) : 2.0;
}

}  // namespace

ElasticImpact elastic_impact(const profile::Profile& indenter, double modulus, double mass, double velocity) {
    const double energy = 0.5 * mass * velocity * velocity;
    ElasticImpact impact;
    if (indenter.is_flat_punch()) {
        impact.radius = indenter.max_radius();
        impact.depth = std::sqrt(energy / (4.0 * modulus * impact.radius));  // W = 8 G a d^2 / 2
    } else {
        double lower = 0.0, upper = 1.0;
        while (elastic_work(indenter, modulus, upper) < energy && upper < indenter.max_radius() && upper < 1e30) {
            lower = upper;
            upper *= 2.0;
        }
        upper = std::min(upper, indenter.max_radius());
        while (lower == 0.0 && elastic_work(indenter, modulus, 0.5 * upper) >= energy && upper > 1e-30) upper *= 0.5;
        for (int i = 0; i < 100 && upper - lower > 1e-4 * upper; ++i) {
            const double middle = 0.5 * (lower + upper);
            (elastic_work(indenter, modulus, middle) < energy ? lower : upper) = middle;
        }
        impact.radius = upper;
        impact.depth = indenter.equivalent(upper);
    }
    impact.duration = 3.0 * impact.depth / velocity;  // Hertz: T = 2.94 d_max / v0
    return impact;
}

double elastic_force(const profile::Profile& indenter, double shear_modulus, double contact_radius) {
    if (contact_radius <= 0.0) return 0.0;
    const double edge = indenter.equivalent(contact_radius);
    const auto integrand = [&](double x) { return edge - indenter.equivalent(x); };
    return 8.0 * shear_modulus * integrate(integrand, 0.0, contact_radius, 4);
}

double shortest_time_above(const rheology::Rheology& material, double floor) {
    double shortest = std::numeric_limits<double>::infinity();
    for (const auto& term : material.terms()) {
        if (term.relaxation_time >= floor) shortest = std::min(shortest, term.relaxation_time);
    }
    for (const auto& term : material.creep_function().terms) {
        if (term.retardation_time >= floor) shortest = std::min(shortest, term.retardation_time);
    }
    return shortest;
}

ResolvedNumerics resolve_history_numerics(const ContactCase& contact_case, bool graded, bool graded_towards_zeros,
                                          const ContactRadiusBound& largest_contact_radius) {
    const auto& numerics = contact_case.numerics;
    const auto& indenter = *contact_case.indenter;
    ResolvedNumerics resolved;
    resolved.output_every = numerics.output_every;
    resolved.elements = numerics.elements.value_or(default_elements);
    resolved.time_limit = contact_case.end_time;
    const auto segments = static_cast<double>(contact_case.load.history->points().size());
    resolved.min_segment_steps = numerics.min_segment_steps.value_or(static_cast<std::size_t>(std::clamp(
        std::ceil(static_cast<double>(default_steps) / segments), 1.0, static_cast<double>(min_steps_per_segment))));

    const double duration = contact_case.end_time - contact_case.load.history->start_time();
    const auto& material = contact_case.material;
    const bool converted_times = contact_case.material_origin.times_from_conversion;
    if (numerics.time_step) {
        resolved.time_step = *numerics.time_step;
    } else if (duration > 0.0) {
        const double step = duration / static_cast<double>(default_steps);
        // A series standing for a continuous spectrum has a node within a factor exp(h) above any step: its
        // times need no finer step (the load is linear between steps and each branch integrated exactly; the
        // power-law ramp, triangle and step-hold agree with 3.6x more steps to 2 digits of their error,
        // tests/verification/test_power_law_default_step.cpp).
        resolved.time_step = converted_times ? step : std::min(step, shortest_time_above(material, step) / 5.0);
    } else {
        resolved.time_step = 1.0;  // a history of jumps only: no step has a length
    }
    // Under a control that solves for the depth (force, spring) the creep after the start and after a fast load
    // change is taken on steps graded from there, scaled to the time step, the user's too (a finer step is never
    // worse than the default):
    if (graded && duration > 0.0) {
        if (material.viscosity() > 0.0) {
            // a parallel dashpot: the trapezoidal rate is second order, and the creep, singular in time there, is
            // graded from a small fraction of the step;
            resolved.grading_ratio = jump_grading_ratio;
            resolved.first_graded_step = jump_first_step * resolved.time_step;
        } else if (converted_times && !material.terms().empty()) {
            // a converted series, J ~ t^beta on every scale down to its shortest time: from that time (on shorter
            // steps the series is elastic; tests/verification/test_power_law_fast_force_step.cpp);
            resolved.grading_ratio = jump_grading_ratio;
            resolved.first_graded_step = std::min(material.shortest_time(), resolved.time_step);
        } else if (!material.terms().empty() && material.shortest_time() < resolved.time_step) {
            // a finite series with a time shorter than the step (the default step skips such times): its exponential
            // creep is resolved from jump_grading_ratio of that time on (test_prony_fast_force_step.cpp).
            resolved.grading_ratio = jump_grading_ratio;
            resolved.first_graded_step =
                std::max(jump_grading_ratio * material.shortest_time(), finest_graded_step * resolved.time_step);
        }
    }
    // Where a force falls to zero on a body that creeps (a dashpot or a series: both show the order 1 + 1/m of the
    // uniform grid there, docs/theory.md section 3), the steps are graded towards the zero.
    if (graded_towards_zeros && (material.viscosity() > 0.0 || !material.terms().empty())) {
        resolved.zero_grading_exponent = zero_grading_exponent(indenter);
    }
    const std::optional<HarmonicLoad> harmonics[] = {
        contact_case.load.harmonic, contact_case.tangential ? contact_case.tangential->load.harmonic : std::nullopt};
    for (const auto& harmonic : harmonics) {
        if (!numerics.time_step && harmonic) {
            resolved.time_step = std::min(resolved.time_step, harmonic->period() / default_steps_per_period);
        }
    }

    if (numerics.half_width) {
        resolved.half_width = *numerics.half_width;
    } else if (indenter.is_flat_punch()) {
        resolved.half_width = indenter.max_radius();
    } else {
        const double peak = contact_case.load.largest_value();
        const auto force_bound = [&](double force) {
            if (!(force > 0.0)) return 0.0;
            const double softest = 1.0 / contact_case.material.creep(std::max(duration, 0.0));
            return 1.25 * elastic_radius(indenter, softest, force);
        };
        double radius = largest_contact_radius(peak, force_bound);
        if (!(radius > 0.0)) radius = std::isfinite(indenter.max_radius()) ? indenter.max_radius() : 1.0;
        resolved.half_width = std::min(radius, indenter.max_radius());
    }
    return resolved;
}

std::optional<double> body_poisson_ratio(const ContactCase& contact_case) {
    if (!contact_case.shear_material) return 0.5;  // no bulk part was folded in
    if (!contact_case.bulk_material) return std::nullopt;
    return rheology::constant_poisson_ratio(*contact_case.shear_material, *contact_case.bulk_material);
}

ResolvedNumerics resolve_numerics(const ContactCase& contact_case) {
    validate(contact_case);
    const ResolvedNumerics resolved = visit_control(
        contact_case.control,
        [&](auto traits, const auto& control) { return traits.resolve_numerics(contact_case, control); });
    require_bounded_work(contact_case, resolved);
    return resolved;
}

void set_bodies(ContactCase& contact_case, rheology::ContactBodies bodies) {
    rheology::ContactMaterial contact = rheology::contact_material(bodies);
    contact_case.material = std::move(contact.material);
    contact_case.shear_material = std::move(contact.shear_material);
    contact_case.bulk_material = std::move(contact.bulk_material);
    contact_case.tangential_exact = contact.tangential_exact;
    contact_case.material_origin = std::move(contact.origin);
    contact_case.bodies = std::move(bodies);
}

}  // namespace mdr::drivers
