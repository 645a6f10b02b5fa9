#include "mdr/drivers/harmonic_load.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mdr::drivers {

double HarmonicLoad::value(double t) const {
    if (t < start) return 0.0;
    return amplitude * std::sin(2.0 * std::numbers::pi * frequency * (std::min(t, end) - start));
}

double HarmonicLoad::rate(double t) const {
    if (t < start || t >= end) return 0.0;
    const double omega = 2.0 * std::numbers::pi * frequency;
    return amplitude * omega * std::cos(omega * (t - start));
}

std::vector<double> HarmonicLoad::breakpoints() const {
    std::vector<double> times{start, end};
    if (const auto cycle = last_full_cycle(end)) {
        times.push_back(cycle->first);
        times.push_back(cycle->second);
    }
    return times;
}

std::optional<std::pair<double, double>> HarmonicLoad::last_full_cycle(double simulated_end) const {
    const double last = std::min(end, simulated_end);
    // The tolerance keeps a cycle count such as 5 - 1e-15 from dropping a whole cycle.
    const double cycles = std::floor((last - start) * frequency + 1e-9);
    if (cycles < 1.0) return std::nullopt;
    return std::pair{start + (cycles - 1.0) * period(), std::min(start + cycles * period(), last)};
}

}  // namespace mdr::drivers
