#include "parameter_scales.hpp"

#include <algorithm>
#include <cmath>

namespace mdr::fit {

bool fitted_on_logarithm(const FreeParameter& parameter) {
    return parameter.lower > 0.0 && parameter.start > 0.0 && !std::isfinite(parameter.domain_upper);
}

bool on_logarithm(const FreeParameter& parameter) {
    return parameter.logarithmic.value_or(fitted_on_logarithm(parameter));
}

double ParameterScales::to_internal(std::size_t j, double value) const {
    return scale[j] == 0.0 ? std::log(value) : value / scale[j];
}

double ParameterScales::to_value(std::size_t j, double u) const {
    return scale[j] == 0.0 ? std::exp(u) : u * scale[j];
}

std::vector<double> ParameterScales::values(const double* u) const {
    std::vector<double> result(scale.size());
    for (std::size_t j = 0; j < scale.size(); ++j) result[j] = to_value(j, u[j]);
    return result;
}

ParameterScales make_scales(const FitProblem& problem) {
    ParameterScales scales;
    for (const auto& parameter : problem.parameters) {
        scales.scale.push_back(on_logarithm(parameter)
                                   ? 0.0
                                   : std::max({std::abs(parameter.start), 0.5 * (parameter.upper - parameter.lower),
                                               1e-300}));
    }
    for (std::size_t j = 0; j < scales.scale.size(); ++j) {
        scales.lower.push_back(scales.to_internal(j, problem.parameters[j].lower));
        scales.upper.push_back(scales.to_internal(j, problem.parameters[j].upper));
    }
    for (const auto& curve : problem.curves) {
        double depth = 0.0;
        double force = 0.0;
        for (double d : curve.depth) depth = std::max(depth, std::abs(d));
        for (double f : curve.force) force = std::max(force, std::abs(f));
        scales.depth.push_back(std::max(depth, 1e-300));
        scales.force.push_back(std::max(force, 1e-300));
    }
    scales.fit_contact = problem.settings.contact_point == ContactPointMode::fit;
    scales.fit_baseline = problem.settings.baseline == BaselineMode::fit;
    return scales;
}

}  // namespace mdr::fit
