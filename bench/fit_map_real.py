#!/usr/bin/python3
"""A map of real curves (issue 25's target: a 64 x 64 map of 4 000-point curves, standard solid + contact point,
<= 5 min on 2 cores, through Dask within 15 % of local). The shared relaxation records
(examples/data/jpk_sr_cell1-000{1,2,3}.csv, segments 0-2: pause, extend, hold) resampled to 4 000 points on a
uniform time grid (linear interpolation of the measured depth and force), one record per pixel in turn, fitted as a
cone of 35 degrees with a standard solid, contact point and baseline fitted. A SIDE x SIDE subset (default 16: 256
pixels) is timed with `mdr.fit_map` on 2 local processes and then through a local Dask cluster of 2 one-thread
workers (tests/python/distributed/cluster.py); the time of 64 x 64 is extrapolated as 16x that of 256 pixels.
Usage: MDR_PYTHONPATH=build/python bench/fit_map_real.py [SIDE]
"""
from __future__ import annotations

import os
import pathlib
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path[:0] = [p for p in (os.environ.get("MDR_PYTHONPATH"), str(ROOT / "tests" / "python" / "distributed")) if p]
import mdr  # noqa: E402
from cluster import local_cluster, worker_env  # noqa: E402

SIDE = int(sys.argv[1]) if len(sys.argv) > 1 else 16
POINTS = 4000
CASE = {"material": {"model": "standard", "G_inf": 200.0, "G1": 300.0, "tau1": 1.0},
        "indenter": {"shape": "cone", "half_angle_deg": 35.0},
        "fit": {"free": ["material.G_inf", "material.G1", "material.tau1"],
                "bounds": {"material.tau1": [1e-3, 300.0]}, "baseline": "fit"}}


def resampled(path: pathlib.Path) -> np.ndarray:
    data = np.genfromtxt(path, delimiter=",", names=True)
    rows = np.isin(data["segment"], [0, 1, 2])
    t, depth, force = data["t_s"][rows], data["indentation_m"][rows], data["force_N"][rows]
    grid = np.linspace(t[0], t[-1], POINTS)
    return np.stack([grid, np.interp(grid, t, depth), np.interp(grid, t, force)], axis=-1)


def main() -> None:
    records = [resampled(ROOT / "examples" / "data" / f"jpk_sr_cell1-000{i}.csv") for i in (1, 2, 3)]
    stack = np.stack([records[i % 3] for i in range(SIDE * SIDE)]).reshape(SIDE, SIDE, POINTS, 3)
    print(f"{SIDE} x {SIDE} pixels of {POINTS} points; load average {os.getloadavg()[0]:.1f}", flush=True)
    start = time.perf_counter()
    local = mdr.fit_map(CASE, stack, jobs=2, figures=False)
    local_s = time.perf_counter() - start
    print(f"local, 2 processes: {local_s:.1f} s ({local_s / SIDE ** 2 * 1e3:.0f} ms a pixel; 64 x 64 extrapolated "
          f"{local_s * 4096 / SIDE ** 2 / 60:.1f} min); {local.summary()}",
          flush=True)
    with local_cluster(workers=2, env=worker_env()) as cluster:
        start = time.perf_counter()
        remote = mdr.fit_map(CASE, stack, scheduler=cluster.address, figures=False)
        remote_s = time.perf_counter() - start
    same = all(np.array_equal(local.values[key], remote.values[key], equal_nan=True) for key in CASE["fit"]["free"])
    print(f"Dask, 2 workers: {remote_s:.1f} s ({remote_s / local_s:.2f} x local; 64 x 64 extrapolated "
          f"{remote_s * 4096 / SIDE ** 2 / 60:.1f} min); values identical to local: {same}; load average "
          f"{os.getloadavg()[0]:.1f}", flush=True)


if __name__ == "__main__":
    main()
