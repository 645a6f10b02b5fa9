#include "mdr/drivers/case_validation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "mdr/drivers/control_end.hpp"
#include "mdr/drivers/controls.hpp"
#include "mdr/drivers/material_window.hpp"
#include "mdr/error.hpp"
#include "mdr/foundation/foundation.hpp"
#include "mdr/rheology/contact_bodies.hpp"
#include "every_control.hpp"

namespace mdr::drivers {
namespace {

void validate_times(const ContactCase& contact_case) {
    const double start = contact_case.load.history->start_time();
    // A run its control's stop rule ends may have no end (infinite: the latest end allowed).
    const bool open_end = ends_by_stop_rule(contact_case.control);
    // A history of jumps only (all points at one time) may end where it starts: no step has a length.
    const bool instant = contact_case.load.history->end_time() == start && contact_case.end_time == start;
    if (!(contact_case.end_time > start || instant) || (!open_end && !std::isfinite(contact_case.end_time))) {
        throw InvalidInput("load.end", format_value(contact_case.end_time),
                           "must be after the first history time " + format_value(start) +
                               (open_end ? "" : " and finite"));
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

bool same_series(const rheology::Rheology& first, const rheology::Rheology& second) {
    const auto same_term = [](const rheology::RelaxationTerm& a, const rheology::RelaxationTerm& b) {
        return a.modulus == b.modulus && a.relaxation_time == b.relaxation_time;
    };
    return first.equilibrium_modulus() == second.equilibrium_modulus() && first.viscosity() == second.viscosity() &&
           std::equal(first.terms().begin(), first.terms().end(), second.terms().begin(), second.terms().end(),
                      same_term);
}

// The bodies as given are what `material` and `material_origin` combine (set_bodies): a caller that replaced those
// without the bodies leaves two materials in one case, the drivers running one, a reader of the bodies seeing the
// other. (The combination is recomputed exactly: it is deterministic.)
void validate_bodies(const ContactCase& contact_case) {
    if (!contact_case.bodies) return;
    const rheology::ContactMaterial combined = rheology::contact_material(*contact_case.bodies);
    const std::string rule = "differs from the combination of the case's bodies (ContactCase::bodies): set the "
                             "material with drivers::set_bodies, or clear the bodies with it";
    if (!same_series(combined.material, contact_case.material)) throw InvalidInput("material", "[...]", rule);
    const rheology::MaterialOrigin& origin = contact_case.material_origin;
    const bool same_certificate =
        combined.origin.certificate.has_value() == origin.certificate.has_value() &&
        (!origin.certificate || (combined.origin.certificate->kind == origin.certificate->kind &&
                                 combined.origin.certificate->error == origin.certificate->error));
    if (combined.origin.description != origin.description || !same_certificate ||
        combined.origin.times_from_conversion != origin.times_from_conversion) {
        throw InvalidInput("material_origin", origin.description.empty() ? "\"\"" : origin.description, rule);
    }
}

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
    validate_bodies(contact_case);
    if (!contact_case.load.history) {
        throw InvalidInput("load.history", "(missing)", "is required (under control = \"impact\" the point (0, 0))");
    }
    // The control's own rules (its ControlTraits); those that need a valid end after the times.
    visit_control(contact_case.control,
                  [&](auto traits, const auto& control) { traits.validate(contact_case, control); });
    validate_times(contact_case);
    visit_control(contact_case.control,
                  [&](auto traits, const auto& control) { traits.validate_within_run(contact_case, control); });
    if (contact_case.tangential) validate(*contact_case.tangential);
    validate_numerics(contact_case.numerics);
    // A model converted to a series (a power law, a springpot) is the case's material only over the lags its
    // certificate covers; the window is computed only for such a material (an impact's needs load.end then).
    if (converted_model(contact_case.material_origin)) {
        require_certified_over(contact_case.material_origin, material_window(contact_case));
    }
}

}  // namespace mdr::drivers
