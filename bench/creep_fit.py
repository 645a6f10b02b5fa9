#!/usr/bin/python3
"""A force-driven creep fit of a 6 000-point record (issue 25's target: <= 1 s), timed. The record is synthetic: a
sphere (R = 5 um) pressed into a standard solid (G_inf = 1 kPa, G1 = 2 kPa, tau1 = 2 s) by a force ramped to 5 nN
in 0.5 s and held to 30 s; the depth from the closed form of Lee and Radok for a creep compliance,
d(t)^1.5 = 3 / (16 sqrt(R)) int_0^t J(t - s) dF(s) (Hertz with E* = 4G, incompressible; Lee & Radok 1960),
J(t) = 1/G_inf - G1 / (G_inf G_0) exp(-t / tau_c), G_0 = G_inf + G1, tau_c = tau1 G_0 / G_inf, plus Gaussian noise
of 1e-4 of the peak depth. `mdr fit` with fitted = "depth", the contact point and baseline fixed (the data's zero),
G_inf, G1, tau1 free from 2x off. Prints mdr's wall time (fit.json), the CPU time of the whole `mdr fit` process
(start, reading and writing included), iterations, runs and the fitted values.

Beside it, in the same run, the classic fit of the same rows (issue 25: the ratio to it): scipy least_squares of the
same three parameters, from the same start, with Lee and Radok's creep solution for the sphere on the measured
force, d(t) = [3 / (16 sqrt(R)) int_0^t J(t - s) dF(s)]^(2/3) (Lee & Radok, J. Appl. Mech. 27, 438 (1960), the
sphere under a load history, with 1 - nu = 1/2; Ting, J. Appl. Mech. 33, 845 (1966): exact while the contact does
not shrink, which holds under a force that does not fall), J the standard solid's shear creep compliance above, the
convolution exact for F linear between rows: int J dF = F(t) / G_inf - (G1 / (G_inf G_0)) y,
y_n = E y_(n-1) + B (F_n - F_(n-1)), E = exp(-dt / tau_c), B = (tau_c / dt)(1 - E). Its CPU time in this process.
Usage: bench/creep_fit.py [path/to/mdr [repeats]]   (run it on one core: taskset -c 0)
"""
from __future__ import annotations

import json
import math
import os
import pathlib
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.optimize import least_squares
from scipy.signal import lfilter

ROOT = pathlib.Path(__file__).resolve().parent.parent
MDR = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build" / "bin" / "mdr"
REPEATS = int(sys.argv[2]) if len(sys.argv) > 2 else 1
RADIUS, G_INF, G1, TAU = 5e-6, 1e3, 2e3, 2.0
PEAK_FORCE, RAMP, END, ROWS = 5e-9, 0.5, 30.0, 6000


def creep_depth(t: np.ndarray) -> np.ndarray:
    g0 = G_INF + G1
    tau_c = TAU * g0 / G_INF
    a = G1 / (G_INF * g0)
    rate = PEAK_FORCE / RAMP
    ramp = rate * (t / G_INF - a * tau_c * (1.0 - np.exp(-t / tau_c)))
    held = rate * (RAMP / G_INF - a * tau_c * (np.exp(-(t - RAMP) / tau_c) - np.exp(-t / tau_c)))
    integral = np.where(t <= RAMP, ramp, held)
    return (3.0 / (16.0 * math.sqrt(RADIUS)) * integral) ** (2.0 / 3.0)


def classic_fit(t: np.ndarray, depth: np.ndarray, force: np.ndarray) -> tuple[float, int, np.ndarray, float]:
    """CPU seconds, model evaluations, fitted (G_inf, G1, tau1) and residual RMS / noise of the classic fit."""
    dt = t[1] - t[0]
    noise = np.std(np.diff(depth[len(depth) // 2:])) / math.sqrt(2.0)
    change = np.diff(force, prepend=0.0)
    evaluations = 0

    def predict(p: np.ndarray) -> np.ndarray:
        nonlocal evaluations
        evaluations += 1
        g_inf, g1, tau = p
        g0 = g_inf + g1
        tau_c = tau * g0 / g_inf
        decay = math.exp(-dt / tau_c)
        gain = -math.expm1(-dt / tau_c) * tau_c / dt
        memory = lfilter([gain], [1.0, -decay], change)
        integral = force / g_inf - g1 / (g_inf * g0) * memory
        return (3.0 / (16.0 * math.sqrt(RADIUS)) * np.maximum(integral, 0.0)) ** (2.0 / 3.0)

    start = [2 * G_INF, G1 / 2, TAU * 2]
    begin = time.process_time()
    bounds = ([0.0, 0.0, 1e-3], [np.inf, np.inf, 300.0])
    fit = least_squares(lambda p: (predict(p) - depth) / noise, start, bounds=bounds, x_scale="jac")
    return time.process_time() - begin, evaluations, fit.x, float(np.sqrt(np.mean(fit.fun ** 2)))


def main() -> None:
    t = np.linspace(0.0, END, ROWS)
    force = PEAK_FORCE * np.minimum(t / RAMP, 1.0)
    depth = creep_depth(t)
    depth = depth + np.random.default_rng(3).normal(0.0, 1e-4 * depth.max(), t.size)
    with tempfile.TemporaryDirectory() as folder_name:
        folder = pathlib.Path(folder_name)
        np.savetxt(folder / "creep.csv", np.column_stack([t, depth, force]), delimiter=",",
                   header="t_s,indentation_m,force_N", comments="")
        (folder / "case.toml").write_text(
            f"[material]\nmodel = \"standard\"\nG_inf = {2 * G_INF}\nG1 = {G1 / 2}\ntau1 = {TAU * 2}\n\n"
            f"[indenter]\nshape = \"sphere\"\nR = {RADIUS}\n\n"
            "[fit]\nfree = [\"material.G_inf\", \"material.G1\", \"material.tau1\"]\n"
            "bounds = { \"material.tau1\" = [1e-3, 300.0] }\nfitted = \"depth\"\n"
            "contact_point = \"fixed\"\nbaseline = \"fixed\"\n\n"
            "[[fit.data]]\nfile = \"creep.csv\"\ntime = \"t_s\"\ndepth = \"indentation_m\"\nforce = \"force_N\"\n")
        print(f"load average {os.getloadavg()[0]:.2f}")
        for _ in range(REPEATS):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            subprocess.run([str(MDR), "fit", str(folder / "case.toml"), "-o", str(folder / "out")], check=True,
                           stdout=subprocess.DEVNULL)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            process_cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
            fit = json.loads((folder / "out" / "fit.json").read_text())
            seconds, evaluations, classic, classic_residual = classic_fit(t, depth, force)
            print(f"rows {ROWS}: mdr {fit['wall_seconds']:.3f} s ({process_cpu:.3f} s CPU, whole process), "
                  f"{fit['iterations']} iterations, "
                  f"{fit['evaluations']} runs ({fit['element_evaluations']} element, "
                  f"{fit.get('band_evaluations', 0)} band), {fit['status']}, residual/noise "
                  f"{fit['residual_to_noise']:.3f}; classic {seconds:.3f} s, {evaluations} runs, residual/noise "
                  f"{classic_residual:.3f}; ratio {fit['wall_seconds'] / seconds:.1f} "
                  f"(CPU {process_cpu / seconds:.1f})", flush=True)
    print(f"load average {os.getloadavg()[0]:.2f}")
    truth = {"material.G_inf": G_INF, "material.G1": G1, "material.tau1": TAU}
    for index, (key, value) in enumerate(fit["parameters"].items()):
        print(f"  {key} = {value:.6g} +- {fit['standard_errors'][key]:.2g} (true {truth[key]:.6g}; classic "
              f"{classic[index]:.6g})")


if __name__ == "__main__":
    main()
