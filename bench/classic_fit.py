#!/usr/bin/python3
"""The fits of bench/bench_fit.cpp side by side with the classic fit, timed in one process: the synthetic
2000-point load-hold-unload curve (sphere R = 10 um; standard solid G_inf = 1 kPa, G1 = 2 kPa, tau1 = 0.2 s, or the
3-term Prony series; noise 1 nN, baseline 5 nN) fitted by mdr.fit (all rows, contact point and baseline fitted),
and by scipy least_squares with Hertz / Lee-Radok (the loading and hold rows, where Lee-Radok is exact, with the
true contact point and baseline: the classic fit's best case). Prints CPU seconds per fit and writes the figure.
Usage: PYTHONPATH=build/python bench/classic_fit.py [FIGURE.png]
"""
from __future__ import annotations

import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.optimize import least_squares  # noqa: E402
from scipy.signal import lfilter  # noqa: E402

import mdr  # noqa: E402

R, NOISE, BASELINE, POINTS = 10e-6, 1e-9, 5e-9, 2000
STANDARD = {"model": "standard", "G_inf": 1e3, "G1": 2e3, "tau1": 0.2}
PRONY = {"model": "prony", "G_inf": 1e3, "terms": [[2e3, 0.02], [1.5e3, 0.2], [1e3, 1.0]]}


def depth_at(t):
    return np.select([t < 0.2, t < 0.7, t < 1.7], [-0.4e-6 + 2e-6 * t, 4e-6 * (t - 0.2), 2e-6 + 0 * t],
                     2e-6 - 4e-6 * (t - 1.7))


def synthetic(material):
    t = np.linspace(0.0, 2.2, POINTS)
    d = depth_at(t)
    history = [[-1e-3, 0.0]] + [[float(a), float(max(b, 0.0))] for a, b in zip(t, d)]
    result = mdr.run({"material": material, "indenter": {"shape": "sphere", "R": R},
                      "load": {"control": "displacement", "history": history},
                      "numerics": {"elements": 2000, "time_step": 2.2 / (POINTS - 1)}})
    rows = np.searchsorted(result.history["t"], t, side="right") - 1
    force = result.history["F"][rows] + BASELINE + np.random.default_rng(7).normal(0.0, NOISE, POINTS)
    return t, d, force


def mdr_fit(material, start, free, curve):
    t, d, f = curve
    case = {"material": start, "indenter": {"shape": "sphere", "R": R}, "fit": {"free": free, "baseline": "fit"}}
    begin = time.process_time()
    result = mdr.fit(case, data=[{"time": t, "depth": d, "force": f}])
    return (time.process_time() - begin, result.summary["residual_to_noise"], result.summary["evaluations"],
            result.status)


def lee_radok(t, d, g_inf, terms):
    """Hertz / Lee-Radok: F = (16/3) sqrt(R) int G(t - s) d/ds d^(3/2) ds, exact for d^(3/2) linear per step."""
    h = np.maximum(d, 0.0) ** 1.5
    dt = t[1] - t[0]
    force = g_inf * h
    for g, tau in terms:
        decay = np.exp(-dt / tau)
        force = force + g * lfilter([1.0], [1.0, -decay], np.diff(h, prepend=0.0) * tau / dt * (1.0 - decay))
    return 16.0 / 3.0 * np.sqrt(R) * force


def classic_fit(start, curve):
    t, d, f = curve
    rows = t < 1.7  # loading and hold: the contact area never shrinks
    t, d, f = t[rows], d[rows], f[rows] - BASELINE

    def residuals(u):
        v = np.exp(u)
        return (lee_radok(t, d, v[0], list(zip(v[1::2], v[2::2]))) - f) / NOISE

    begin = time.process_time()
    solution = least_squares(residuals, np.log(start), method="trf")
    seconds = time.process_time() - begin
    return (seconds, np.sqrt(np.mean(solution.fun ** 2)), solution.nfev + solution.njev * len(start),
            "converged" if solution.success else solution.message)


def main():
    rows = []
    curve = synthetic(STANDARD)
    start = {"model": "standard", "G_inf": 2e3, "G1": 1e3, "tau1": 0.5}
    rows.append(("mdr.fit, standard solid", *mdr_fit(STANDARD, start, ["material.G_inf", "material.G1",
                                                                       "material.tau1"], curve)))
    rows.append(("scipy Lee-Radok, standard solid", *classic_fit([2e3, 1e3, 0.5], curve)))
    curve = synthetic(PRONY)
    start = {"model": "prony", "G_inf": 2e3, "terms": [[1e3, 0.05], [3e3, 0.5], [2e3, 3.0]]}
    free = ["material.G_inf"] + [f"material.terms[{i}][{j}]" for i in range(3) for j in range(2)]
    rows.append(("mdr.fit, 3-term Prony", *mdr_fit(PRONY, start, free, curve)))
    rows.append(("scipy Lee-Radok, 3-term Prony", *classic_fit([2e3, 1e3, 0.05, 3e3, 0.5, 2e3, 3.0], curve)))
    print("| fit | CPU per fit [ms] | residual/noise | model evaluations | status |")
    print("|---|---|---|---|---|")
    for name, seconds, ratio, runs, status in rows:
        print(f"| {name} | {seconds * 1e3:.1f} | {ratio:.3f} | {runs} | {status} |")
    if len(sys.argv) > 1:
        figure, axes = plt.subplots(figsize=(7.0, 3.2))
        axes.barh([r[0] for r in rows][::-1], [r[1] * 1e3 for r in rows][::-1],
                  color=["C0", "C3", "C0", "C3"][::-1])
        axes.set_xscale("log")
        axes.set_xlabel("CPU time per fit [ms] (2000-point load-hold-unload curve)")
        for goal in (50.0, 200.0):
            axes.axvline(goal, color="k", lw=0.6, ls=":")
        figure.tight_layout()
        figure.savefig(sys.argv[1], dpi=110)
        print(f"wrote {sys.argv[1]}")


if __name__ == "__main__":
    main()
