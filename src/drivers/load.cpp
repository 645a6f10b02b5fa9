#include "mdr/drivers/load.hpp"

#include <algorithm>
#include <cmath>

namespace mdr::drivers {

double Load::value(double t) const {
    if (!harmonic) return history->value(t);
    if (!history) return harmonic->value(t);
    return history->value(t) + harmonic->value(t);
}

double Load::start_rate(double t0, double v0, double t1, double v1) const {
    const double h0 = harmonic ? harmonic->value(t0) : 0.0, h1 = harmonic ? harmonic->value(t1) : 0.0;
    return ((v1 - h1) - (v0 - h0)) / (t1 - t0) + (harmonic ? harmonic->rate(t0) : 0.0);
}

double Load::largest_value() const {
    return history->max_value() + (harmonic ? std::abs(harmonic->amplitude) : 0.0);
}

double Load::end_time() const {
    if (!harmonic) return history->end_time();
    if (!history) return harmonic->end;
    return std::max(history->end_time(), harmonic->end);
}

std::vector<double> Load::breakpoints() const {
    std::vector<double> times;
    if (history) {
        for (const auto& point : history->points()) times.push_back(point.time);
    }
    if (harmonic) {
        const auto cycle = harmonic->breakpoints();
        times.insert(times.end(), cycle.begin(), cycle.end());
    }
    return times;
}

std::optional<std::pair<double, double>> Load::last_full_cycle(double simulated_end) const {
    if (!harmonic) return std::nullopt;
    return harmonic->last_full_cycle(simulated_end);
}

}  // namespace mdr::drivers
