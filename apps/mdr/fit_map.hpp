#pragma once
// `mdr fit CASE --map FILE --out DIR`: every curve of an instrument map fitted alone with the case's [fit]
// (mdr/fitcase/map_fit.hpp); DIR/map.csv has one row per pixel, DIR/map.json the grid (docs/instrument-to-map.md).

#include <string>

#include "mdr/fitcase/fit_case.hpp"
#include "mdr/io/result_directory.hpp"

namespace mdr::cli {

/// Fits every curve of `map` with `fit_case` (fitcase::require_map_case) on parallel::local_threads(jobs, curves)
/// threads (`jobs` 0: every core), with progress on stderr and Ctrl-C as for sweeps, writes map.csv and map.json
/// into `directory` and prints a summary. A pixel that fails is a row with its reason. Returns true when every
/// pixel's fit converged.
bool run_map(const fitcase::FitCase& fit_case, const std::string& map, const io::ResultDirectory& directory,
             unsigned jobs);

}  // namespace mdr::cli
