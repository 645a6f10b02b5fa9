"""The one rule for the local workers of mdr.sweep, mdr.map_curves, mdr.fit_map and mdr.distributed: `jobs` is an
integer >= 1 (or None: every core), not given with a scheduler, and a run starts min(jobs, cores, items) workers;
asking for more than the cores warns once (a RuntimeWarning naming the bound)."""

from __future__ import annotations

import numbers
import os
import warnings
from typing import Any


def cores() -> int:
    """The cores this process may run on (its CPU affinity where the system has one)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return os.cpu_count() or 1


def check_jobs(jobs: Any, scheduler: Any = None) -> None:
    """Raises ValueError naming `jobs` unless it is None or an integer >= 1 (not a bool), and when it is given
    with a scheduler (whose workers' threads run the chunks)."""
    if jobs is None:
        return
    if isinstance(jobs, bool) or not isinstance(jobs, numbers.Integral) or jobs < 1:
        raise ValueError(f"jobs = {jobs!r}: must be an integer >= 1 (local workers) or None (every core)")
    if scheduler is not None:
        raise ValueError(f"jobs = {jobs!r}: not used with a scheduler (its workers' threads run the chunks)")


def local_workers(jobs: Any, items: int) -> int:
    """How many local workers run `items` items: min(jobs, cores, items), at least 1 (`jobs` None: the cores).
    Checks `jobs` (check_jobs) and warns when it asks for more workers than the cores."""
    check_jobs(jobs)
    available = cores()
    if jobs is not None and jobs > available:
        warnings.warn(f"jobs = {jobs}: more than the {available} cores; {min(available, max(items, 1))} workers run "
                      f"the {items} items", RuntimeWarning, stacklevel=3)
    return max(1, min(available if jobs is None else int(jobs), available, items))
