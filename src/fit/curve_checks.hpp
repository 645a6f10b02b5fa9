#pragma once
// The rules every measured curve obeys, shared by make_curve (arrays) and load_curve (a CSV file).

#include <functional>
#include <string>
#include <vector>

#include "mdr/fit/curve.hpp"

namespace mdr::fit {

/// Where row i of a curve comes from, for messages ("in x.csv, line 17", "at index 16").
using RowLocation = std::function<std::string(std::size_t)>;

/// The curve from SI arrays after the checks (equal lengths, at least minimum_curve_rows rows, finite values, time
/// strictly increasing), with its contact estimates (estimate_contact). `origin` names the whole curve in
/// messages ("x.csv", "the arrays"). Keys of the errors: `time`, `depth`, `force`.
Curve checked_curve(std::string name, std::vector<double> time, std::vector<double> depth, std::vector<double> force,
                    const std::string& origin, const RowLocation& where);

}  // namespace mdr::fit
