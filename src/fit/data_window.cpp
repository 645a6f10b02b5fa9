#include "data_window.hpp"

#include <algorithm>
#include <exception>
#include <limits>

namespace mdr::fit {

namespace {

// The contact time of every impact of `rebound`: measured, else the elastic estimate at `values`.
std::vector<double> contact_times(const FitProblem& problem, const ReboundData& rebound,
                                  const std::vector<double>& values) {
    if (!rebound.contact_time.empty()) return rebound.contact_time;
    std::vector<double> times;
    try {
        const auto model_case = problem.model(values);
        const double modulus = model_case.material.relaxation(0.0);
        for (double velocity : rebound.velocity) {
            times.push_back(drivers::elastic_impact(*model_case.indenter, modulus, rebound.mass, velocity).duration);
        }
    } catch (const std::exception&) {
        times.clear();  // values the case refuses: this data set adds nothing to the window
    }
    return times;
}

}  // namespace

DataWindow data_window(const FitProblem& problem, const std::vector<double>& values) {
    DataWindow window{std::numeric_limits<double>::infinity(), 0.0};
    for (const auto& curve : problem.curves) {
        for (std::size_t i = 1; i < curve.time.size(); ++i) {
            window.finest = std::min(window.finest, curve.time[i] - curve.time[i - 1]);
        }
        window.longest = std::max(window.longest, curve.time.back() - curve.time.front());
    }
    for (const auto& rebound : problem.rebounds) {
        for (double duration : contact_times(problem, rebound, values)) {
            window.finest = std::min(window.finest, duration / rebound_resolution);
            window.longest = std::max(window.longest, duration);
        }
    }
    return window;
}

}  // namespace mdr::fit
