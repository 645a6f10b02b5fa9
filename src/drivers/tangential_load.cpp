#include "mdr/drivers/tangential_load.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mdr::drivers {

double TangentialLoad::value(double t) const {
    if (history) return history->value(t);
    const HarmonicLoad& h = *harmonic;
    if (t < h.start) return 0.0;
    const double phase = 2.0 * std::numbers::pi * h.frequency * (std::min(t, h.end) - h.start);
    return h.amplitude * std::sin(phase);
}

double TangentialLoad::end_time() const { return history ? history->end_time() : harmonic->end; }

std::vector<double> TangentialLoad::breakpoints() const {
    std::vector<double> times;
    if (history) {
        for (const auto& point : history->points()) times.push_back(point.time);
    } else {
        times = {harmonic->start, harmonic->end};
        if (const auto cycle = last_full_cycle(harmonic->end)) {
            times.push_back(cycle->first);
            times.push_back(cycle->second);
        }
    }
    return times;
}

std::optional<std::pair<double, double>> TangentialLoad::last_full_cycle(double simulated_end) const {
    if (!harmonic) return std::nullopt;
    const double last = std::min(harmonic->end, simulated_end);
    // The tolerance keeps a cycle count such as 5 - 1e-15 from dropping a whole cycle.
    const double cycles = std::floor((last - harmonic->start) * harmonic->frequency + 1e-9);
    if (cycles < 1.0) return std::nullopt;
    const double period = 1.0 / harmonic->frequency;
    return std::pair{harmonic->start + (cycles - 1.0) * period, std::min(harmonic->start + cycles * period, last)};
}

}  // namespace mdr::drivers
