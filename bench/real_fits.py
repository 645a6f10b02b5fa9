#!/usr/bin/python3
"""Fits of the shared real relaxation records (examples/data/jpk_sr_cell1-000{1,2,3}.csv: pause, extend, 30 s hold,
~10 000 rows) timed beside the classic fit of the same rows (issue 25). mdr: `mdr fit` of a cone (35 degrees) with a
standard solid, a 3-term Prony series or a power law G0 (t / 1 s)^-beta, contact point and baseline fitted; its
fit.json gives the wall time, the iterations and the model runs per forward model (band: the element runs that ran
as the band model). Classic: scipy least_squares with Lee-Radok for a cone,
F = (8 tan(theta) / pi) int G(t - s) d/ds [d(s)^2] ds (exact for d^2 linear per step; the power law's kernel
integrated over each step, G0 dt^-beta ((m + 1)^(1 - beta) - m^(1 - beta)) / (1 - beta) at lag m steps, by FFT
convolution), on the measured depth (`indentation_m`) with the contact point and the baseline fitted, CPU time in this
process.
Usage: bench/real_fits.py [path/to/mdr [results.json]]   (one core each, one fit at a time; results.json: every
fit.json by record and model, to compare fitted values between builds)
"""
from __future__ import annotations

import json
import math
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.optimize import least_squares
from scipy.signal import fftconvolve, lfilter

ROOT = pathlib.Path(__file__).resolve().parent.parent
MDR = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build" / "bin" / "mdr"
RECORDS = [ROOT / "examples" / "data" / f"jpk_sr_cell1-000{i}.csv" for i in (1, 2, 3)]
HALF_ANGLE = math.radians(35.0)
MODELS = {
    "standard": ('model = "standard"\nG_inf = 200.0\nG1 = 300.0\ntau1 = 1.0\n',
                 ["material.G_inf", "material.G1", "material.tau1"], {"material.tau1": [1e-3, 300.0]}),
    "prony3": ('model = "prony"\nG_inf = 200.0\nterms = [[300.0, 0.1], [300.0, 1.0], [300.0, 10.0]]\n',
               ["material.G_inf"] + [f"material.terms[{k}][{c}]" for k in range(3) for c in range(2)],
               {f"material.terms[{k}][1]": [1e-3, 300.0] for k in range(3)}),
    "power_law": ('model = "power_law"\nG0 = 300.0\nbeta = 0.3\n', ["material.G0", "material.beta"], {}),
}


def mdr_fit(record: pathlib.Path, model: str, folder: pathlib.Path) -> dict:
    material, free, bounds = MODELS[model]
    bounds_toml = ", ".join(f'"{key}" = [{low}, {high}]' for key, (low, high) in bounds.items())
    bounds_line = f"bounds = {{ {bounds_toml} }}\n" if bounds else ""
    case = (f"[material]\n{material}\n[indenter]\nshape = \"cone\"\nhalf_angle_deg = 35.0\n\n"
            f"[fit]\nbaseline = \"fit\"\nfree = {json.dumps(free)}\n{bounds_line}\n"
            f"[[fit.data]]\nfile = \"{record}\"\ntime = \"t_s\"\npiezo = \"z_measured_m\"\n"
            "deflection = \"deflection_m\"\nspring_constant = 1.0677\nsegment_column = \"segment\"\n"
            "segments = [\"0\", \"1\", \"2\"]\n")
    (folder / "case.toml").write_text(case)
    subprocess.run([str(MDR), "fit", str(folder / "case.toml"), "-o", str(folder / "out")], check=True,
                   stdout=subprocess.DEVNULL)
    return json.loads((folder / "out" / "fit.json").read_text())


def classic_fit(record: pathlib.Path, model: str) -> tuple[float, int, float]:
    """CPU seconds, model evaluations and residual RMS / noise of the classic Lee-Radok fit of the same rows."""
    data = np.genfromtxt(record, delimiter=",", names=True, dtype=None, encoding=None)
    rows = np.isin(data["segment"], [0, 1, 2])
    t, depth, force = data["t_s"][rows], data["indentation_m"][rows], data["force_N"][rows]
    dt = t[1] - t[0]
    scale = 8.0 * math.tan(HALF_ANGLE) / math.pi
    terms = 1 if model == "standard" else 3
    noise = np.std(np.diff(force[: len(force) // 20])) / math.sqrt(2.0)
    evaluations = 0
    contact_start = (float(depth[np.argmax(force - force[0] > 10 * noise)]) if np.any(force - force[0] > 10 * noise)
                     else 0.0)
    if model == "power_law":
        lags = np.arange(len(t), dtype=float)

        def predict_power(p):
            nonlocal evaluations
            evaluations += 1
            g0, beta, contact, baseline = p
            rate = np.diff(np.maximum(depth - contact, 0.0) ** 2, prepend=0.0)
            kernel = g0 * dt ** -beta * ((lags + 1.0) ** (1.0 - beta) - lags ** (1.0 - beta)) / (1.0 - beta)
            return scale * fftconvolve(rate, kernel)[: len(t)] + baseline

        begin = time.process_time()
        fit = least_squares(lambda p: (predict_power(p) - force) / noise, [300.0, 0.3, contact_start, float(force[0])],
                            bounds=([0.0, 1e-3, -np.inf, -np.inf], [np.inf, 0.999, np.inf, np.inf]), x_scale="jac")
        return time.process_time() - begin, evaluations, float(np.sqrt(np.mean(fit.fun ** 2)))

    def predict(p):
        nonlocal evaluations
        evaluations += 1
        g_inf, contact, baseline = p[0], p[-2], p[-1]
        h = np.maximum(depth - contact, 0.0) ** 2
        rate = np.diff(h, prepend=0.0)
        out = g_inf * h
        for k in range(terms):
            g, tau = p[1 + 2 * k], p[2 + 2 * k]
            decay = math.exp(-dt / tau)
            out = out + g * lfilter([1.0], [1.0, -decay], rate)  # exact for d^2 constant between rows
        return scale * out + baseline

    start = [200.0] + ([300.0, 1.0] if terms == 1 else [300.0, 0.1, 300.0, 1.0, 300.0, 10.0])
    start += [contact_start, float(force[0])]
    low = [0.0] + [0.0, 1e-3] * terms + [-np.inf, -np.inf]
    high = [np.inf] + [np.inf, 300.0] * terms + [np.inf, np.inf]
    begin = time.process_time()
    fit = least_squares(lambda p: (predict(p) - force) / noise, start, bounds=(low, high), x_scale="jac")
    return time.process_time() - begin, evaluations, float(np.sqrt(np.mean(fit.fun ** 2)))


def main() -> None:
    print(f"{'record':<22} {'model':<9} {'mdr s':>7} {'iter':>5} {'runs':>5} {'elem':>5} {'band':>5} {'status':<14} "
          f"{'res/noise':>9} {'classic s':>9} {'evals':>6} {'res/noise':>9} {'ratio':>6}")
    results = {}
    with tempfile.TemporaryDirectory() as scratch:
        for record in RECORDS:
            for model in MODELS:
                folder = pathlib.Path(scratch) / f"{record.stem}-{model}"
                folder.mkdir()
                fit = mdr_fit(record, model, folder)
                results[f"{record.stem}/{model}"] = fit
                seconds, evaluations, classic_residual = classic_fit(record, model)
                print(f"{record.stem:<22} {model:<9} {fit['wall_seconds']:7.2f} {fit['iterations']:5d} "
                      f"{fit['evaluations']:5d} {fit['element_evaluations']:5d} {fit.get('band_evaluations', 0):5d} "
                      f"{fit['status']:<14} "
                      f"{fit['residual_to_noise']:9.1f} {seconds:9.3f} {evaluations:6d} {classic_residual:9.1f} "
                      f"{fit['wall_seconds'] / seconds:6.0f}", flush=True)
    if len(sys.argv) > 2:
        pathlib.Path(sys.argv[2]).write_text(json.dumps(results, indent=1))


if __name__ == "__main__":
    main()
