#pragma once
/// \file
/// The 95 % interval of a fitted parameter (internal to mdr_fit): built on the scale on which the parameter's open
/// physical domain is the whole real line, so that it always lies inside that domain. The standard error stays the
/// first-order one at the value; the interval is value-space's image of g(value) -/+ t g'(value) standard_error.

#include <array>
#include <string>

#include "mdr/fit/fit.hpp"

namespace mdr::fit {

/// The scale of a parameter's interval, chosen by its domain.
enum class IntervalScale {
    linear,  ///< the whole line (a parameter fitted linearly, domain unbounded): g(x) = x
    log,     ///< (0, infinity): g(x) = ln x
    logit,   ///< (0, L), L = FreeParameter::domain_upper finite: g(x) = ln(x / (L - x))
};

/// The scale of `parameter`'s interval: logit when its domain has a finite upper end, log when it is fitted on its
/// logarithm (on_logarithm), else linear.
IntervalScale interval_scale(const FreeParameter& parameter);

/// Its name in fit.json's `interval_scales`: "linear", "log" or "logit".
std::string interval_scale_name(IntervalScale scale);

/// [lower, upper] = g^-1(g(value) -/+ quantile g'(value) standard_error) on `scale` (domain (0, domain_upper) for
/// logit; on the linear scale the interval ends at domain_lower: the part below holds no value of the parameter, so
/// the cut keeps the coverage). A value on the edge of its domain (log, logit), or not finite, has no such interval:
/// NaN, NaN.
std::array<double, 2> interval_on_scale(IntervalScale scale, double value, double standard_error, double quantile,
                                        double domain_lower, double domain_upper);

}  // namespace mdr::fit
