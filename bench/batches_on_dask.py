"""Throughput of batches locally and through a real Dask cluster on this machine (docs/performance.md, issue 14).

    PYTHONPATH=build/python /usr/bin/python3 bench/batches_on_dask.py [--points N] [--map NY]

Starts a scheduler and two one-thread workers on 127.0.0.1 (tests/python/distributed/cluster.py), then times
1. a restitution sweep of N points (examples/restitution_map.toml at elements = 100, time_step = 5e-5: about 1 ms a
   run) with mdr.sweep on 2 threads and through the scheduler;
2. a map of NY x NY synthetic 500-point curves with the closed-form Hertz fit of the tests (tens of microseconds a
   curve: the worst case for scheduling) locally on 2 processes and through the scheduler;
3. the same map with a per-curve function that runs the standard-solid load-hold case the curves come from once
   (one model evaluation of a fit, ~1 ms);
4. mdr.fit_map of an F x F map (--fit-map F, default 16) of standard-solid load-hold curves of 500 points (G_inf,
   G1 and tau1 free) locally on 2 processes and through the scheduler.
Prints wall times, rates, tasks, the share of the scheduling overhead (tasks x 2.5 ms over the chunks' compute) and
checks that the results are the local ones bit for bit.
"""

from __future__ import annotations

import argparse
import os
import pathlib
import sys
import time
import tomllib

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "python" / "distributed"))

import mdr  # noqa: E402
from cluster import local_cluster  # noqa: E402
from hertz_curves import fit_hertz, hertz_force  # noqa: E402

LOAD_HOLD = {
    "material": {"model": "standard", "G_inf": 1.0e5, "G1": 2.0e5, "tau1": 0.05},
    "indenter": {"shape": "sphere", "R": 1.0e-5},
    "load": {"control": "displacement", "history": [[0.0, 0.0], [0.1, 1.0e-6], [0.5, 1.0e-6]]},
    "numerics": {"elements": 100},
}


def model_force(curve: np.ndarray) -> dict[str, float]:
    """One forward run of the load-hold case (as one evaluation of a fit would), compared with the curve."""
    result = mdr.run(LOAD_HOLD)
    force = np.interp(np.linspace(0.0, 0.5, len(curve)), result.history["t"], result.history["F"])
    return {"rms": float(np.sqrt(np.mean((force - curve[:, 1]) ** 2)))}


def g_inf_truth(n: int) -> np.ndarray:
    return LOAD_HOLD["material"]["G_inf"] * (1.0 + np.add.outer(np.arange(n), np.arange(n)) / (2.0 * n))


def load_hold_map(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """n x n force curves of the load-hold case at 500 times, G_inf varying over the map, 0.1 % noise."""
    t = np.linspace(0.0, 0.5, 500)
    d = np.interp(t, *np.array(LOAD_HOLD["load"]["history"]).T)
    forces = np.empty((n, n, 500))
    rng = np.random.default_rng(2)
    for (row, col), g_inf in np.ndenumerate(g_inf_truth(n)):
        result = mdr.run({**LOAD_HOLD, "material": {**LOAD_HOLD["material"], "G_inf": g_inf}})
        force = np.interp(t, result.history["t"], result.history["F"])
        forces[row, col] = force * (1.0 + 1e-3 * rng.standard_normal(500))
    return forces, t, d


def same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    return a.dtype.kind != "f" and np.array_equal(a, b) or np.array_equal(a.view(np.int64), b.view(np.int64))


def report(label: str, items: int, seconds: float, batch=None) -> None:
    line = f"{label:<44} {seconds:7.2f} s  {items / seconds:9.0f} items/s"
    if batch is not None and batch.tasks:
        line += (f"  {batch.tasks} tasks, {batch.compute_seconds / batch.tasks * 1e3:.0f} ms each, overhead "
                 f"{batch.tasks * 2.5e-3 / batch.compute_seconds:.1%}, retried {batch.retried}")
    print(line, flush=True)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--points", type=int, default=100_000)
    parser.add_argument("--map", type=int, default=64)
    parser.add_argument("--fit-map", type=int, default=16)
    args = parser.parse_args()
    with open(ROOT / "examples" / "restitution_map.toml", "rb") as handle:
        case = tomllib.load(handle)
    case["numerics"] = {"elements": 100, "time_step": 5.0e-5}
    g1 = 4
    vary = {"material.tau1": f"1e-5:1e-1:{args.points // g1}:log", "material.G1": "1e6,3e6,1e7,3e7"}
    n = args.map
    depth = np.linspace(0.0, 1.0e-6, 500)
    curves = np.empty((n, n, 500, 2))
    curves[..., 0] = depth
    rng = np.random.default_rng(1)
    G = 1.0e5 * (1.0 + rng.random((n, n)))
    curves[..., 1] = hertz_force(1.0, depth) * G[..., None] * (1.0 + 1e-2 * rng.standard_normal((n, n, 500)))
    print(f"{os.cpu_count()} cores; sweep of {args.points} points, map of {n}x{n} curves of 500 points", flush=True)

    with local_cluster(workers=2) as cluster:
        mdr.sweep(case, {"material.tau1": [1e-3, 2e-3]}, scheduler=cluster.address)  # the workers import mdr
        # Each workload locally, then through Dask, back to back (the machine is shared: compare within a pair).
        start = time.perf_counter()
        local = mdr.sweep(case, vary, jobs=2)
        report("sweep, local (2 threads)", args.points, time.perf_counter() - start)
        start = time.perf_counter()
        remote = mdr.sweep(case, vary, scheduler=cluster.address)
        report("sweep, Dask (2 workers x 1 thread)", args.points, time.perf_counter() - start, remote.batch)
        start = time.perf_counter()
        hertz_local = mdr.map_curves(fit_hertz, curves, jobs=2)
        report("map, Hertz fit, local (2 processes)", n * n, time.perf_counter() - start, hertz_local.batch)
        start = time.perf_counter()
        hertz_remote = mdr.map_curves(fit_hertz, curves, scheduler=cluster.address)
        report("map, Hertz fit, Dask", n * n, time.perf_counter() - start, hertz_remote.batch)
        start = time.perf_counter()
        model_local = mdr.map_curves(model_force, curves, jobs=2)
        report("map, one run a curve, local (2 processes)", n * n, time.perf_counter() - start, model_local.batch)
        start = time.perf_counter()
        model_remote = mdr.map_curves(model_force, curves, scheduler=cluster.address)
        report("map, one run a curve, Dask", n * n, time.perf_counter() - start, model_remote.batch)
        forces, t, d = load_hold_map(args.fit_map)
        fit_case = {**LOAD_HOLD, "fit": {"free": ["material.G_inf", "material.G1", "material.tau1"],
                                         "contact_point": "fixed", "baseline": "fixed"}}
        start = time.perf_counter()
        fits_local = mdr.fit_map(fit_case, forces, time=t, depth=d, jobs=2)
        report(f"fit_map {args.fit_map}x{args.fit_map}, local (2 processes)", forces.shape[0] * forces.shape[1],
               time.perf_counter() - start, fits_local.batch)
        start = time.perf_counter()
        fits_remote = mdr.fit_map(fit_case, forces, time=t, depth=d, scheduler=cluster.address)
        report(f"fit_map {args.fit_map}x{args.fit_map}, Dask", forces.shape[0] * forces.shape[1],
               time.perf_counter() - start, fits_remote.batch)
        print(f"fit_map: {np.count_nonzero(fits_local.status == 0)} of {fits_local.status.size} converged; G_inf "
              f"within {np.nanmax(np.abs(fits_local.values['material.G_inf'] / g_inf_truth(args.fit_map) - 1)):.1e}")

    assert all(same_bits(local[k], remote[k]) for k in local if k != "wall_seconds"), "sweep differs"
    assert same_bits(hertz_local.values["G"], hertz_remote.values["G"]), "Hertz map differs"
    assert same_bits(model_local.values["rms"], model_remote.values["rms"]), "model map differs"
    assert all(same_bits(fits_local.values[k], fits_remote.values[k]) for k in fits_local.values), "fits differ"
    print("results identical bit for bit (wall_seconds aside)")


if __name__ == "__main__":
    main()
