#include "mdr/drivers/tangential_load.hpp"

namespace mdr::drivers {

double TangentialLoad::value(double t) const { return history ? history->value(t) : harmonic->value(t); }

double TangentialLoad::end_time() const { return history ? history->end_time() : harmonic->end; }

std::vector<double> TangentialLoad::breakpoints() const {
    if (harmonic) return harmonic->breakpoints();
    std::vector<double> times;
    for (const auto& point : history->points()) times.push_back(point.time);
    return times;
}

std::optional<std::pair<double, double>> TangentialLoad::last_full_cycle(double simulated_end) const {
    if (!harmonic) return std::nullopt;
    return harmonic->last_full_cycle(simulated_end);
}

}  // namespace mdr::drivers
