"""Figures of a run: force-depth and force-time with loading and unloading told apart, contact radius, pressure
profiles at the snapshots; material functions and complex moduli; a sweep over one or two keys. Uses
matplotlib's Agg backend unless another one is set."""

from __future__ import annotations

import csv
import os
from typing import Mapping

import matplotlib
import matplotlib.ticker

if "MPLBACKEND" not in os.environ:
    matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_csv(path: str) -> dict[str, np.ndarray]:
    """A CSV file with a header line as a dict of arrays keyed by column name: float arrays, or string arrays for
    columns that are not numeric (the `error` column of sweep.csv)."""
    with open(path, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    if not rows:
        raise ValueError(f"{path}: empty file")
    header = rows[0]
    columns = {}
    for i, name in enumerate(header):
        values = [row[i] for row in rows[1:]]
        try:
            columns[name] = np.array(values, dtype=float)
        except ValueError:
            columns[name] = np.array(values, dtype=str)
    return columns


def _loading_mask(depth: np.ndarray) -> np.ndarray:
    """True where the depth grows (loading), False where it falls or holds."""
    change = np.diff(depth, prepend=depth[:1])
    return change > 0


def force_depth(history: Mapping[str, np.ndarray], axes=None):
    """Force over depth, loading in one colour and unloading in another."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    d, F = history["d"], history["F"]
    loading = _loading_mask(d)
    axes.plot(d, F, color="0.8", lw=1, zorder=1)
    axes.plot(np.where(loading, d, np.nan), np.where(loading, F, np.nan), color="C0", label="loading")
    axes.plot(np.where(~loading, d, np.nan), np.where(~loading, F, np.nan), color="C3", label="unloading / hold")
    axes.set(xlabel="depth d [m]", ylabel="normal force F [N]", title="Force-depth")
    axes.legend()
    return axes


def force_time(history: Mapping[str, np.ndarray], axes=None):
    """Force and depth over time (depth on a second axis)."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.plot(history["t"], history["F"], color="C0", label="F")
    axes.set(xlabel="time t [s]", ylabel="normal force F [N]", title="Force and depth over time")
    right = axes.twinx()
    right.plot(history["t"], history["d"], color="C1", ls="--", label="d")
    right.set_ylabel("depth d [m]")
    axes.figure.legend(loc="upper right")
    return axes


def contact_radius(history: Mapping[str, np.ndarray], axes=None):
    """Contact radius over time."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.plot(history["t"], history["a"], color="C2")
    axes.set(xlabel="time t [s]", ylabel="contact radius a [m]", title="Contact radius")
    return axes


def _profiles(profiles: Mapping[str, np.ndarray], column: str, ylabel: str, title: str, axes=None):
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    for time in np.unique(profiles["t"]):
        rows = profiles["t"] == time
        axes.plot(profiles["r"][rows], profiles[column][rows], label=f"t = {time:.4g} s")
    axes.set(xlabel="radius r [m]", ylabel=ylabel, title=title)
    axes.legend()
    return axes


def pressure_profiles(profiles: Mapping[str, np.ndarray], axes=None):
    """Pressure p(r) (eq. 23) at each snapshot time."""
    return _profiles(profiles, "p", "pressure p [Pa]", "Pressure profiles", axes)


def shear_stress_profiles(profiles: Mapping[str, np.ndarray], axes=None):
    """Shear stress tau_xz(r) (eq. 47) at each snapshot time (profiles.csv with tangential loading)."""
    return _profiles(profiles, "tau", "shear stress tau_xz [Pa]", "Shear stress profiles", axes)


def tangential_loop(history: Mapping[str, np.ndarray], axes=None):
    """The tangential force over the tangential displacement (the fretting hysteresis loop)."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.plot(history["u"], history["Fx"], color="C0")
    axes.set(xlabel="tangential displacement u [m]", ylabel="tangential force F_x [N]",
             title="Tangential force-displacement loop")
    return axes


def material_functions(functions: Mapping[str, np.ndarray], axes=None):
    """Relaxation G(t) and creep J(t) on log axes (functions.csv of `mdr material`; J_shear too if present)."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.loglog(functions["t"], functions["G"], color="C0", label="G(t)")
    if "G_model" in functions:  # a model or data standing as a series: both, side by side
        axes.loglog(functions["t"], functions["G_model"], color="k", ls=":", label="G(t), model or data")
    axes.set(xlabel="time t [s]", ylabel="relaxation G [Pa]", title="Material functions")
    right = axes.twinx()
    right.loglog(functions["t"], functions["J"], color="C1", label="J(t)")
    if "J_shear" in functions:
        right.loglog(functions["t"], functions["J_shear"], color="C1", ls="--", label="J_shear(t)")
    right.set_ylabel("creep J [1/Pa]")
    axes.figure.legend(loc="upper center")
    return axes


def dynamic_moduli(dynamic: Mapping[str, np.ndarray], axes=None):
    """Storage and loss moduli over angular frequency on log axes (dynamic.csv of `mdr material`)."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.loglog(dynamic["omega"], dynamic["storage"], label="storage")
    axes.loglog(dynamic["omega"], np.maximum(dynamic["loss"], np.finfo(float).tiny), label="loss")
    if "storage_model" in dynamic:  # a model or data standing as a series: both, side by side
        axes.loglog(dynamic["omega"], dynamic["storage_model"], color="k", ls=":", label="model or data")
        axes.loglog(dynamic["omega"], dynamic["loss_model"], color="k", ls=":")
    axes.set(xlabel="angular frequency omega [rad/s]", ylabel="modulus [Pa]", title="Complex modulus")
    axes.legend()
    return axes


def sweep_map(sweep: Mapping[str, np.ndarray], value: str, axes=None):
    """`value` over the first varied key of a sweep.csv table (log axis if its grid is), one line per value of
    the second varied key if there is one."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    keys = [k for k in sweep if "." in k]
    if not keys:
        raise ValueError("sweep table without varied keys (dotted names)")
    x = sweep[keys[0]]
    groups = np.unique(sweep[keys[1]]) if len(keys) > 1 else [None]
    for group in groups:
        rows = np.ones(x.shape, bool) if group is None else sweep[keys[1]] == group
        order = np.argsort(x[rows])
        axes.plot(x[rows][order], sweep[value][rows][order], label=None if group is None else f"{keys[1]} = {group:g}")
    if np.all(x > 0) and x.max() / x.min() > 100:
        axes.set_xscale("log")
    axes.set(xlabel=keys[0], ylabel=value, title=f"{value} over {keys[0]}")
    if len(keys) > 1:
        axes.legend()
    return axes


MANIFEST = ".mdr-result"  # include/mdr/io/result_directory.hpp: the files mdr wrote into a result directory


def _listed_files(directory: str) -> set[str] | None:
    try:
        with open(os.path.join(directory, MANIFEST), encoding="utf-8") as handle:
            return {line.rstrip("\n") for line in handle if line.strip() and not line.startswith("#")}
    except FileNotFoundError:
        return None


def plot_directory(directory: str) -> list[str]:
    """PNG figures for a result directory: of `mdr run` (force_depth, force_time, contact_radius, with
    tangential loading tangential_loop, and with profiles pressure and shear_stress), of `mdr material` (material,
    dynamic) or of `mdr sweep` (sweep: max_force, or the restitution for impacts, over the varied keys). Returns
    their paths. The figures are added to the directory's manifest, so that mdr may still replace the directory;
    a file of the same name that mdr did not write is never overwritten (ValueError)."""
    listed = _listed_files(directory)

    def path(name):
        return os.path.join(directory, name)

    def figure(name):
        target = path(name + ".png")
        if os.path.lexists(target) and (listed is None or name + ".png" not in listed):
            raise ValueError(f"{target}: exists and was not written by mdr; not overwritten")
        return target

    written = []
    try:
        if os.path.exists(path("history.csv")):
            history = read_csv(path("history.csv"))
            for name, draw in (("force_depth", force_depth), ("force_time", force_time),
                               ("contact_radius", contact_radius)):
                written.append(save(draw(history), figure(name)))
            if "Fx" in history:
                written.append(save(tangential_loop(history), figure("tangential_loop")))
            if os.path.exists(path("profiles.csv")):
                profiles = read_csv(path("profiles.csv"))
                written.append(save(pressure_profiles(profiles), figure("pressure")))
                if "tau" in profiles:
                    written.append(save(shear_stress_profiles(profiles), figure("shear_stress")))
        if os.path.exists(path("functions.csv")):
            written.append(save(material_functions(read_csv(path("functions.csv"))), figure("material")))
        if os.path.exists(path("dynamic.csv")):
            written.append(save(dynamic_moduli(read_csv(path("dynamic.csv"))), figure("dynamic")))
        if os.path.exists(path("sweep.csv")):
            sweep = read_csv(path("sweep.csv"))
            value = "restitution" if "restitution" in sweep else "max_force"
            written.append(save(sweep_map(sweep, value), figure("sweep")))
    finally:
        if listed is not None and written:
            with open(os.path.join(directory, MANIFEST), "a", encoding="utf-8") as handle:
                handle.writelines(os.path.basename(p) + "\n" for p in written if os.path.basename(p) not in listed)
    if not written:
        raise ValueError(f"{directory}: no history.csv, functions.csv or sweep.csv (not a result directory of mdr)")
    return written


def save(axes, path: str) -> str:
    """Writes the axes' figure to `path` (PNG) and closes it; returns the path."""
    for each in axes.figure.axes:
        for axis in (each.xaxis, each.yaxis):
            if isinstance(axis.get_major_formatter(), matplotlib.ticker.ScalarFormatter):  # not on log axes
                axis.get_major_formatter().set_powerlimits((-3, 4))
                axis.get_major_formatter().set_useMathText(True)
    axes.figure.tight_layout()
    axes.figure.savefig(path, dpi=120)
    plt.close(axes.figure)
    return path
