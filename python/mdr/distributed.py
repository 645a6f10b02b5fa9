"""Batches on the local cores or on a Dask cluster: a chunked, ordered, fault-tolerant map.

`ordered_map` runs a picklable chunk function over the items 0..total-1 in chunks and returns the per-item outputs in
item order, whatever ran where. With `scheduler=None` the chunks run in local processes; with a Dask scheduler
address (``"tcp://HOST:PORT"``) or a ``distributed.Client`` they run on its workers. `mdr.sweep(...,
scheduler=...)` and `mdr.map_curves` (python/mdr/curve_maps.py) are built on it; docs/distributed.md tells how to
deploy the workers.

Chunks: every task reports the compute time of its items; the next chunks carry about `target_seconds` of work
(0.1 s: Dask's ~2.5 ms per task is then ~2.5 % of the compute), shrinking towards the end of the run so that the
last tasks finish together (never below a quarter of the target). At most two chunks per worker thread are in
flight, so memory stays bounded and the sizes follow the measured cost.

Faults: a chunk whose worker dies is sent again by the scheduler (Dask's `allowed-failures`, 3 by default; a chunk
that kills more workers than that fails the run). Every item's output is placed by its index, once: a chunk that
ran twice cannot duplicate rows. `MapOutcome.retried` counts the chunks the scheduler had to send again because
the worker holding them was lost (the scheduler's `suspicious` count of each task, read before it is released).
"""

from __future__ import annotations

import concurrent.futures
import functools
import math
import queue
import signal
import time
import uuid
from dataclasses import dataclass
from typing import Any, Callable, Sequence

from . import _mdr
from ._jobs import check_jobs, local_workers

#: Seconds of work a chunk should carry (Dask's scheduling overhead is ~2.5 ms a task, docs/performance.md).
TARGET_SECONDS = 0.1
#: The most items in one chunk, and about the most bytes of data it carries (the data of a task travels through the
#: scheduler: below 1 MB, Dask's large-object threshold; an item that costs less to compute than to move is better
#: mapped locally).
MAX_CHUNK = 10_000
MAX_CHUNK_BYTES = 900_000
#: How long to wait for the first worker of a scheduler. (How long to wait for the scheduler itself is Dask's
#: setting distributed.comm.timeouts.connect, 30 s; environment DASK_DISTRIBUTED__COMM__TIMEOUTS__CONNECT.)
WORKER_TIMEOUT = 30.0


@dataclass
class MapOutcome:
    """What `ordered_map` did: `outputs[i]` is the chunk function's output for item i; `scheduler` is the address
    (or "local"); `workers` and `threads` what ran the chunks; `tasks` the number of chunks; `retried` the chunks
    sent again after a worker was lost; `seconds` the wall time; `compute_seconds` the sum of the chunks' own times
    (where they ran: `tasks` x overhead per task over it is the share of scheduling)."""

    outputs: list
    scheduler: str
    workers: int
    threads: int
    tasks: int
    retried: int
    seconds: float
    compute_seconds: float


class SchedulerError(ValueError):
    """The scheduler cannot be used: `address` and `rule` (the message is "scheduler = ADDRESS: RULE")."""

    def __init__(self, address: str, rule: str):
        super().__init__(f"scheduler = {address}: {rule}")
        self.address, self.rule = address, rule


def _timed(version: str, chunk_function: Callable[[Any], list], payload: Any) -> tuple[list, float]:
    """Runs one chunk where it is sent (a worker, a process) and measures its compute time; refuses to run with
    another version of mdr than the caller's (the rows would not be the local rows)."""
    if _mdr.__version__ != version:
        raise RuntimeError(f"this worker has mdr {_mdr.__version__} ({_mdr.__file__}), the caller {version}: "
                           f"install the same package on every worker")
    start = time.perf_counter()
    outputs = chunk_function(payload)
    return outputs, time.perf_counter() - start


class _LocalPool:
    """The chunks in min(jobs, cores, items) local processes (ProcessPoolExecutor; Ctrl-C is the parent's alone)."""

    def __init__(self, jobs: int | None, items: int):
        self.workers = self.threads = local_workers(jobs, items)
        self.scheduler = "local"
        self._pool = concurrent.futures.ProcessPoolExecutor(self.threads, initializer=_ignore_interrupts)

    def submit(self, function, *args):
        return self._pool.submit(function, *args)

    def results(self, futures):
        return [future.result() for future in futures]

    def retried(self, futures) -> int:
        return 0  # a process that dies breaks the pool (BrokenProcessPool): there is nothing to retry

    def close(self, interrupted: bool, in_flight: list):
        if interrupted:
            # Running chunks are not waited for: their processes are ended (CPython keeps them in _processes).
            processes = list(getattr(self._pool, "_processes", {}).values())
            self._pool.shutdown(wait=False, cancel_futures=True)
            for process in processes:
                process.terminate()
        else:
            self._pool.shutdown(wait=True)


def _ignore_interrupts() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)


class _DaskPool:
    """The chunks on the workers of a Dask scheduler; a Client given by the caller is not closed."""

    def __init__(self, scheduler: Any):
        import distributed  # python3-distributed; only needed here

        self._distributed = distributed
        if isinstance(scheduler, distributed.Client):
            self._client, self._own = scheduler, False
        elif isinstance(scheduler, str):
            try:
                self._client = distributed.Client(scheduler, set_as_default=False)
            except (OSError, ValueError, TypeError) as error:  # refused, timed out, or not an address
                raise SchedulerError(scheduler, f"no Dask scheduler answered ({error})") from None
            self._own = True
        else:
            raise TypeError(f"scheduler: expected 'tcp://HOST:PORT' or a distributed.Client, got "
                            f"{type(scheduler).__name__}")
        self.scheduler = self._client.scheduler.address
        try:
            self._client.wait_for_workers(1, timeout=WORKER_TIMEOUT)
        except (TimeoutError, OSError):
            self.close(False, [])
            raise SchedulerError(self.scheduler, f"no worker joined within {WORKER_TIMEOUT:g} s") from None
        workers = self._client.scheduler_info()["workers"]
        self.workers = len(workers)
        self.threads = sum(worker["nthreads"] for worker in workers.values())
        self._prefix = f"mdr-{uuid.uuid4().hex[:12]}"
        self._count = 0

    def submit(self, function, *args):
        self._count += 1
        return self._client.submit(function, *args, key=f"{self._prefix}-{self._count}", pure=False)

    def results(self, futures):
        try:
            return self._client.gather(futures)
        except self._distributed.KilledWorker as error:
            raise RuntimeError(f"scheduler = {self.scheduler}: a chunk was lost with more workers than Dask's "
                               f"allowed-failures permits ({error})") from None
        except Exception as error:  # the chunk itself failed on the worker (per-item failures never get here)
            raise RuntimeError(f"scheduler = {self.scheduler}: a chunk failed on a worker: {type(error).__name__}: "
                               f"{error} (each worker needs the mdr package and the module of the per-item "
                               f"function; docs/distributed.md)") from error

    def retried(self, futures) -> int:
        keys = [future.key for future in futures]
        # A lambda travels by value: the scheduler needs dask only, not mdr.
        counts = self._client.run_on_scheduler(
            lambda dask_scheduler, keys: [getattr(dask_scheduler.tasks.get(k), "suspicious", 0) for k in keys],
            keys=keys)
        return int(sum(counts))

    def close(self, interrupted: bool, in_flight: list):
        if interrupted and in_flight:
            self._client.cancel(in_flight)
        if self._own:
            self._client.close()


def _chunk_size(seconds_per_item: float | None, bytes_per_item: float, remaining: int, threads: int,
                target_seconds: float) -> int:
    if seconds_per_item is None:
        return 1  # the first chunks measure the cost of an item
    full = math.ceil(target_seconds / max(seconds_per_item, 1e-9))
    balanced = math.ceil(remaining / (2 * threads))  # the tail: every thread gets a last chunk or two
    largest = min(MAX_CHUNK, max(1, int(MAX_CHUNK_BYTES / max(bytes_per_item, 1.0))))
    return max(1, min(full, largest, max(balanced, math.ceil(full / 4))))


def _nbytes(payload: Any) -> int:
    """The bytes of the arrays in a chunk's data (numpy arrays, in lists or dicts); 0 for anything else."""
    if hasattr(payload, "nbytes"):
        return int(payload.nbytes)
    if isinstance(payload, dict):
        return sum(_nbytes(value) for value in payload.values())
    if isinstance(payload, (list, tuple)):
        return sum(_nbytes(value) for value in payload)
    return 0


def _wait_some(completed: queue.SimpleQueue, timeout: float) -> list:
    """The futures finished within `timeout` seconds (waits for the first, then takes all that are there)."""
    try:
        ready = [completed.get(timeout=timeout)]
    except queue.Empty:
        return []
    while not completed.empty():
        ready.append(completed.get())
    return ready


def ordered_map(chunk_function: Callable[[Any], list], read_chunk: Callable[[int, int], Any], total: int, *,
                scheduler: Any = None, jobs: int | None = None, target_seconds: float = TARGET_SECONDS,
                progress: Callable[[int, int], None] | None = None) -> MapOutcome:
    """Runs `chunk_function(read_chunk(start, stop))` over chunks of the items 0..total-1 and returns the outputs in
    item order, whatever ran where.

    Chunks carry about `target_seconds` of work each, as measured on the first ones; at most two a worker thread
    are in flight. KeyboardInterrupt cancels every chunk and closes what was opened.

    Parameters
    ----------
    chunk_function : callable
        ``chunk_function(chunk)`` returns one output per item of the chunk, in order. It must be picklable by
        reference (a function of an installed module, e.g. with functools.partial) or be defined in ``__main__``.
    read_chunk : callable
        ``read_chunk(start, stop)`` gives the data of the items start..stop-1. It runs here, so data read from
        local files or arrays travels with the tasks (workers need no shared file system).
    total : int
        The number of items.
    scheduler : str or distributed.Client, optional
        A Dask scheduler address ``"tcp://HOST:PORT"`` or a client; None (the default): local processes.
    jobs : int, optional
        Local processes (default: all cores); min(jobs, cores, total) start (``MapOutcome.workers``), and more
        than the cores warns (RuntimeWarning); only without a scheduler.
    target_seconds : float, optional
        The compute time a chunk should carry (default `TARGET_SECONDS`, 0.1 s).
    progress : callable, optional
        Called as ``progress(done, total)`` at least every 0.2 s.

    Returns
    -------
    MapOutcome
        ``outputs[i]`` the output for item i, and how the map ran: scheduler, workers, threads, tasks, retried,
        seconds, compute_seconds.

    Raises
    ------
    ValueError
        For `jobs` not an integer >= 1 (a bool included), or given with a scheduler.
    SchedulerError
        When no scheduler answers at the address, or no worker joins within `WORKER_TIMEOUT`.
    RuntimeError
        When a chunk fails as a whole on a worker (a missing module, another mdr version) or is lost with more
        workers than Dask allows.

    Examples
    --------
    The chunk function ``np.sqrt`` (picklable) over chunks of squares read here:

    >>> outcome = mdr.distributed.ordered_map(np.sqrt, lambda start, stop: np.arange(start, stop) ** 2.0, 6, jobs=1)
    >>> [float(x) for x in outcome.outputs], outcome.scheduler
    ([0.0, 1.0, 2.0, 3.0, 4.0, 5.0], 'local')
    >>> outcome = mdr.distributed.ordered_map(np.sqrt, read_chunk, 10**6,
    ...                                       scheduler="tcp://127.0.0.1:8786")      # doctest: +SKIP
    """
    check_jobs(jobs, scheduler)
    start_time = time.perf_counter()
    pool = _LocalPool(jobs, total) if scheduler is None else _DaskPool(scheduler)
    outputs: list = [None] * total
    placed = [False] * total
    in_flight: dict[Any, tuple[int, int]] = {}
    finished: list = []
    completed: queue.SimpleQueue = queue.SimpleQueue()  # futures, as they finish (their callbacks put them)
    tasks = retried = done = next_start = 0
    compute_seconds = 0.0
    sent_bytes = 0
    next_release = start_time + 1.0
    interrupted = True
    try:
        while done < total:
            seconds_per_item = compute_seconds / done if done else None
            while next_start < total and len(in_flight) < (2 * pool.threads if done else pool.threads):
                size = _chunk_size(seconds_per_item, sent_bytes / max(next_start, 1), total - next_start,
                                   pool.threads, target_seconds)
                stop = min(total, next_start + size)
                payload = read_chunk(next_start, stop)
                sent_bytes += _nbytes(payload)
                future = pool.submit(_timed, _mdr.__version__, chunk_function, payload)
                in_flight[future] = (next_start, stop)
                future.add_done_callback(completed.put)
                tasks += 1
                next_start = stop
            ready = _wait_some(completed, timeout=0.2)
            for future, (outputs_chunk, seconds) in zip(ready, pool.results(ready)):
                first, stop = in_flight.pop(future)
                if len(outputs_chunk) != stop - first:
                    raise RuntimeError(f"a chunk of {stop - first} items returned {len(outputs_chunk)} outputs")
                for index, output in zip(range(first, stop), outputs_chunk):
                    if placed[index]:
                        raise RuntimeError(f"item {index} came back twice")
                    outputs[index], placed[index] = output, True
                done += stop - first
                compute_seconds += seconds
            finished.extend(ready)
            if finished and (done == total or time.perf_counter() > next_release):
                # Once a second: their retries counted, the finished tasks are released on the scheduler (a worker
                # that dies later would otherwise make it compute them again).
                retried += pool.retried(finished)
                finished.clear()
                next_release = time.perf_counter() + 1.0
            if progress:
                progress(done, total)
        interrupted = False
    finally:
        pool.close(interrupted, list(in_flight))
    return MapOutcome(outputs=outputs, scheduler=pool.scheduler, workers=pool.workers, threads=pool.threads,
                      tasks=tasks, retried=retried, seconds=time.perf_counter() - start_time,
                      compute_seconds=compute_seconds)


def map_items(function: Callable[[Any], Any], items: Sequence[Any], **options: Any) -> tuple[list, list[str],
                                                                                              MapOutcome]:
    """`function(item)` for every item, in order; a failed item does not stop the others.

    Parameters
    ----------
    function : callable
        ``function(item)`` for one item; picklable as for `ordered_map`.
    items : sequence
        The items; slices of it travel with the tasks.
    **options
        Those of `ordered_map`: ``scheduler``, ``jobs``, ``target_seconds``, ``progress``.

    Returns
    -------
    results : list
        ``function(item)`` per item; None where the item failed.
    errors : list of str
        The reason ("ExceptionType: message") where the item failed, else "".
    outcome : MapOutcome
        How the map ran (its ``outputs`` are the pairs (result, error)).

    Examples
    --------
    >>> results, errors, outcome = mdr.distributed.map_items(math.sqrt, [4.0, -1.0, 9.0], jobs=1)
    >>> results, errors
    ([2.0, None, 3.0], ['', 'ValueError: math domain error', ''])
    """
    outcome = ordered_map(functools.partial(_each_item, function), lambda start, stop: list(items[start:stop]),
                          len(items), **options)
    results = [result for result, _ in outcome.outputs]
    errors = [error for _, error in outcome.outputs]
    return results, errors, outcome


def _each_item(function: Callable[[Any], Any], items: list) -> list[tuple[Any, str]]:
    outputs = []
    for item in items:
        try:
            outputs.append((function(item), ""))
        except Exception as error:  # the item's reason is kept; the map goes on
            outputs.append((None, f"{type(error).__name__}: {error}"))
    return outputs


def sweep_chunk(case: str | dict[str, Any] | _mdr.ContactCase, source: str, keys: list[str],
                points: Any) -> list[tuple[dict[str, Any], str]]:
    r"""The rows (summary, error) of a sweep at the given points, on one thread (the chunk task of a sweep).

    Parameters
    ----------
    case : str or dict or mdr.ContactCase
        The case as TOML text (a file's), as its plain tree of dicts, lists and numbers, or as objects (an
        ``mdr.ContactCase``, pickled with its typed parts: each point set on its objects, as `mdr.sweep` does).
    source : str
        The case's name in messages (its file name; not used with an ``mdr.ContactCase``).
    keys : list of str
        The varied dotted keys, e.g. ``"material.G"`` or ``"load.history[1][1]"``.
    points : array-like
        One row a point, one column a key.

    Returns
    -------
    list of (dict, str)
        Per point its summary (the keys of summary.json; {} where the point failed) and its error ("" where it
        ran).

    Raises
    ------
    mdr.InvalidInput
        For a bad case, a key that is not a number of the case, or points with another number of columns.

    Examples
    --------
    >>> text = ('[material]\nmodel = "elastic"\nG = 1.0e6\n[indenter]\nshape = "sphere"\nR = 0.01\n'
    ...         '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [1.0, 1.0e-4]]\n')
    >>> rows = mdr.distributed.sweep_chunk(text, "case.toml", ["material.G"], [[1.0e6], [4.0e6]])
    >>> [round(summary["max_force"] / rows[0][0]["max_force"], 6) for summary, _ in rows], [e for _, e in rows]
    ([1.0, 4.0], ['', ''])
    """
    summaries, errors = _points_rows(case, source, keys, points)
    return list(zip(summaries, errors))


def _points_rows(case: str | dict[str, Any] | _mdr.ContactCase, source: str, keys: list[str],
                 points: Any) -> tuple[list, list]:
    """(summaries, errors) of the case at the points on one thread: of its objects for an mdr.ContactCase."""
    if isinstance(case, _mdr.ContactCase):
        return _mdr._sweep_contact_case_points(case, keys, points, 1)
    return _mdr._sweep_points(case, source, keys, points, 1)


def sweep_rows(case: str | dict[str, Any] | _mdr.ContactCase, source: str, specs: list[str], scheduler: Any,
               progress: Callable[[int, int], None] | None = None) -> tuple[list[str], Any, MapOutcome]:
    r"""The rows of a sweep run in chunks through a Dask scheduler (`mdr.sweep` with ``scheduler=``), the same rows
    as the local sweep's, bit for bit.

    Parameters
    ----------
    case : str or dict or mdr.ContactCase
        The case as TOML text (a file's), as its plain tree of dicts, lists and numbers, or as objects (an
        ``mdr.ContactCase``, which pickles with its typed parts; the rows of its local sweep, bit for bit).
    source : str
        The case's name in messages (its file name; not used with an ``mdr.ContactCase``).
    specs : list of str or (str, list of float)
        One axis each, ``"KEY=V1,V2,..."``, ``"KEY=START:STOP:COUNT[:log]"`` or ``(KEY, [V1, V2, ...])`` (the last
        varies fastest).
    scheduler : str or distributed.Client or None
        A Dask scheduler address ``"tcp://HOST:PORT"`` or a client; None runs the chunks in local processes.
    progress : callable, optional
        Called as ``progress(done, total)`` at least every 0.2 s.

    Returns
    -------
    keys : list of str
        The varied keys.
    points : numpy.ndarray
        The grid, one row a point.
    outcome : MapOutcome
        ``outputs[i]`` = (summary, error) of point i ({} as the summary of a point that failed), and how it ran.

    Raises
    ------
    mdr.InvalidInput
        For a bad case or axis, checked here before any chunk is sent.
    SchedulerError
        When the scheduler cannot be used.

    Examples
    --------
    >>> text = ('[material]\nmodel = "elastic"\nG = 1.0e6\n[indenter]\nshape = "sphere"\nR = 0.01\n'
    ...         '[load]\ncontrol = "displacement"\nhistory = [[0.0, 0.0], [1.0, 1.0e-4]]\n')
    >>> keys, points, outcome = mdr.distributed.sweep_rows(text, "case.toml", ["material.G=1e6,4e6"], None)
    >>> keys, points.tolist(), [round(summary["max_force"], 4) for summary, _ in outcome.outputs]   # Hertz
    (['material.G'], [[1000000.0], [4000000.0]], [0.5333, 2.1333])

    The same rows on the workers of a Dask scheduler:

    >>> rows = mdr.distributed.sweep_rows(text, "case.toml", ["material.G=1e6,4e6"],
    ...                                   "tcp://127.0.0.1:8786")      # doctest: +SKIP
    """
    keys, points = _mdr._sweep_grid(specs)
    _points_rows(case, source, keys, points[:0])  # validates the case and the keys here, first
    outcome = ordered_map(functools.partial(sweep_chunk, case, source, keys),
                          lambda start, stop: points[start:stop], len(points), scheduler=scheduler, progress=progress)
    return keys, points, outcome
