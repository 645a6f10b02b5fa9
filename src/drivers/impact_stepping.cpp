#include "impact_stepping.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "mdr/drivers/oblique_sphere.hpp"
#include "mdr/drivers/work_estimate.hpp"
#include "mdr/error.hpp"
#include "mdr/profile/profile.hpp"
#include "default_numerics.hpp"
#include "impact_end.hpp"

namespace mdr::drivers {
namespace {

void validate_impact(const ContactCase& contact_case, const ImpactControl& impact) {
    require_positive("load.velocity", impact.velocity);
    require_positive("indenter.mass", impact.mass);
    const auto& material = contact_case.material;
    if (material.is_fluid() && material.terms().empty()) {  // a dashpot alone: no spring to give the energy back
        throw InvalidInput("material.eta", format_value(material.viscosity()),
                           "an impact needs an elastic part beside the dashpot: a purely viscous body stops the "
                           "indenter at a finite depth, which never rebounds (restitution 0, the contact never ends)");
    }
    if (contact_case.tangential) {
        throw InvalidInput("tangential", "[...]",
                           "a tangential load history is not for an impact; an oblique impact takes only "
                           "tangential.friction with load.tangential_velocity or load.spin");
    }
}

void validate_oblique(const ContactCase& contact_case, const ImpactControl& impact) {
    if (!impact.oblique) return;
    const ObliqueImpactLoad& oblique = *impact.oblique;
    require_non_negative("tangential.friction", oblique.friction);
    require_finite("load.tangential_velocity", oblique.tangential_velocity);
    require_finite("load.spin", oblique.spin);
    if (!contact_case.indenter->tip_radius()) {  // the capability of the type, not its name (issue 27)
        throw InvalidInput("indenter.shape", "\"" + contact_case.indenter->definition().shape + "\"",
                           "an oblique impact needs shape = \"sphere\" (its radius is the lever of the friction)");
    }
    if (oblique.moment_of_inertia) require_positive("indenter.moment_of_inertia", *oblique.moment_of_inertia);
    // Section 6 maps the tangential problem exactly for an incompressible body only: with a compressible body (or
    // two bodies, whose elastic mismatch couples them) the normal and tangential problems are coupled (section 7).
    if (contact_case.tangential_approximate()) {
        throw InvalidInput("load.tangential_velocity", format_value(oblique.tangential_velocity),
                           "an oblique impact needs an incompressible half-space and a rigid sphere: with a "
                           "compressible body or two bodies the normal and tangential problems are coupled (section "
                           "7) and the tangential mapping is not exact");
    }
}

// Impact: the time step from the elastic impact with the stiffest spring modulus, the foundation from the one
// with the softest modulus (G_inf; for a fluid 1/J at ten stiff impact times), which bounds the depth.
ResolvedNumerics resolve_impact_numerics(const ContactCase& contact_case, const ImpactControl& impact) {
    const auto& numerics = contact_case.numerics;
    const auto& material = contact_case.material;
    const auto& indenter = *contact_case.indenter;
    double spring_modulus = material.equilibrium_modulus();
    for (const auto& term : material.terms()) spring_modulus += term.modulus;
    if (!(spring_modulus > 0.0)) spring_modulus = material.viscosity() / std::max(material.shortest_time(), 1e-300);
    const ElasticImpact stiff = elastic_impact(indenter, spring_modulus, impact.mass, impact.velocity);
    const double soft_modulus =
        material.is_fluid() ? 1.0 / material.creep(10.0 * stiff.duration) : material.equilibrium_modulus();
    const ElasticImpact soft =
        elastic_impact(indenter, std::min(soft_modulus, spring_modulus), impact.mass, impact.velocity);

    ResolvedNumerics resolved;
    resolved.output_every = numerics.output_every;
    resolved.elements = numerics.elements.value_or(default_elements);
    double step = stiff.duration / static_cast<double>(default_steps);
    if (material.viscosity() > 0.0) {
        // A parallel dashpot brakes the indenter within m / (8 eta a) (eq. 21 with the dashpot's force 8 eta a v):
        // an overdamped impact is decided on that scale, which the elastic contact time does not see. The soft
        // radius bounds a, so this time is bounded below.
        const double braking_time = impact.mass / (8.0 * material.viscosity() * soft.radius);
        step = std::min(step, braking_time / static_cast<double>(braking_steps));
    }
    if (impact.oblique) {
        // The contact point's motion has the effective mass m_t, 1/m_t = 1/m + R^2/I (2/7 m for a solid sphere, for
        // which the normal steps resolve it): a lighter m_t oscillates faster, as sqrt(m_t).
        const auto [radius, inertia] = oblique_sphere(indenter, impact);
        const double tangential_mass = 1.0 / (1.0 / impact.mass + radius * radius / inertia);
        step *= std::min(1.0, std::sqrt(tangential_mass / (2.0 / 7.0 * impact.mass)));
    }
    resolved.time_step = numerics.time_step.value_or(std::min(step, shortest_time_above(material, step) / 5.0));
    resolved.half_width = numerics.half_width.value_or(
        indenter.is_flat_punch() ? indenter.max_radius() : std::min(1.2 * soft.radius, indenter.max_radius()));
    // Without load.end: ten soft contact times, and at most 200 stiff ones (a fluid may never push back).
    resolved.time_limit = std::isfinite(contact_case.end_time)
                              ? contact_case.end_time
                              : std::min(10.0 * soft.duration, 200.0 * stiff.duration);
    resolved.expected_end = std::min(soft.duration, resolved.time_limit);
    return resolved;
}

}  // namespace

ImpactStepping::ImpactStepping(const ContactCase& contact_case, const ResolvedNumerics& numerics,
                               foundation::Foundation& foundation, const ImpactControl& impact)
    : contact_case_(contact_case),
      numerics_(numerics),
      foundation_(foundation),
      mass_(impact.mass),
      approach_(impact.velocity),
      cache_(contact_case.material),
      clock_(contact_case.snapshots, numerics.time_step),
      velocity_(impact.velocity) {
    if (impact.oblique) {
        oblique_.emplace(*impact.oblique, oblique_sphere(*contact_case.indenter, impact), mass_, contact_case.material,
                         foundation);
    }
}

void ImpactStepping::add_observers(ObserverList& observers, IndentationResult& result) {
    if (oblique_) observers.add(oblique_columns_.emplace(*oblique_, result));
}

FoundationSnapshots::ShearStress ImpactStepping::shear_stress() {
    if (!oblique_) return {};
    return [this](Snapshot& snapshot) { oblique_->add_shear_stress(snapshot); };
}

StepState ImpactStepping::state(std::size_t step, bool ended) const {
    return {.step = step, .time = clock_.time(), .depth = depth_, .force = force_, .velocity = velocity_,
            .fraction = impact_progress(clock_.time(), ended, numerics_), .last = ended,
            .foundation = &foundation_};
}

StepState ImpactStepping::step(std::size_t n) {
    require_before_end(clock_.time(), numerics_.time_limit, velocity_);
    // Land exactly on snapshot times (the recorder takes each at the first state at or after it).
    const double step = clock_.step();
    foundation_.begin_step(cache_.get(step), velocity_);
    // Trapezoidal rule for m d'' = -F (eq. 37): d1 = d0 + (v0 + v1) dt/2, v1 = v0 - (F0 + F1) dt/(2m), i.e.
    // F(d1) + (4m/dt^2)(d1 - d0 - v0 dt) = -F0, monotone in d1.
    const double spring = inertial_stiffness(mass_, step);
    const double anchor = depth_ + velocity_ * step;
    const double guess = anchor - force_ * step * step / (2.0 * mass_);
    // The depth increment of the step, never below a billionth of the approach increment: scales with the
    // impact itself (not with the half-width), so that a slow impact is solved as precisely as a fast one.
    const double scale = std::max(std::abs(velocity_), 1e-9 * approach_) * step;
    const double new_depth = solve_depth(foundation_, depth_, guess, scale, -force_, spring, anchor);
    foundation_.advance(depth_, new_depth);
    for (std::size_t i = 0; i < inner_exits_.size(); ++i) {
        if (foundation_.inner_exit(i) >= 0.0) inner_exits_[i] = clock_.time() + foundation_.inner_exit(i) * step;
    }
    const double new_force = foundation_.total_force();
    require_steps_within_bound(contact_case_, numerics_, n, clock_.time());
    // The stop rule: every element has left (eq. 39).
    const bool ended = new_force == 0.0 && force_ > 0.0;
    const double new_velocity = ended ? end_contact(step) : trapezoidal_velocity(depth_, new_depth, velocity_, step);
    if (oblique_ && !ended) oblique_->step(cache_.get(step), step);
    clock_.advance();
    depth_ = new_depth;
    force_ = new_force;
    velocity_ = new_velocity;
    return state(n, ended);
}

double ImpactStepping::end_contact(double time_step) {
    // The last element left where its force crossed zero inside the step (located by the foundation).
    const double fraction = foundation_.latest_exit();
    ImpactOutcome outcome =
        impact_outcome({.mass = mass_, .approach = approach_, .time = clock_.time(), .time_step = time_step,
                        .velocity = velocity_, .force = force_, .fraction = fraction});
    // Where the contact shrinks to the axis, the exit times of the two innermost elements are linear in g near it,
    // so extrapolated there (Foundation::axis_weight) they give the end to O(dx^2), where the innermost element's
    // own exit is only O(dx) for a cone.
    const bool axis_last = foundation_.inner_exit(0) == fraction;  // not an annulus leaving last
    if (axis_last && inner_exits_[1] >= 0.0 && inner_exits_[1] < inner_exits_[0]) {
        outcome.contact_time += foundation_.axis_weight() * (inner_exits_[1] - inner_exits_[0]);
    }
    if (oblique_) {
        oblique_->finish(cache_.get(time_step), time_step, fraction);
        outcome.oblique = oblique_->outcome(outcome, approach_);
        outcome.dissipated_energy += oblique_->kinetic_energy_lost();
    }
    outcome_ = outcome;
    return -outcome.rebound_velocity;
}

std::vector<ControlKind> ControlTraits<ImpactControl>::rows() {
    const auto& oblique = oblique_impact_keys();
    return {{"impact",
             "a rigid indenter of mass m meets the surface at speed v0 at t = 0 and moves by m d'' = -F (eq. 37) until "
             "it leaves",
             "",
             {{"velocity", "m/s", "the approach speed v0 > 0 at first contact", true},
              {"end", "s", "the latest end (default: from the contact time's scales)"},
              oblique[0], oblique[1], oblique[2]},
             {"indenter.mass"}}};
}

void ControlTraits<ImpactControl>::validate(const ContactCase& contact_case, const ImpactControl& impact) {
    validate_impact(contact_case, impact);
    validate_oblique(contact_case, impact);
    if (contact_case.load.harmonic) throw InvalidInput("load.harmonic", "{...}", "not with control = \"impact\"");
}

std::string ControlTraits<ImpactControl>::describe(const ContactCase& contact_case, const ImpactControl& impact,
                                                   const rheology::UnitNames& unit_names) {
    std::string load = fmt::format("impact of m = {:.4g} {} at v0 = {:.4g} {}", impact.mass, unit_names("kg"),
                                   impact.velocity, unit_names("m/s"));
    if (const auto& oblique = impact.oblique) {
        load += fmt::format(", oblique: v_t0 = {:.4g} {}, omega0 = {:.4g} {}, I = {:.4g} {}, mu = {:.4g}",
                            oblique->tangential_velocity, unit_names("m/s"), oblique->spin, unit_names("rad/s"),
                            oblique_sphere(*contact_case.indenter, impact).moment_of_inertia, unit_names("kg m^2"),
                            oblique->friction);
    }
    return load;
}

ResolvedNumerics ControlTraits<ImpactControl>::resolve_numerics(const ContactCase& contact_case,
                                                               const ImpactControl& impact) {
    ResolvedNumerics resolved = resolve_impact_numerics(contact_case, impact);
    if (!(std::isfinite(resolved.time_limit) && resolved.time_step > 0.0)) {
        throw InvalidInput("load.velocity", format_value(impact.velocity),
                           fmt::format("the impact's time scales are not representable (time step {:.4g} s, contact "
                                       "time limit {:.4g} s); give load.end and numerics.time_step",
                                       resolved.time_step, resolved.time_limit));
    }
    return resolved;
}

std::vector<GridNode> ControlTraits<ImpactControl>::grid(const ContactCase& /*contact_case*/,
                                                         const ResolvedNumerics& /*numerics*/,
                                                         const ImpactControl& /*impact*/) {
    throw InvalidInput("load.control", "\"impact\"", "has no history grid (its steps end at the contact's end)");
}

LayerLoading ControlTraits<ImpactControl>::on_layer(const ContactCase& /*contact_case*/, const ImpactControl& impact) {
    if (impact.oblique) refuse_on_layer("load.tangential_velocity", "[...]", "an oblique impact");
    return {.impact = &impact};
}

}  // namespace mdr::drivers
