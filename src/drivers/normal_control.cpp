#include "normal_control.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "mdr/drivers/case_validation.hpp"
#include "mdr/drivers/contact_case.hpp"
#include "mdr/drivers/shore.hpp"
#include "mdr/error.hpp"
#include "control_keys.hpp"

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
    if (spring.spring_constant != shore.instrument.spring_rate) {
        throw InvalidInput("load.spring_constant", format_value(spring.spring_constant),
                           "a Shore test's spring is the durometer's, k = " +
                               format_value(shore.instrument.spring_rate) +
                               " (io::assemble_case sets it; control = \"shore\" takes no spring_constant)");
    }
    require_positive("load.duration", shore.duration);
    if (contact_case.load.harmonic) throw InvalidInput("load.harmonic", "{...}", "not with control = \"shore\"");
    if (contact_case.tangential) throw InvalidInput("tangential", "[...]", "not with control = \"shore\"");
}

// Constant-force pauses (ForcePause): spring control only, in time order and apart, inside the simulated time after
// the history's first point, and not during a harmonic.
void validate_force_pauses(const ContactCase& contact_case, const SpringControl& control) {
    const std::vector<ForcePause>& pauses = control.force_pauses;
    if (pauses.empty()) return;
    if (control.shore) {
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

}  // namespace

std::vector<ControlKind> ControlTraits<DisplacementControl>::rows() {
    return {{"displacement", "the history prescribes the depth d(t); the force follows (eq. 16)", "d",
             {history_key("s, m", "d"), harmonic_key("m"), end_key()}, {}}};
}

void ControlTraits<DisplacementControl>::validate(const ContactCase& contact_case,
                                                  const DisplacementControl& /*control*/) {
    if (contact_case.material.viscosity() > 0.0 && contact_case.load.history->has_jump()) {
        throw InvalidInput(
            "load.history", "[...]",
            "a jump in depth needs an infinite force with a dashpot (eta > 0); give the jump a duration");
    }
    validate_harmonic(contact_case);
}

double ControlTraits<DisplacementControl>::largest_contact_radius(const ContactCase& contact_case,
                                                                  const DisplacementControl& /*control*/, double peak,
                                                                  const ForceRadiusBound& /*force_bound*/) {
    return 1.1 * contact_case.indenter->contact_radius(peak);
}

std::vector<ControlKind> ControlTraits<ForceControl>::rows() {
    return {{"force", "the history prescribes the force F(t) >= 0; the depth is solved for at each step (eq. 19)", "F",
             {history_key("s, N", "F"), harmonic_key("N"), end_key()}, {}}};
}

void ControlTraits<ForceControl>::validate(const ContactCase& contact_case, const ForceControl& /*control*/) {
    validate_force_history(contact_case);
    validate_harmonic(contact_case);
    validate_force_harmonic(contact_case);
}

double ControlTraits<ForceControl>::largest_contact_radius(const ContactCase& /*contact_case*/,
                                                           const ForceControl& /*control*/, double peak,
                                                           const ForceRadiusBound& force_bound) {
    return force_bound(peak);
}

std::vector<ControlKind> ControlTraits<SpringControl>::rows() {
    return {
        {"spring",
         "the history prescribes the base z(t) of a spring k in series with the massless indenter: F = k (z - d)", "z",
         {history_key("s, m", "z"),
          {"spring_constant", "N/m", "the spring's stiffness k > 0", true},
          harmonic_key("m"),
          {"force_pauses", "s", "[[start, end], ...]: the instrument's feedback holds the force over each"},
          end_key()},
         {}},
        {"shore",
         "a Shore A or D durometer (ASTM D2240, ISO 48-4): the standard's indenter pushed through its calibrated spring "
         "(spring control with a constant base); the reading H = 100 - d / 0.025 mm over time",
         "",
         {{"scale", "", "\"A\" (soft rubbers) or \"D\" (hard rubbers, plastics)", true},
          {"duration", "s",
           "how long the foot rests on the sample (default " + format_value(shore_default_duration) + ")"}},
         {}},
    };
}

void ControlTraits<SpringControl>::validate(const ContactCase& contact_case, const SpringControl& control) {
    validate_harmonic(contact_case);
    if (control.shore) {
        validate_shore(contact_case, control);  // the durometer's spring first: no spring_constant of its own
    } else {
        require_positive("load.spring_constant", control.spring_constant);
        validate_base_history(contact_case);
    }
}

BroughtParts ControlTraits<SpringControl>::bring(const SpringControl& control, double length_unit,
                                                 double force_unit) {
    if (!control.shore) return {.control = control};
    const ShoreTest test = make_shore_test(control.shore->scale, control.shore->duration, length_unit, force_unit);
    // 0 is the unset constant; the durometer's own is a case's read back (mdr.ContactCase(control=case.control)).
    if (control.spring_constant != 0.0 && control.spring_constant != test.instrument.spring_rate) {
        throw InvalidInput("load.spring_constant", format_value(control.spring_constant),
                           "not with control = \"shore\": the durometer's spring is the standard's, k = " +
                               format_value(test.instrument.spring_rate));
    }
    SpringControl completed = control;  // its pauses kept: validate refuses them
    completed.spring_constant = test.instrument.spring_rate;
    completed.shore = test;
    return {.control = std::move(completed),
            .indenter = durometer_indenter(test.scale, length_unit),
            .history = shore_base_history(test)};
}

std::string ControlTraits<SpringControl>::describe(const ContactCase& contact_case, const SpringControl& control,
                                                   const rheology::UnitNames& unit_names) {
    if (const auto& shore = control.shore) {
        const Durometer& instrument = shore->instrument;
        return fmt::format("Shore {} durometer (spring force {:.4g} {} at reading 100, falling {:.4g} {}; one point = "
                           "{:.4g} {}), the foot resting from t = 0 to {:.4g} {}",
                           shore->scale == ShoreScale::A ? "A" : "D", instrument.reading_100_force, unit_names("N"),
                           instrument.spring_rate, unit_names("N/m"), instrument.point_depth, unit_names("m"),
                           shore->duration, unit_names("s"));
    }
    std::string load = describe_history(
        contact_case, row_name(control),
        fmt::format(" (spring k = {:.4g} {})", control.spring_constant, unit_names("N/m")), unit_names);
    for (const ForcePause& pause : control.force_pauses) {
        load += fmt::format(", force held from t = {:.4g} to {:.4g} {}", pause.start, pause.end, unit_names("s"));
    }
    return load;
}

void ControlTraits<SpringControl>::validate_within_run(const ContactCase& contact_case, const SpringControl& control) {
    validate_force_pauses(contact_case, control);
}

double ControlTraits<SpringControl>::largest_contact_radius(const ContactCase& contact_case,
                                                            const SpringControl& control, double peak,
                                                            const ForceRadiusBound& force_bound) {
    // d <= z and F <= k z
    const auto& indenter = *contact_case.indenter;
    const double k = control.spring_constant;
    double base = peak;
    double force = k * peak;
    if (!control.force_pauses.empty()) {
        // The force at a depth d <= z is at most the elastic one with G(0+) (the contact only grows up to a
        // pause); each pause shifts the later base by its creep, at most the depth of that force's bound.
        const double modulus = contact_case.material.instantaneous_modulus();
        const auto at_most = [&](double z) {
            return std::isfinite(modulus)
                       ? std::min(k * z, elastic_force(indenter, modulus, indenter.contact_radius(z)))
                       : k * z;
        };
        const double creep = indenter.equivalent(std::min(force_bound(at_most(peak)), indenter.max_radius()));
        base = paused_base_peak(*contact_case.load.history, control.force_pauses, peak, creep);
        force = std::isfinite(base) ? at_most(base) : force;
    }
    // (An infinite bound: the force bound reaches the indenter's edge, which is then the half-width.)
    return std::isfinite(base) ? std::min(1.1 * indenter.contact_radius(base), force_bound(force))
                               : indenter.max_radius();
}

}  // namespace mdr::drivers
