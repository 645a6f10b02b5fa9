#pragma once
/// \file
/// Independent pieces of work on local threads, with progress reported and a stop asked for on the calling thread:
/// the one loop of `mdr sweep --jobs` (mdr/io/sweep.hpp) and of `mdr fit --map --jobs` (mdr/fitcase/map_fit.hpp).

#include <atomic>
#include <cstddef>
#include <functional>

namespace mdr::parallel {

/// The cores this process may run on (its CPU affinity), at least 1: the bound of local threads, as
/// `mdr._jobs.cores()` is in Python.
unsigned available_cores();

/// How many local threads run `items` items when `jobs` are asked for: min(jobs, available_cores(), items), at
/// least 1; `jobs` 0 means every core. The rule of `mdr.fit_map(jobs=)` (python/mdr/_jobs.py, local_workers).
unsigned local_threads(unsigned jobs, std::size_t items);

/// Runs `work(item, worker, stop)` once for every item < `count` on `threads` threads (at least 1, at most
/// `count` start; `worker` < that number names the thread, so that it may keep its own state), the items taken in
/// increasing order, each by the first free thread. Meanwhile the calling thread calls `report(done)` (the items
/// finished) every 0.2 s and once at the end, outside any lock: it may stop the work by throwing, which sets
/// `stop`, joins the threads (work in progress should check `stop` and return early) and passes the exception on.
/// The first exception thrown by `work` also sets `stop`; it is rethrown once the threads are joined. Throws
/// std::runtime_error naming `--jobs` when a thread cannot be started.
void run_on_threads(std::size_t count, unsigned threads,
                    const std::function<void(std::size_t item, unsigned worker, const std::atomic<bool>& stop)>& work,
                    const std::function<void(std::size_t done)>& report);

}  // namespace mdr::parallel
