#pragma once
/// \file
/// The chi-squared distribution's distribution function and quantiles, for the consistency range of a sample
/// standard deviation (fit::spread_of_repeats).

namespace mdr::numerics {

/// P(X <= x) for X chi-squared with `degrees` > 0 degrees of freedom: the regularised lower incomplete gamma
/// function P(degrees / 2, x / 2), by its series below a + 1 and its continued fraction above (Abramowitz & Stegun
/// 6.5.29 and 6.5.31), to about 1e-14. 0 for x <= 0.
double chi_squared_cdf(double degrees, double x);

/// The x with chi_squared_cdf(degrees, x) = probability, 0 < probability < 1, by bisection on the logarithm of x to
/// 1e-13 of x. Throws std::invalid_argument outside those ranges.
double chi_squared_quantile(double degrees, double probability);

}  // namespace mdr::numerics
