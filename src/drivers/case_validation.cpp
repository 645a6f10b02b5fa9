#include "mdr/drivers/case_validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mdr/drivers/controls.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/profile/profile.hpp"

namespace mdr::drivers {
namespace {

// Force control: no pull, a history force >= 0.
void validate_force_history(const ContactCase& contact_case) {
    const auto& points = contact_case.load.history->points();
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (points[i].value < 0.0) {
            throw InvalidInput(fmt::format("load.history[{}].F", i), format_value(points[i].value),
                               "must be >= 0 in force control (the contact cannot pull)");
        }
    }
}

// The smallest value of the history over [from, to] (piecewise linear: at the ends or at a point between).
double history_minimum(const LoadHistory& history, double from, double to) {
    double lowest = std::min(history.value(from), history.value(to));
    for (const auto& point : history.points()) {
        if (point.time >= from && point.time <= to) lowest = std::min(lowest, point.value);
    }
    return lowest;
}

// The rules of a normal harmonic under any control that takes one.
void validate_harmonic(const ContactCase& contact_case) {
    if (!contact_case.load.harmonic) return;
    const HarmonicLoad& harmonic = *contact_case.load.harmonic;
    validate(harmonic, "load.harmonic.");
    require_positive("load.harmonic.amplitude", harmonic.amplitude);
    const double start = contact_case.load.history->start_time();
    if (harmonic.start < start) {
        throw InvalidInput("load.harmonic.start", format_value(harmonic.start),
                           "must not be before the first history time " + format_value(start) +
                               " (the harmonic is added to the history)");
    }
}

// Force control: the harmonic must not make the force pull, during it or after it.
void validate_force_harmonic(const ContactCase& contact_case) {
    if (!contact_case.load.harmonic) return;
    const HarmonicLoad& harmonic = *contact_case.load.harmonic;
    const double lowest = history_minimum(*contact_case.load.history, harmonic.start, harmonic.end);
    if (harmonic.amplitude > lowest) {
        throw InvalidInput("load.harmonic.amplitude", format_value(harmonic.amplitude),
                           "must not exceed the smallest force of the history during the harmonic, " +
                               format_value(lowest) + " (the force would pull; the contact cannot)");
    }
    // After its end the harmonic holds its end value (0 after whole cycles, up to the sine's round-off).
    const double held = harmonic.value(harmonic.end);
    const double after = history_minimum(*contact_case.load.history, harmonic.end,
                                         std::max(harmonic.end, contact_case.load.history->end_time()));
    if (held + after < -1e-9 * harmonic.amplitude) {
        throw InvalidInput("load.harmonic.end", format_value(harmonic.end),
                           "the harmonic holds " + format_value(held) + " after its end, and with the history's " +
                               format_value(after) + " there the force would pull (end after whole cycles)");
    }
}

// The base history of a plain spring: it starts at or above the surface and does not jump.
void validate_base_history(const ContactCase& contact_case) {
    const auto& points = contact_case.load.history->points();
    if (points.front().value > 0.0) {
        throw InvalidInput("load.history[0].z", format_value(points.front().value),
                           "must be <= 0: the spring is unloaded at first contact, and the base starts at or "
                           "above it (give the approach a duration)");
    }
    for (std::size_t i = 1; i < points.size(); ++i) {
        if (points[i].time == points[i - 1].time && points[i].value != points[i - 1].value) {
            throw InvalidInput(fmt::format("load.history[{}].t", i), format_value(points[i].time),
                               "the base displacement must not jump (give each change a duration)");
        }
    }
}

// A Shore test is spring control with the durometer's spring and the base history of shore_base_history.
void validate_shore(const ContactCase& contact_case, const SpringControl& spring) {
    const ShoreTest& shore = *spring.shore;
    require_positive("load.duration", shore.duration);
    if (spring.spring_constant != shore.instrument.spring_rate) {
        throw InvalidInput("load.control", "\"shore\"",
                           "a Shore test is spring control with the durometer's own spring (no spring_constant)");
    }
    if (contact_case.load.harmonic) throw InvalidInput("load.harmonic", "{...}", "not with control = \"shore\"");
    if (contact_case.tangential) throw InvalidInput("tangential", "[...]", "not with control = \"shore\"");
}

// Constant-force pauses (ForcePause): spring control only, in time order and apart, inside the simulated time after
// the history's first point, and not during a harmonic.
void validate_force_pauses(const ContactCase& contact_case, const std::vector<ForcePause>& pauses) {
    if (pauses.empty()) return;
    if (contact_case.shore()) {
        throw InvalidInput("load.force_pauses", "[...]",
                           "only with control = \"spring\" (the feedback moves the base)");
    }
    const double first = contact_case.load.history->start_time();
    for (std::size_t i = 0; i < pauses.size(); ++i) {
        const ForcePause& pause = pauses[i];
        const std::string key = fmt::format("load.force_pauses[{}]", i);
        const std::string value = fmt::format("[{}, {}]", format_value(pause.start), format_value(pause.end));
        if (!(pause.start > first)) {
            throw InvalidInput(key, value, "must start after the history's first time " + format_value(first) +
                                               " (the force held is that of a contact)");
        }
        if (!(pause.end > pause.start)) throw InvalidInput(key, value, "must end after it starts");
        if (!(pause.end <= contact_case.end_time)) {
            throw InvalidInput(key, value, "must end by the end of the run, load.end = " +
                                               format_value(contact_case.end_time));
        }
        if (i > 0 && !(pause.start > pauses[i - 1].end)) {
            throw InvalidInput(key, value, "must start after the previous pause ends at " +
                                               format_value(pauses[i - 1].end) + " (pauses in time order, apart)");
        }
        if (const auto& harmonic = contact_case.load.harmonic; harmonic && harmonic->start < pause.end &&
                                                           harmonic->end > pause.start) {
            throw InvalidInput(key, value,
                               fmt::format("overlaps load.harmonic (t = {} .. {}): during a pause the feedback holds "
                                           "the force, so the base cannot follow a harmonic",
                                           format_value(harmonic->start), format_value(harmonic->end)));
        }
    }
}

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

void validate_oblique(const ContactCase& contact_case) {
    const ObliqueImpactLoad* oblique = contact_case.oblique();
    if (!oblique) return;
    require_non_negative("tangential.friction", oblique->friction);
    require_finite("load.tangential_velocity", oblique->tangential_velocity);
    require_finite("load.spin", oblique->spin);
    const profile::ProfileDefinition sphere = contact_case.indenter->definition();
    if (sphere.shape != "sphere") {
        throw InvalidInput("indenter.shape", "\"" + sphere.shape + "\"",
                           "an oblique impact needs shape = \"sphere\" (its radius is the lever of the friction)");
    }
    if (oblique->moment_of_inertia) require_positive("indenter.moment_of_inertia", *oblique->moment_of_inertia);
    // Section 6 maps the tangential problem exactly for an incompressible body only: with a compressible body (or
    // two bodies, whose elastic mismatch couples them) the normal and tangential problems are coupled (section 7).
    if (contact_case.tangential_approximate()) {
        throw InvalidInput("load.tangential_velocity", format_value(oblique->tangential_velocity),
                           "an oblique impact needs an incompressible half-space and a rigid sphere: with a "
                           "compressible body or two bodies the normal and tangential problems are coupled (section "
                           "7) and the tangential mapping is not exact");
    }
}

void validate_times(const ContactCase& contact_case) {
    const double start = contact_case.load.history->start_time();
    const bool impact = contact_case.impact() != nullptr;
    // A history of jumps only (all points at one time) may end where it starts: no step has a length.
    const bool instant = contact_case.load.history->end_time() == start && contact_case.end_time == start;
    if (!(contact_case.end_time > start || instant) || (!impact && !std::isfinite(contact_case.end_time))) {
        throw InvalidInput("load.end", format_value(contact_case.end_time),
                           "must be after the first history time " + format_value(start) +
                               (impact ? "" : " and finite"));
    }
    for (std::size_t i = 0; i < contact_case.snapshots.size(); ++i) {
        const double t = contact_case.snapshots[i];
        if (std::fpclassify(t) == FP_SUBNORMAL) {
            throw InvalidInput(fmt::format("output.snapshots[{}]", i), format_value(t),
                               "is subnormal (below about 2.2e-308 in size); a snapshot time must be 0 or a normal "
                               "number within the simulated time");
        }
        if (!(t >= start && t <= contact_case.end_time)) {
            throw InvalidInput(fmt::format("output.snapshots[{}]", i), format_value(t),
                               fmt::format("must lie within the simulated time [{}, {}]", start,
                                           contact_case.end_time));
        }
    }
}

void validate_numerics(const NumericsOptions& numerics) {
    if (numerics.elements) foundation::require_element_count("numerics.elements", *numerics.elements);
    if (numerics.time_step) require_positive("numerics.time_step", *numerics.time_step);
    if (numerics.half_width) require_positive("numerics.half_width", *numerics.half_width);
    if (numerics.output_every < 1) throw InvalidInput("numerics.output_every", "0", "must be an integer >= 1");
    if (numerics.max_element_steps) require_positive("numerics.max_element_steps", *numerics.max_element_steps);
    if (numerics.max_memory) require_positive("numerics.max_memory", *numerics.max_memory);
}

// Each control's own rules, in the order the checks of a case have always run (those before the times).
struct ControlRules {
    const ContactCase& contact_case;

    void operator()(const DisplacementControl&) const {
        if (contact_case.material.viscosity() > 0.0 && contact_case.load.history->has_jump()) {
            throw InvalidInput(
                "load.history", "[...]",
                "a jump in depth needs an infinite force with a dashpot (eta > 0); give the jump a duration");
        }
        validate_harmonic(contact_case);
    }
    void operator()(const ForceControl&) const {
        validate_force_history(contact_case);
        validate_harmonic(contact_case);
        validate_force_harmonic(contact_case);
    }
    void operator()(const SpringControl& spring) const {
        validate_harmonic(contact_case);
        require_positive("load.spring_constant", spring.spring_constant);
        if (spring.shore) {
            validate_shore(contact_case, spring);
        } else {
            validate_base_history(contact_case);
        }
    }
    void operator()(const ImpactControl& impact) const {
        validate_impact(contact_case, impact);
        validate_oblique(contact_case);
        if (contact_case.load.harmonic) throw InvalidInput("load.harmonic", "{...}", "not with control = \"impact\"");
    }
};

}  // namespace

double incidence_velocity(double velocity, double incidence_deg) {
    if (!(incidence_deg >= 0.0 && incidence_deg < 90.0)) {
        throw InvalidInput("load.incidence_deg", format_value(incidence_deg),
                           "must lie in [0, 90) degrees (from the surface normal)");
    }
    return velocity * std::tan(incidence_deg * std::numbers::pi / 180.0);
}

void validate(const TangentialLoad& load) {
    require_non_negative("tangential.friction", load.friction);
    const auto& [history, harmonic] = load.load;
    if (history.has_value() == harmonic.has_value()) {
        throw InvalidInput("tangential", "[...]",
                           fmt::format("give either history or {}", fmt::join(harmonic_key_names(), ", ")));
    }
    if (history && history->has_jump()) {
        throw InvalidInput("tangential.history", "[...]",
                           "must start at 0 and have no jumps (give each change a duration)");
    }
    if (harmonic) validate(*harmonic, "tangential.");
}

void validate(const HarmonicLoad& harmonic, const std::string& prefix) {
    require_finite(prefix + "amplitude", harmonic.amplitude);
    require_positive(prefix + "frequency", harmonic.frequency);
    require_finite(prefix + "start", harmonic.start);
    require_finite(prefix + "end", harmonic.end);
    if (!(harmonic.end > harmonic.start)) {
        throw InvalidInput(prefix + "end", format_value(harmonic.end),
                           "must be after " + prefix + "start = " + format_value(harmonic.start));
    }
}

void validate(const ContactCase& contact_case) {
    if (!contact_case.indenter) throw InvalidInput("indenter", "(missing)", "is required");
    if (!contact_case.load.history) {
        throw InvalidInput("load.history", "(missing)", "is required (under control = \"impact\" the point (0, 0))");
    }
    std::visit(ControlRules{contact_case}, contact_case.control);
    validate_times(contact_case);
    if (const SpringControl* spring = contact_case.spring()) validate_force_pauses(contact_case, spring->force_pauses);
    if (contact_case.tangential) validate(*contact_case.tangential);
    validate_numerics(contact_case.numerics);
}

}  // namespace mdr::drivers
