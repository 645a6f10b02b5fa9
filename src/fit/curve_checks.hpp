#pragma once
// The rules every measured curve obeys, shared by make_curve (arrays) and the fit case's readers of files
// (src/fitcase: fitcase::load_curve, fitcase::instrument_fit_curve), which include this header of fit.

#include <functional>
#include <string>
#include <vector>

#include "mdr/fit/curve.hpp"

namespace mdr::fit {

/// The largest magnitude of a curve's value (time, depth, force in the case's units). The fit differences, squares
/// and sums the values (noise and contact estimates, residuals): within [1e-100, 1e100] those stay finite and keep
/// their precision for any realistic number of rows.
inline constexpr double largest_curve_value = 1e100;
/// The smallest magnitude of a curve's value other than 0 (see largest_curve_value).
inline constexpr double smallest_curve_value = 1e-100;

/// True when `value` is 0 or of a magnitude within [smallest_curve_value, largest_curve_value].
bool curve_value_in_range(double value);

/// The rule of curve_value_in_range, for messages.
std::string curve_value_rule();

/// Where row i of a curve comes from, for messages ("in x.csv, line 17", "at index 16").
using RowLocation = std::function<std::string(std::size_t)>;

/// The curve from SI arrays after the checks (equal lengths, at least minimum_curve_rows rows, finite values in the
/// range of curve_value_in_range, time strictly increasing), with its contact estimates (estimate_contact). `origin`
/// names the whole curve in messages ("x.csv", "the arrays"). Keys of the errors: `time`, `depth`, `force`.
Curve checked_curve(std::string name, std::vector<double> time, std::vector<double> depth, std::vector<double> force,
                    const std::string& origin, const RowLocation& where);

}  // namespace mdr::fit
