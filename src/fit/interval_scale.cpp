#include "interval_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mdr::fit {

IntervalScale interval_scale(const FreeParameter& parameter) {
    if (std::isfinite(parameter.domain_upper)) return IntervalScale::logit;
    return on_logarithm(parameter) ? IntervalScale::log : IntervalScale::linear;
}

std::string interval_scale_name(IntervalScale scale) {
    switch (scale) {
        case IntervalScale::linear: return "linear";
        case IntervalScale::log: return "log";
        case IntervalScale::logit: return "logit";
    }
    return "linear";
}

std::array<double, 2> interval_on_scale(IntervalScale scale, double value, double standard_error, double quantile,
                                        double domain_lower, double domain_upper) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double half = quantile * standard_error;
    switch (scale) {
        case IntervalScale::linear: return {std::max(value - half, domain_lower), value + half};
        case IntervalScale::log: {
            if (!(value > 0.0) || !std::isfinite(value)) return {nan, nan};
            const double spread = half / value;  // g'(x) = 1 / x
            return {value * std::exp(-spread), value * std::exp(spread)};
        }
        case IntervalScale::logit: {
            const double limit = domain_upper;
            if (!(value > 0.0 && value < limit)) return {nan, nan};
            // g(x) = ln(x / (L - x)), g'(x) = L / (x (L - x)), g^-1(u) = L / (1 + exp(-u)), L = limit.
            const double centre = std::log(value / (limit - value));
            const double spread = half * limit / (value * (limit - value));
            const auto back = [limit](double u) { return limit / (1.0 + std::exp(-u)); };
            return {back(centre - spread), back(centre + spread)};
        }
    }
    return {nan, nan};
}

}  // namespace mdr::fit
