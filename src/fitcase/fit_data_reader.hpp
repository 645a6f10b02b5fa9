#pragma once
// Reads one `[[fit.data]]` table of a fit case: where a measured curve's columns are (docs/case-format.md,
// "Measured curves").

#include <filesystem>
#include <string>
#include <vector>

#include "mdr/fit/curve.hpp"
#include "mdr/fit/rebound.hpp"
#include "mdr/fitcase/curve_source.hpp"
#include "mdr/io/units.hpp"
#include "io/toml_reader.hpp"

namespace mdr::fitcase {

/// The CurveSource of one `[[fit.data]]` table: `file` (relative to `case_directory` unless absolute), the column
/// keys `time`, `depth`, `force`, `piezo`, `deflection`, `segment_column`, and `spring_constant` (N/m), `units`,
/// `segments`, `name`; the data's units and the spring constant converted to the case's `system`. A table that
/// names no column is an instrument file's (CurveSource::instrument): `curve` (an index >= 0) is read, `units`,
/// `spring_constant` and `segment_column` are refused (the file states them). Refuses unknown
/// keys (suggesting the nearest) and values of the wrong type; the rules that relate the keys (one depth source,
/// the spring constant with the AFM columns, ...) are load_curve's, checked when the curve is loaded.
CurveSource read_fit_data(io::TableReader& table, const std::filesystem::path& case_directory,
                          const io::UnitSystem& system);

/// The ReboundSource of a `[[fit.data]]` table with `kind = "rebound"`: `file`, `name`, the column keys
/// `velocity`, `restitution`, `contact_time`, the uncertainties `restitution_error` and `contact_time_error` (a
/// number, or a column name), `mass` and `units` (`velocity`: m/s with an SI prefix or a factor, `time`). Refuses
/// unknown keys and values of the wrong type; the other rules are load_rebound's. The units are converted to the
/// case's `system`.
fit::ReboundSource read_rebound_data(io::TableReader& table, const std::filesystem::path& case_directory,
                                     const io::UnitSystem& system);

/// The string at `key`, one of `choices` (`fallback` when absent); mdr::InvalidInput listing them otherwise.
std::string choice(io::TableReader& table, const std::string& key, const std::vector<std::string>& choices,
                   const std::string& fallback);

/// `fitted` of a `[fit]` or `[[fit.data]]` table ("force" or "depth"), `fallback` when absent.
fit::Fitted read_fitted(io::TableReader& table, fit::Fitted fallback);

/// The size of one unit of a `units` entry in units of the case's system, whose unit of this quantity is
/// `system_size` in SI (UnitSystem::length_size, ...): the entry is the data unit's size in SI (s, m, N or m/s for
/// `base`), a number > 0 or a name made of an SI prefix (p, n, u or µ, m, c, k, or none) and `base` ("nm", "ms",
/// "nN", "m"); the result is that size / `system_size`, 1 when the entry is absent (data in the case's units). `key`
/// names the entry.
double read_unit(io::TableReader& units, const std::string& key, const std::string& base, double system_size);

}  // namespace mdr::fitcase
