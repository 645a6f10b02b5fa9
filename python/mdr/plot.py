"""Figures of a run: force-depth and force-time with loading and unloading told apart, contact radius, and
pressure profiles at the snapshots. Uses matplotlib's Agg backend unless another one is set."""

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


def pressure_profiles(profiles: Mapping[str, np.ndarray], axes=None):
    """Pressure p(r) at each snapshot time."""
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    for time in np.unique(profiles["t"]):
        rows = profiles["t"] == time
        axes.plot(profiles["r"][rows], profiles["p"][rows], label=f"t = {time:.4g} s")
    axes.set(xlabel="radius r [m]", ylabel="pressure p [Pa]", title="Pressure profiles")
    axes.legend()
    return axes


def plot_directory(directory: str) -> list[str]:
    """Writes force_depth.png, force_time.png, contact_radius.png and (with profiles) pressure.png into the
    result directory; returns their paths."""
    history_path = os.path.join(directory, "history.csv")
    if not os.path.exists(history_path):
        raise ValueError(f"{directory}: no history.csv (not a result directory of mdr run)")
    history = read_csv(history_path)
    written = []
    for name, draw in (("force_depth", force_depth), ("force_time", force_time), ("contact_radius", contact_radius)):
        axes = draw(history)
        written.append(save(axes, os.path.join(directory, name + ".png")))
    profiles_path = os.path.join(directory, "profiles.csv")
    if os.path.exists(profiles_path):
        written.append(save(pressure_profiles(read_csv(profiles_path)), os.path.join(directory, "pressure.png")))
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
