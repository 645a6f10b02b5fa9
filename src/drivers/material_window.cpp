#include "mdr/drivers/material_window.hpp"

#include <algorithm>
#include <cmath>

#include "mdr/error.hpp"

namespace mdr::drivers {

rheology::TimeWindow material_window(const LoadHistory& history, double end_time, const NumericsOptions& numerics,
                                     const std::optional<TangentialLoad>& tangential, bool impact) {
    const char* rule = "a material converted to a Prony series needs the problem's time window";
    if (impact && !std::isfinite(end_time)) {
        throw InvalidInput("load.end", "(missing)", std::string(rule) + ": give load.end for an impact");
    }
    if (impact && !numerics.time_step) {
        throw InvalidInput("numerics.time_step", "(missing)", std::string(rule) + ": give it for an impact");
    }
    const double duration = end_time - history.start_time();
    if (!(duration > 0.0) || !std::isfinite(duration)) {
        throw InvalidInput("load.end", format_value(end_time),
                           std::string(rule) + ": the history must last (end after its first time)");
    }
    double step = numerics.time_step.value_or(duration / static_cast<double>(default_steps));
    if (!numerics.time_step && tangential && tangential->harmonic) {
        step = std::min(step, 1.0 / tangential->harmonic->frequency / default_steps_per_period);
    }
    if (numerics.time_step) require_positive("numerics.time_step", step);
    const double shortest = std::min(step / 5.0, duration / 10.0);
    return {shortest, duration};
}

}  // namespace mdr::drivers
