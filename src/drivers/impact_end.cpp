#include "impact_end.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "mdr/error.hpp"

namespace mdr::drivers {

void require_before_end(double time, double time_limit, double velocity) {
    if (time < time_limit) return;
    throw InvalidInput("load.end", format_value(time_limit),
                       "the contact has not ended by then (velocity v = " + format_value(velocity) +
                           "): the indenter does not rebound in time; give a later load.end");
}

double impact_progress(double time, bool ended, const ResolvedNumerics& numerics) {
    if (ended) return 1.0;
    constexpr double by_expected_end = 0.9;
    const double expected = numerics.expected_end, limit = numerics.time_limit;
    if (time < expected) return by_expected_end * time / expected;
    const double beyond = limit > expected ? (time - expected) / (limit - expected) : 1.0;
    return std::min(by_expected_end + (1.0 - by_expected_end) * beyond, std::nextafter(1.0, 0.0));
}

ImpactOutcome impact_outcome(const ImpactEnd& end) {
    const double rebound = -(end.velocity - end.force * end.fraction * end.time_step / (2.0 * end.mass));
    ImpactOutcome outcome;
    outcome.contact_time = end.time + end.fraction * end.time_step;
    outcome.rebound_velocity = rebound;
    outcome.restitution = rebound / end.approach;
    outcome.dissipated_energy = 0.5 * end.mass * (end.approach * end.approach - rebound * rebound);
    if (!(outcome.restitution >= 0.0 && outcome.restitution <= 1.0 + 1e-6)) {
        throw std::runtime_error(fmt::format(
            "the impact is not resolved at these numerics: restitution e = {} lies outside [0, 1]; give a smaller "
            "numerics.time_step (now {:.4g} s) or more numerics.elements",
            outcome.restitution, end.time_step));
    }
    return outcome;
}

}  // namespace mdr::drivers
