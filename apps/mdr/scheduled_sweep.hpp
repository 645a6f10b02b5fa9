#pragma once
// `mdr sweep --scheduler tcp://HOST:PORT`: the rows of a sweep computed on a Dask cluster. The command line keeps
// everything else (validation, the result directory, sweep.csv, progress, Ctrl-C); the rows come from the installed
// Python package (`python3 -m mdr._sweep_rows`, python/mdr/_sweep_rows.py), which holds the Dask client: one
// implementation of the distributed sweep, shared with mdr.sweep(..., scheduler=...). docs/distributed.md.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "mdr/io/sweep.hpp"

namespace mdr::cli {

/// How a scheduled sweep ran (also written to scheduler.json in the result directory).
struct ScheduledSweepInfo {
    std::string scheduler;      ///< the scheduler's address
    std::size_t workers = 0;    ///< workers when the sweep started
    std::size_t tasks = 0;      ///< chunks sent
    std::size_t retried = 0;    ///< chunks sent again after their worker was lost
    std::string python;         ///< the Python interpreter that ran the client
};

/// The Python interpreter that runs the client: $MDR_PYTHON, else `python3` beside this executable (a venv's or
/// /usr/bin's), else `python3` on PATH.
std::string scheduler_python();

/// Runs the sweep's points on the scheduler and returns its rows in grid order, the same as io::run_sweep's (bit for
/// bit, but wall_seconds). `progress(done, total)` is called as chunks finish (at least every 0.5 s); when it throws,
/// the helper is asked to stop (SIGINT: it cancels its tasks) and waited for, and the exception propagates.
/// Throws mdr::InvalidInput for input the helper refuses (the scheduler cannot be reached, ...), std::runtime_error
/// when the helper cannot be started or ends without a result.
std::vector<io::SweepRow> run_scheduled_sweep(const std::string& case_text, const std::string& source,
                                              const std::vector<std::string>& specs,
                                              const std::vector<io::SweepAxis>& axes, const std::string& scheduler,
                                              const std::function<void(std::size_t, std::size_t)>& progress,
                                              ScheduledSweepInfo& info);

}  // namespace mdr::cli
