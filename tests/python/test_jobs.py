"""The local workers of mdr.sweep, mdr.map_curves, mdr.fit_map and mdr.distributed (issue 23, item 2): one rule,
min(jobs, cores, items) workers, a RuntimeWarning past the cores, and a ValueError naming `jobs` for anything
but an integer >= 1 (before, jobs=10**6 forked thousands of processes for a 6-pixel map)."""

from __future__ import annotations

import math
import os

import numpy as np
import pytest

import mdr
from mdr import _jobs, distributed

CORES = _jobs.cores()
HERTZ_CASE = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
              "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
SWEEP_CASE = {"material": {"model": "elastic", "G": 1e6}, "indenter": {"shape": "sphere", "R": 1e-2},
              "load": {"control": "displacement", "history": [[0.0, 0.0], [1.0, 1e-4]]}}


def process_ids(chunk):
    """A chunk function: the id of the process that ran each item."""
    return [os.getpid()] * len(chunk)


def test_cores_are_this_process_cores():
    assert CORES == (len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count())


@pytest.mark.parametrize("items", [1, 3])
def test_workers_are_bounded_by_the_items_and_the_cores(items):
    with pytest.warns(RuntimeWarning, match=rf"^jobs = {CORES + 3}: more than the {CORES} cores"):
        outcome = distributed.ordered_map(process_ids, lambda start, stop: list(range(start, stop)), items,
                                          jobs=CORES + 3)
    assert outcome.workers == outcome.threads == min(CORES, items)
    assert len(set(outcome.outputs)) <= outcome.workers


def test_a_six_pixel_fit_map_with_a_million_jobs_runs_on_at_most_six_workers():
    t = np.linspace(0.0, 1.0, 51)
    d = 1e-5 * t
    G = np.array([[1e6, 2e6, 3e6], [4e6, 5e6, 6e6]])
    forces = 16.0 / 3.0 * G[..., None] * math.sqrt(1e-3) * d ** 1.5  # Hertz, eq. of docs/case-format.md
    with pytest.warns(RuntimeWarning, match=r"^jobs = 1000000: more than the"):
        fits = mdr.fit_map(HERTZ_CASE, forces, time=t, depth=d, jobs=10**6)
    assert fits.batch.workers == min(CORES, 6)
    np.testing.assert_allclose(fits.values["material.G"], G, rtol=1e-4)


def test_a_sweep_runs_on_at_most_its_points():
    with pytest.warns(RuntimeWarning, match=r"^jobs = 1000000: more than the"):
        table = mdr.sweep(SWEEP_CASE, {"material.G": [1e6, 2e6, 3e6]}, jobs=10**6)
    assert table.threads == min(CORES, 3)
    np.testing.assert_allclose(table["max_force"] / table["max_force"][0], [1.0, 2.0, 3.0], rtol=1e-12)
    assert mdr.sweep(SWEEP_CASE, {"material.G": [1e6]}, jobs=np.int64(1)).threads == 1


NONSENSE = [0, -1, 1.5, True, False, "2", np.float64(2.0), [2]]


@pytest.mark.parametrize("jobs", NONSENSE, ids=repr)
def test_nonsense_jobs_are_refused_naming_jobs_before_anything_runs(jobs, tmp_path):
    message = r"^jobs = .*: must be an integer >= 1"
    with pytest.raises(ValueError, match=message):
        mdr.sweep(SWEEP_CASE, {"material.G": [1e6, 2e6]}, jobs=jobs)
    with pytest.raises(ValueError, match=message):
        distributed.ordered_map(process_ids, lambda start, stop: list(range(start, stop)), 2, jobs=jobs)
    with pytest.raises(ValueError, match=message):
        mdr.map_curves(process_ids, np.zeros((1, 2, 5)), jobs=jobs, out=tmp_path / "map")
    with pytest.raises(ValueError, match=message):
        mdr.fit_map(HERTZ_CASE, np.zeros((1, 2, 5)), time=np.arange(5.0), depth=np.arange(5.0), jobs=jobs,
                    out=tmp_path / "fits")
    assert list(tmp_path.iterdir()) == []


def test_jobs_with_a_scheduler_are_refused_by_every_entry():
    for call in (lambda: mdr.map_curves(process_ids, np.zeros((1, 2, 5)), jobs=2, scheduler="tcp://127.0.0.1:1"),
                 lambda: distributed.ordered_map(process_ids, lambda a, b: [], 2, jobs=2, scheduler="tcp://x:1")):
        with pytest.raises(ValueError, match=r"^jobs = 2: not used with a scheduler"):
            call()
