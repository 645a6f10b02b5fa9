#include "reference/piecewise_linear.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace mdr::reference {
namespace {

// Index i of the piece [times[i], times[i+1]] holding t, the earlier piece at a breakpoint.
std::size_t piece_index(const std::vector<double>& times, double t) {
    const auto upper = std::lower_bound(times.begin(), times.end(), t);
    const auto index = static_cast<std::size_t>(upper - times.begin());
    return std::clamp<std::size_t>(index, 1, times.size() - 1) - 1;
}

}  // namespace

double PiecewiseLinear::value(double t) const {
    if (t <= times.front()) return values.front();
    if (t >= times.back()) return values.back();
    const std::size_t i = piece_index(times, t);
    const double weight = (t - times[i]) / (times[i + 1] - times[i]);
    return values[i] + weight * (values[i + 1] - values[i]);
}

double PiecewiseLinear::slope(double t) const {
    if (t <= times.front() || t > times.back()) return 0.0;
    const std::size_t i = piece_index(times, t);
    return (values[i + 1] - values[i]) / (times[i + 1] - times[i]);
}

void PiecewiseLinear::validate() const {
    if (times.size() != values.size())
        throw std::invalid_argument("reference history.values size = " + std::to_string(values.size()) +
                                    ": must equal times size " + std::to_string(times.size()));
    if (times.size() < 2)
        throw std::invalid_argument("reference history.times size = " + std::to_string(times.size()) + ": must be >= 2");
    for (std::size_t i = 1; i < times.size(); ++i)
        if (!(times[i] > times[i - 1]))
            throw std::invalid_argument("reference history.times[" + std::to_string(i) + "] = " +
                                        std::to_string(times[i]) + ": must be > the previous time");
}

}  // namespace mdr::reference
