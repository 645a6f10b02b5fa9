#!/usr/bin/python3
"""A force-driven creep fit of a 6 000-point record (issue 25's target: <= 1 s), timed. The record is synthetic: a
sphere (R = 5 um) pressed into a standard solid (G_inf = 1 kPa, G1 = 2 kPa, tau1 = 2 s) by a force ramped to 5 nN
in 0.5 s and held to 30 s; the depth from the closed form of Lee and Radok for a creep compliance,
d(t)^1.5 = 3 / (16 sqrt(R)) int_0^t J(t - s) dF(s) (Hertz with E* = 4G, incompressible; Lee & Radok 1960),
J(t) = 1/G_inf - G1 / (G_inf G_0) exp(-t / tau_c), G_0 = G_inf + G1, tau_c = tau1 G_0 / G_inf, plus Gaussian noise
of 1e-4 of the peak depth. `mdr fit` with fitted = "depth", the contact point and baseline fixed (the data's zero),
G_inf, G1, tau1 free from 2x off. Prints mdr's wall time, iterations, runs and the fitted values.
Usage: bench/creep_fit.py [path/to/mdr]
"""
from __future__ import annotations

import json
import math
import pathlib
import subprocess
import sys
import tempfile

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parent.parent
MDR = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build" / "bin" / "mdr"
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
        subprocess.run([str(MDR), "fit", str(folder / "case.toml"), "-o", str(folder / "out")], check=True,
                       stdout=subprocess.DEVNULL)
        fit = json.loads((folder / "out" / "fit.json").read_text())
    print(f"rows {ROWS}: mdr {fit['wall_seconds']:.3f} s, {fit['iterations']} iterations, {fit['evaluations']} runs "
          f"({fit['element_evaluations']} element, {fit.get('band_evaluations', 0)} band), {fit['status']}, "
          f"residual/noise {fit['residual_to_noise']:.3f}")
    truth = {"material.G_inf": G_INF, "material.G1": G1, "material.tau1": TAU}
    for key, value in fit["parameters"].items():
        print(f"  {key} = {value:.6g} +- {fit['standard_errors'][key]:.2g} (true {truth[key]:.6g})")


if __name__ == "__main__":
    main()
