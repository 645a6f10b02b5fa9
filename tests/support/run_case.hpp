#pragma once
// Running a case written as TOML text, for verification tests.

#include <string>
#include <vector>

#include "mdr/drivers/indentation.hpp"

namespace mdr::testing {

/// Parses `toml_text` with the case-file parser and runs it.
drivers::IndentationResult run_toml(const std::string& toml_text);

/// Linear interpolation of (x, y) at `at` (x ascending).
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at);

/// max |F - F_ref| row by row over the peak |F_ref|, two runs on the same time grid (a differing row count is a
/// test failure; the common rows are compared).
double force_difference(const drivers::IndentationResult& result, const drivers::IndentationResult& reference);

/// log2(e_coarse / e_fine): the observed order of a halving refinement.
double observed_order(double coarse_error, double fine_error);

}  // namespace mdr::testing
