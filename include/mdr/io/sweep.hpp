#pragma once
/// \file
/// Parameter sweeps (`mdr sweep`): a case run over the cartesian product of grids of numeric keys.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace mdr::io {

/// One varied key and its values.
struct SweepAxis {
    std::string key;              ///< dotted key as given, e.g. `material.tau1`
    std::vector<double> values;   ///< grid values, in the order given
};

/// Parses `KEY=START:STOP:COUNT[:log]` (COUNT points from START to STOP, linear or logarithmic) or
/// `KEY=v1,v2,...` (the listed values). Throws mdr::InvalidInput (key `--vary`) for a malformed spec, a count
/// below 1, a non-finite bound, or a non-positive bound on a log grid.
SweepAxis parse_sweep_axis(const std::string& spec);

/// One grid point's outcome.
struct SweepRow {
    std::vector<double> point;   ///< the value of each axis
    std::string summary_json;    ///< the run's summary.json ("" if it failed)
    std::string error;           ///< the failure message ("" if it succeeded)
};

/// Checks that every axis names a numeric key present in the case (and the case itself). Throws
/// mdr::InvalidInput otherwise.
void validate_sweep(std::string_view case_text, const std::string& source, const std::vector<SweepAxis>& axes);

/// Runs the case at every point of the cartesian product of the axes (the last axis varying fastest) on `jobs`
/// threads. Rows come back in grid order whatever the number of jobs; a failed point keeps its message and does not
/// stop the others. `progress(done, total)` is called from the calling thread as points finish.
std::vector<SweepRow> run_sweep(std::string_view case_text, const std::string& source,
                                const std::vector<SweepAxis>& axes, unsigned jobs,
                                const std::function<void(std::size_t, std::size_t)>& progress);

/// Writes sweep.csv into `directory`: the varied keys (named as given), then every numeric key of summary.json
/// (in its order), then `error` (empty for rows that succeeded; their numeric fields are then `nan`).
void write_sweep_csv(const std::filesystem::path& directory, const std::vector<SweepAxis>& axes,
                     const std::vector<SweepRow>& rows);

}  // namespace mdr::io
