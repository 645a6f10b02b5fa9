#pragma once
/// \file
/// Parameter sweeps (`mdr sweep`): a case run over the cartesian product of grids of numeric keys.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "mdr/io/case_template.hpp"
#include "mdr/io/summary.hpp"

namespace mdr::io {

/// What a sweep varies: a case whose numbers are named by the dotted keys of a case file (`material.tau1`,
/// `load.history[1][1]`). A case file's is its CaseTemplate (its tables, read again at every point); a case given as
/// objects is an io::CaseObjects (its parts, a typed value set on a copy of the part a key names).
class SweepCase {
public:
    virtual ~SweepCase() = default;
    /// True when `key` names a number of the case.
    virtual bool has_number(const std::string& key) const = 0;
    /// The rule a key that is not among has_number's breaks, for the message naming `--vary` and the key.
    virtual std::string numbers_rule() const = 0;
    /// The validated case with `values[a]` under `keys[a]` (no keys: the case itself). Throws mdr::InvalidInput
    /// (naming the key, the value and the rule) for a value the case's rules refuse.
    virtual drivers::ContactCase build(const std::vector<std::string>& keys,
                                       const std::vector<double>& values) const = 0;
};

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
    Summary summary;             ///< the run's summary (empty if it failed)
    std::string error;           ///< the failure message ("" if it succeeded)
};

/// The most points one sweep may have; the rows of a sweep are kept in memory (about 1 kB each).
inline constexpr std::size_t max_sweep_points = 1'000'000;

/// The number of points of the cartesian product of the axes. Throws mdr::InvalidInput (key `--vary`) when it
/// exceeds max_sweep_points (computed without overflow).
std::size_t sweep_size(const std::vector<SweepAxis>& axes);

/// Checks the grid size (sweep_size), and that every axis names a numeric key present in the case (and the case
/// itself). Throws
/// mdr::InvalidInput otherwise.
void validate_sweep(std::string_view case_text, const std::string& source, const std::vector<SweepAxis>& axes);
/// validate_sweep of a case already parsed (or given as a tree).
void validate_sweep(const CaseTemplate& model, const std::vector<SweepAxis>& axes);
/// validate_sweep of any case a sweep varies (the one rule of its keys and their message).
void validate_sweep(const SweepCase& model, const std::vector<SweepAxis>& axes);

/// The points of the cartesian product of the axes, in row order (the last axis varying fastest): the value of each
/// axis at each row. Throws mdr::InvalidInput for a grid above max_sweep_points.
std::vector<std::vector<double>> sweep_points(const std::vector<SweepAxis>& axes);

/// Runs the case at the given points (`points[r][a]` is the value of `keys[a]` at row r) on `jobs` threads, with
/// the rules of run_sweep: rows in the order of `points`, failures kept as messages, the same `progress`. A row
/// does not depend on the other rows, nor on `jobs`: any split of the points gives the same rows, bit for bit (the
/// distributed sweep of python/mdr/distributed.py runs chunks of points with it).
std::vector<SweepRow> run_sweep_points(std::string_view case_text, const std::string& source,
                                       const std::vector<std::string>& keys, std::vector<std::vector<double>> points,
                                       unsigned jobs, const std::function<void(std::size_t, std::size_t)>& progress);
/// run_sweep_points of a case already parsed (or given as a tree).
std::vector<SweepRow> run_sweep_points(const CaseTemplate& model, const std::vector<std::string>& keys,
                                       std::vector<std::vector<double>> points, unsigned jobs,
                                       const std::function<void(std::size_t, std::size_t)>& progress);
/// run_sweep_points of any case a sweep varies: each point's case is model.build(keys, point).
std::vector<SweepRow> run_sweep_points(const SweepCase& model, const std::vector<std::string>& keys,
                                       std::vector<std::vector<double>> points, unsigned jobs,
                                       const std::function<void(std::size_t, std::size_t)>& progress);

/// Runs the case at every point of the cartesian product of the axes (the last axis varying fastest) on `jobs`
/// threads (at most one a point; with more than one, the points are handed out costliest first by
/// drivers::estimate_work, so that no large point starts last). Rows come back in grid order whatever the number of
/// jobs; a failed point keeps its message and does not stop the others, and so does a point whose summary is not
/// finite. `progress(done, total)` is called from the calling thread as points finish, at least every 0.2 s and at
/// the end; when it throws, the running points are stopped at their next progress report, every thread is joined
/// and the exception propagates.
/// Throws mdr::InvalidInput for a grid above max_sweep_points, std::runtime_error when a thread cannot be started.
std::vector<SweepRow> run_sweep(std::string_view case_text, const std::string& source,
                                const std::vector<SweepAxis>& axes, unsigned jobs,
                                const std::function<void(std::size_t, std::size_t)>& progress);
/// run_sweep of a case already parsed (or given as a tree).
std::vector<SweepRow> run_sweep(const CaseTemplate& model, const std::vector<SweepAxis>& axes, unsigned jobs,
                                const std::function<void(std::size_t, std::size_t)>& progress);
/// run_sweep of any case a sweep varies.
std::vector<SweepRow> run_sweep(const SweepCase& model, const std::vector<SweepAxis>& axes, unsigned jobs,
                                const std::function<void(std::size_t, std::size_t)>& progress);

/// The numeric keys (numbers and counts, not flags) of the rows' summaries by union_of_keys (mdr/document.hpp), the
/// rule of map.csv's columns too: rows whose keys follow one order (a summary's) give that order whatever the order
/// of the rows. The columns of sweep.csv between the varied keys and `error`, and of mdr.sweep's table.
std::vector<std::string> sweep_columns(const std::vector<SweepRow>& rows);

/// Writes sweep.csv into `directory`: the varied keys (named as given), then sweep_columns (`nan` where a row lacks
/// one), then `error` (empty for rows that succeeded; a failed row's numeric fields are `nan`). Text fields are
/// quoted by RFC 4180 (csv_field).
void write_sweep_csv(const std::filesystem::path& directory, const std::vector<SweepAxis>& axes,
                     const std::vector<SweepRow>& rows);

}  // namespace mdr::io
