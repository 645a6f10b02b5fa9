"""Figures of a run: force-depth with loading, holds and unloading told apart, force and depth over time,
contact radius, pressure profiles at the snapshots; material functions and complex moduli; a sweep over one or
two keys.

The backend is matplotlib's choice (Agg where there is no display; ``python -m mdr plot`` always uses Agg).
Every function draws into `axes` when given one, else into a new figure, and returns the axes. Axis labels name
the units of the case's declared unit system (`units`, default "SI"; docs/case-format.md): a system name or the
summary dict of a run.
"""

from __future__ import annotations

import csv
import json
import os
from typing import Any, Mapping, Optional, Union

import matplotlib.pyplot as plt
import matplotlib.ticker
import numpy as np

from . import _mdr

Units = Union[str, Mapping[str, Any]]


def _unit_names(units: Units) -> dict[str, str]:
    """The unit names of a system name, or of the `units` of a run's summary dict (SI when it has none)."""
    if isinstance(units, Mapping):
        units = units.get("units", "SI")
    return _mdr._unit_system(units)


def read_csv(path: str) -> dict[str, np.ndarray]:
    """Reads a CSV file with a header line.

    Parameters
    ----------
    path : str
        The file (history.csv, profiles.csv, sweep.csv, functions.csv, dynamic.csv).

    Returns
    -------
    dict of str to numpy.ndarray
        One array per column, keyed by the header's names: float arrays, or string arrays for columns that are
        not numeric (the ``error`` column of sweep.csv). Quoted fields (RFC 4180) may hold commas, quotes and line
        breaks.

    Raises
    ------
    ValueError
        For an empty file, or a row with another number of fields than the header.

    Examples
    --------
    >>> history = mdr.plot.read_csv("out/demo/history.csv")  # doctest: +SKIP
    >>> history["F"].max()                                   # doctest: +SKIP
    """
    with open(path, newline="", encoding="utf-8") as handle:
        reader = csv.reader(handle)  # RFC 4180: a quoted field may hold commas, quotes and line breaks
        rows = []
        for row in reader:
            if rows and len(row) != len(rows[0]):
                raise ValueError(f"{path}, line {reader.line_num}: {len(row)} fields; the header has {len(rows[0])}")
            rows.append(row)
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


def load_phases(depth: np.ndarray, force: np.ndarray, control: Optional[str] = None) -> np.ndarray:
    """Tells loading, holds and unloading apart along a history.

    A row ends a hold when the controlled quantity did not change since the row before: the depth under
    displacement control (where the force relaxes), the force under force control (where the depth creeps).
    Otherwise it ends loading where the controlled quantity grew, unloading where it fell. Under force control a
    force of zero is no hold but the recovery of the unloaded surface (unloading).

    Parameters
    ----------
    depth, force : numpy.ndarray
        The ``d`` and ``F`` columns of a history.
    control : {"displacement", "force", "impact"}, optional
        The case's control (summary.json ``control``). When not given: force control if the force stays at a
        non-zero value while the depth changes, else displacement control.

    Returns
    -------
    numpy.ndarray of str
        "loading", "hold" or "unloading" per row (the first row: "hold").

    Examples
    --------
    >>> d, F = np.array([0.0, 1.0, 1.5, 1.6, 1.0]), np.array([0.0, 2.0, 2.0, 1.0, 0.0])
    >>> mdr.plot.load_phases(d, F).tolist()
    ['hold', 'loading', 'hold', 'unloading', 'unloading']
    """
    d, F = np.asarray(depth, float), np.asarray(force, float)
    dd, dF = np.diff(d, prepend=d[:1]), np.diff(F, prepend=F[:1])
    # Still: a change below 1e-9 of the largest value (a force solved for under force control meets its target to
    # round-off; a step of a real ramp changes by far more).
    d_still = np.abs(dd) <= 1e-9 * np.max(np.abs(d), initial=0.0)
    F_tolerance = 1e-9 * np.max(np.abs(F), initial=0.0)
    F_held = (np.abs(dF) <= F_tolerance) & (np.abs(F) > F_tolerance)
    if control is None:
        control = "force" if np.any(F_held & ~d_still) else "displacement"
    if control == "force":
        hold, change = F_held, dF
    else:
        hold, change = d_still, dd
    phases = np.where(hold, "hold", np.where(change > 0, "loading", "unloading"))
    phases[:1] = "hold"
    return phases


def force_depth(history: Mapping[str, np.ndarray], axes=None, units: Units = "SI", control: Optional[str] = None):
    """Force over depth, with loading, holds and unloading in their own colours (`load_phases`).

    Parameters
    ----------
    history : dict of str to numpy.ndarray
        With the columns ``d`` and ``F`` (``Result.history`` or history.csv).
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the run's summary dict (default "SI").
    control : str, optional
        The case's control (summary.json ``control``; inferred from the history when not given).

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> result = mdr.run("examples/default.toml")
    >>> axes = mdr.plot.force_depth(result.history, units=result.summary, control=result.summary["control"])
    """
    names = _unit_names(units)
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    d, F = history["d"], history["F"]
    phases = load_phases(d, F, control)
    for phase, color in (("loading", "C0"), ("hold", "C2"), ("unloading", "C3")):
        # The segment from row i - 1 to row i belongs to the phase of row i; NaN separates the segments.
        ends = np.flatnonzero(phases[1:] == phase) + 1
        if ends.size:
            gaps = np.full(ends.size, np.nan)
            axes.plot(np.column_stack([d[ends - 1], d[ends], gaps]).ravel(),
                      np.column_stack([F[ends - 1], F[ends], gaps]).ravel(), color=color, label=phase)
    axes.set(xlabel=f"depth d [{names['length']}]", ylabel=f"normal force F [{names['force']}]", title="Force-depth")
    axes.legend(loc="best")
    return axes


def _legend_of_twins(axes, right) -> None:
    """One legend for a plot with a second y axis, in a row above the axes (never over the curves, the title
    above it or the axis labels)."""
    handles, labels = [], []
    for each in (axes, right):
        more_handles, more_labels = each.get_legend_handles_labels()
        handles += more_handles
        labels += more_labels
    axes.legend(handles, labels, loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=len(labels), frameon=False,
                borderaxespad=0.2)
    axes.set_title(axes.get_title(), pad=24)


def force_time(history: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Force and depth over time (depth on a second y axis).

    Parameters
    ----------
    history : dict of str to numpy.ndarray
        With the columns ``t``, ``d`` and ``F``.
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the run's summary dict (default "SI").

    Returns
    -------
    matplotlib.axes.Axes
        The axes of the force (the depth's is its twin).

    Examples
    --------
    >>> axes = mdr.plot.force_time(mdr.run("examples/default.toml").history)
    """
    names = _unit_names(units)
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.plot(history["t"], history["F"], color="C0", label="force F")
    axes.set(xlabel=f"time t [{names['time']}]", ylabel=f"normal force F [{names['force']}]",
             title="Force and depth over time")
    right = axes.twinx()
    right.plot(history["t"], history["d"], color="C1", ls="--", label="depth d")
    right.set_ylabel(f"depth d [{names['length']}]")
    _legend_of_twins(axes, right)
    return axes


def contact_radius(history: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Contact radius over time.

    Parameters
    ----------
    history : dict of str to numpy.ndarray
        With the columns ``t`` and ``a``.
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the run's summary dict (default "SI").

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> axes = mdr.plot.contact_radius(mdr.run("examples/default.toml").history)
    """
    names = _unit_names(units)
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.plot(history["t"], history["a"], color="C2")
    axes.set(xlabel=f"time t [{names['time']}]", ylabel=f"contact radius a [{names['length']}]",
             title="Contact radius")
    return axes


def _profiles(profiles: Mapping[str, np.ndarray], column: str, ylabel: str, title: str, axes, names):
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    for time in np.unique(profiles["t"]):
        rows = profiles["t"] == time
        axes.plot(profiles["r"][rows], profiles[column][rows], label=f"t = {time:.4g} {names['time']}")
    axes.set(xlabel=f"radius r [{names['length']}]", ylabel=ylabel, title=title)
    axes.legend(loc="best")
    return axes


def pressure_profiles(profiles: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Pressure p(r) (eq. 23) at each snapshot time.

    Parameters
    ----------
    profiles : dict of str to numpy.ndarray
        With the columns ``t``, ``r`` and ``p`` (``Result.profiles`` or profiles.csv).
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the run's summary dict (default "SI").

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> axes = mdr.plot.pressure_profiles(mdr.run("examples/default.toml").profiles)
    """
    names = _unit_names(units)
    return _profiles(profiles, "p", f"pressure p [{names['pressure']}]", "Pressure profiles", axes, names)


def shear_stress_profiles(profiles: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Shear stress tau_xz(r) (eq. 47) at each snapshot time.

    Parameters
    ----------
    profiles : dict of str to numpy.ndarray
        With the columns ``t``, ``r`` and ``tau`` (profiles of a run with tangential loading).
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the run's summary dict (default "SI").

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> axes = mdr.plot.shear_stress_profiles(mdr.run("examples/fretting_stick_radius.toml").profiles)
    """
    names = _unit_names(units)
    return _profiles(profiles, "tau", f"shear stress tau_xz [{names['pressure']}]", "Shear stress profiles", axes,
                     names)


def tangential_loop(history: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """The tangential force over the tangential displacement (the fretting hysteresis loop).

    Parameters
    ----------
    history : dict of str to numpy.ndarray
        With the columns ``u`` and ``Fx`` (a run with tangential loading).
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the run's summary dict (default "SI").

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> axes = mdr.plot.tangential_loop(mdr.run("examples/fretting_stick_radius.toml").history)
    """
    names = _unit_names(units)
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.plot(history["u"], history["Fx"], color="C0")
    axes.set(xlabel=f"tangential displacement u [{names['length']}]",
             ylabel=f"tangential force F_x [{names['force']}]", title="Tangential force-displacement loop")
    return axes


def material_functions(functions: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Relaxation G(t) and creep J(t) on log axes (J on a second y axis).

    Parameters
    ----------
    functions : dict of str to numpy.ndarray
        With the columns ``t``, ``G``, ``J`` and optionally ``J_shear`` (functions.csv of ``mdr material``), or
        ``G_lower``, ``G_upper``, ``J_lower``, ``J_upper`` (functions.csv of ``mdr fit``: 95 % bands, shaded).
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the summary dict of the result directory (default "SI").

    Returns
    -------
    matplotlib.axes.Axes
        The axes of G (J's is its twin).

    Examples
    --------
    >>> m, t = mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1), np.logspace(-3, 1, 50)
    >>> axes = mdr.plot.material_functions({"t": t, "G": m.relaxation(t), "J": m.creep(t)})
    """
    names = _unit_names(units)
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.loglog(functions["t"], functions["G"], color="C0", label="G(t)")
    _band(axes, functions, "t", "G", "C0")
    if "G_model" in functions:  # a model or data standing as a series: both, side by side
        axes.loglog(functions["t"], functions["G_model"], color="k", ls=":", label="G(t), model or data")
    ratio = _young_ratio(units)
    axes.set(xlabel=f"time t [{names['time']}]", ylabel=f"relaxation G [{names['pressure']}]"
             + (f"\n(Young's E(t) = {ratio:.4g} G(t))" if ratio else ""), title="Material functions")
    right = axes.twinx()
    right.loglog(functions["t"], functions["J"], color="C1", label="J(t)")
    _band(right, functions, "t", "J", "C1")
    if "J_shear" in functions:
        right.loglog(functions["t"], functions["J_shear"], color="C1", ls="--", label="J_shear(t)")
    right.set_ylabel(f"creep J [{names['compliance']}]")
    _legend_of_twins(axes, right)
    return axes


def _band(axes, table: Mapping[str, np.ndarray], x: str, name: str, color: str) -> None:
    """Shades the 95 % band of column `name` where the table has it (positive part only: log axes)."""
    if f"{name}_lower" not in table:
        return
    lower = np.maximum(table[f"{name}_lower"], np.finfo(float).tiny)
    axes.fill_between(table[x], lower, table[f"{name}_upper"], color=color, alpha=0.2, lw=0,
                      label=f"{name}: 95 % band")


def _fitted_quantities(units: Units) -> dict[str, str]:
    """What each curve of a fit's summary dict (fit.json) fitted: ``{name: "force" or "depth"}`` ({} without)."""
    if not isinstance(units, Mapping):
        return {}
    return {str(c["name"]): str(c.get("fitted", "force")) for c in units.get("curves", ())
            if c.get("kind") != "rebound"}


def _quantity_label(quantities: set[str], names: Mapping[str, str], prefix: str = "") -> str:
    """``force F [nN]``, ``depth d [µm]``, or both when the curves fitted either: an axis label with its unit."""
    labels = {"force": f"{prefix}force [{names['force']}]", "depth": f"{prefix}depth [{names['length']}]"}
    return " or ".join(labels[q] for q in ("force", "depth") if q in (quantities or {"force", "depth"}))


def _moduli_title(summary: Units, names: Mapping[str, str]) -> str:
    """``G_inf = 0.0154 kPa (E = 0.0462 kPa)`` for each modulus with a Young's modulus in fit.json, else ""."""
    if not isinstance(summary, Mapping) or not summary.get("young_moduli"):
        return ""
    parameters = summary.get("parameters", {})
    return ", ".join(f"{key.split('.')[-1]} = {parameters[key]:.4g} (E = {young:.4g}) {names['pressure']}"
                     for key, young in summary["young_moduli"].items() if key in parameters and young is not None)


def _young_ratio(summary: Units) -> Optional[float]:
    """E / G = 2 (1 + nu) of a fit's summary dict (from its ``young_moduli``), None without them."""
    if not isinstance(summary, Mapping):
        return None
    parameters = summary.get("parameters", {})
    for key, young in (summary.get("young_moduli") or {}).items():
        if young is not None and parameters.get(key):
            return young / parameters[key]
    return None


def fit_curves(curves: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Measured and fitted curves over time, with the residuals (model - measured, with their unit) below.

    Parameters
    ----------
    curves : dict of str to numpy.ndarray
        With the columns ``curve`` (names), ``t``, ``measured``, ``model``, ``residual`` (curves.csv of
        ``mdr fit``).
    axes : sequence of two matplotlib.axes.Axes, optional
        Where to draw (data above, residuals below); a new figure by default.
    units : str or dict, optional
        The unit system's name, or the fit's summary dict (fit.json; default "SI"): with it the axes name the
        fitted quantity (force or depth) and the title the fitted moduli with their Young's moduli E.

    Returns
    -------
    matplotlib.axes.Axes
        The axes of the data (the residuals' share its time axis).

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 50)
    >>> axes = mdr.plot.fit_curves({"curve": np.array(["a"] * 50), "t": t, "measured": t ** 1.5,
    ...                             "model": t ** 1.5, "residual": 0 * t})
    """
    names = _unit_names(units)
    if axes is None:
        _, axes = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), height_ratios=[3, 1.3])
    top, bottom = axes
    curve_names = list(dict.fromkeys(curves["curve"]))
    untimed = False
    for i, name in enumerate(curve_names):
        rows = curves["curve"] == name
        # A curve from a file that records no time has t = nan (docs/case-format.md): drawn over its row number.
        x = curves["t"][rows]
        if np.all(np.isnan(x)):
            x, untimed = np.arange(x.size, dtype=float), True
        top.plot(x, curves["measured"][rows], ".", ms=2, color=f"C{i}", label=f"{name}: measured")
        top.plot(x, curves["model"][rows], "-", lw=1, color="k" if i == 0 else f"C{i}", label=f"{name}: model")
        bottom.plot(x, curves["residual"][rows], ".", ms=2, color=f"C{i}")
    fitted = _fitted_quantities(units)
    quantities = {fitted[name] for name in curve_names if name in fitted}
    moduli = _moduli_title(units, names)
    top.set(ylabel=_quantity_label(quantities, names), title="Fit: data and model" + (f"\n{moduli}" if moduli else ""))
    xlabel = f"time t [{names['time']}]" + (", or row number where no time is recorded" if untimed else "")
    bottom.set(xlabel=xlabel, ylabel="model - measured\n" + _quantity_label(quantities, names))
    bottom.axhline(0.0, color="k", lw=0.5)
    top.legend(loc="best", fontsize=8)
    return top


def force_indentation(curves: Mapping[str, np.ndarray], summary: Mapping[str, Any], axes=None):
    """Force over indentation (depth below the fitted contact point) of each measured curve of a fit, measured and
    model, with the contact point marked: the contact region at full width, with at most half its depth of the
    approach before it (a long approach would leave it a sliver).

    Parameters
    ----------
    curves : dict of str to numpy.ndarray
        curves.csv of ``mdr fit``, with its ``drive`` column (the depth below the contact point of a force-fitted
        curve, the force above the baseline of a depth-fitted one).
    summary : dict
        fit.json of the same fit (each curve's ``fitted``, ``contact_point``, ``baseline``; ``units``).
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> summary = json.load(open("out/fit.json"))  # doctest: +SKIP
    >>> axes = mdr.plot.force_indentation(mdr.plot.read_csv("out/curves.csv"), summary)  # doctest: +SKIP
    """
    names = _unit_names(summary)
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    for i, entry in enumerate(c for c in summary["curves"] if c.get("kind") != "rebound"):
        rows = curves["curve"] == entry["name"]
        baseline = entry["baseline"] or 0.0
        if entry.get("fitted", "force") == "force":
            x_measured = x_model = curves["drive"][rows]
            y_measured, y_model = curves["measured"][rows], curves["model"][rows]
        else:
            contact = entry["contact_point"] or 0.0
            x_measured, x_model = curves["measured"][rows] - contact, curves["model"][rows] - contact
            y_measured = y_model = curves["drive"][rows] + baseline
        axes.plot(x_measured, y_measured, ".", ms=2, color=f"C{i}", label=f"{entry['name']}: measured")
        axes.plot(x_model, y_model, "-", lw=1, color="k" if i == 0 else f"C{i}", label=f"{entry['name']}: model")
        axes.plot([0.0], [baseline], "o", mfc="none", ms=9, color="C3",
                  label="contact point" if i == 0 else None)
    axes.axvline(0.0, color="C3", lw=0.7, ls="--")
    deepest = max((np.nanmax(line.get_xdata()) for line in axes.get_lines() if len(line.get_xdata())), default=0.0)
    if deepest > 0.0:  # the contact region at full width, half as much of the approach before it
        axes.set_xlim(left=max(axes.get_xlim()[0], -0.5 * deepest))
    moduli = _moduli_title(summary, names)
    axes.set(xlabel=f"indentation d - contact point [{names['length']}]", ylabel=f"force F [{names['force']}]",
             title="Force-indentation" + (f"\n{moduli}" if moduli else ""))
    axes.legend(loc="best", fontsize=8)
    return axes


_REBOUND_QUANTITIES = {"restitution": "restitution e", "contact_time": "contact time T [m{time}]"}


def _rebound_rows(curves: Mapping[str, np.ndarray]) -> np.ndarray:
    """Which rows of curves.csv are rebound data (their curve named ``NAME:restitution`` or ``NAME:contact_time``)."""
    names = np.asarray(curves["curve"], dtype=str)
    return np.array([name.rpartition(":")[2] in _REBOUND_QUANTITIES and ":" in name for name in names], dtype=bool)


def _rows(table: Mapping[str, np.ndarray], keep: np.ndarray) -> dict[str, np.ndarray]:
    return {name: np.asarray(values)[keep] for name, values in table.items()}


def fit_rebounds(curves: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Measured and fitted rebound data over the approach speed: e(v0) and, where measured, T(v0).

    Parameters
    ----------
    curves : dict of str to numpy.ndarray
        The rebound rows of curves.csv of ``mdr fit`` (``curve`` named ``NAME:restitution`` or
        ``NAME:contact_time``, ``t`` holding v0, ``measured``, ``model``); other rows are left out.
    axes : sequence of two matplotlib.axes.Axes, optional
        Where to draw (e above, T below); a new figure by default.
    units : str or dict, optional
        The unit system's name, or the fit's summary dict (fit.json; default "SI"). T is drawn in thousandths of
        its time unit (ms in every declared system).

    Returns
    -------
    matplotlib.axes.Axes
        The axes of e (T's share its speed axis).

    Examples
    --------
    >>> v0 = np.array([0.01, 0.1, 1.0])
    >>> axes = mdr.plot.fit_rebounds({"curve": np.array(["drops:restitution"] * 3), "t": v0,
    ...                               "measured": np.array([0.5, 0.55, 0.6]), "model": np.array([0.5, 0.56, 0.6])})
    """
    unit_names = _unit_names(units)
    rows = _rows(curves, _rebound_rows(curves))
    if axes is None:
        _, axes = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5))
    top, bottom = axes
    names = np.asarray(rows["curve"], dtype=str)
    colours = {data_set: f"C{i}" for i, data_set in enumerate(dict.fromkeys(n.rpartition(":")[0] for n in names))}
    for name in dict.fromkeys(names):
        data_set, _, quantity = name.rpartition(":")
        target, scale = (top, 1.0) if quantity == "restitution" else (bottom, 1e3)
        keep = names == name
        order = np.argsort(rows["t"][keep])
        v0 = rows["t"][keep][order]
        colour = colours[data_set]
        target.plot(v0, scale * rows["measured"][keep][order], "o", ms=4, color=colour, label=f"{data_set}: measured")
        target.plot(v0, scale * rows["model"][keep][order], "-", lw=1, color=colour, label=f"{data_set}: model")
    top.set(xscale="log", ylabel=_REBOUND_QUANTITIES["restitution"], title="Fit: rebound data and model")
    bottom.set(xlabel=f"approach speed v0 [{unit_names['velocity']}]",
               ylabel=_REBOUND_QUANTITIES["contact_time"].format(time=unit_names["time"]))
    top.legend(loc="best", fontsize=8)
    return top


def dynamic_moduli(dynamic: Mapping[str, np.ndarray], axes=None, units: Units = "SI"):
    """Storage and loss moduli over angular frequency on log axes.

    Parameters
    ----------
    dynamic : dict of str to numpy.ndarray
        With the columns ``omega``, ``storage`` and ``loss`` (dynamic.csv of ``mdr material``), and the 95 % bands
        ``storage_lower`` ... ``loss_upper`` of ``mdr fit`` (shaded) where given.
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.
    units : str or dict, optional
        The unit system's name, or the summary dict of the result directory (default "SI").

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> w = np.logspace(-2, 3, 50)
    >>> G = mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1).complex_modulus(w)
    >>> axes = mdr.plot.dynamic_moduli({"omega": w, "storage": G.real, "loss": G.imag})
    """
    names = _unit_names(units)
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    axes.loglog(dynamic["omega"], dynamic["storage"], label="storage")
    axes.loglog(dynamic["omega"], np.maximum(dynamic["loss"], np.finfo(float).tiny), label="loss")
    _band(axes, dynamic, "omega", "storage", "C0")
    _band(axes, dynamic, "omega", "loss", "C1")
    if "storage_model" in dynamic:  # a model or data standing as a series: both, side by side
        axes.loglog(dynamic["omega"], dynamic["storage_model"], color="k", ls=":", label="model or data")
        axes.loglog(dynamic["omega"], dynamic["loss_model"], color="k", ls=":")
    axes.set(xlabel=f"angular frequency omega [rad/{names['time']}]", ylabel=f"modulus [{names['pressure']}]",
             title="Complex modulus")
    axes.legend(loc="best")
    return axes


def sweep_map(sweep: Mapping[str, np.ndarray], value: str, axes=None):
    """One column of a sweep over the first varied key, one line per value of the second varied key if any.

    Parameters
    ----------
    sweep : dict of str to numpy.ndarray
        A sweep table (``mdr.sweep`` or sweep.csv); the varied keys are the dotted names.
    value : str
        The column to plot (a numeric summary key, e.g. "max_force" or "restitution").
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.

    Returns
    -------
    matplotlib.axes.Axes
        With a log x axis when the first key's grid spans two decades or more of positive values.

    Raises
    ------
    ValueError
        When the table has no varied keys, or no numeric column `value` (the message lists those it has).

    Examples
    --------
    >>> table = mdr.sweep("examples/default.toml", {"material.G_inf": [0.5e6, 1e6, 2e6]}, jobs=2)
    >>> axes = mdr.plot.sweep_map(table, "max_force")
    """
    keys = [k for k in sweep if "." in k]
    if not keys:
        raise ValueError("sweep table without varied keys (dotted names)")
    columns = [k for k in sweep if k not in keys and np.asarray(sweep[k]).dtype.kind == "f"]
    if value not in columns:
        raise ValueError(f"column = {value}: not a numeric column of the sweep; one of {', '.join(columns)}")
    axes = axes or plt.figure(figsize=(6, 4.5)).add_subplot()
    x = sweep[keys[0]]
    groups = np.unique(sweep[keys[1]]) if len(keys) > 1 else [None]
    for group in groups:
        rows = np.ones(x.shape, bool) if group is None else sweep[keys[1]] == group
        order = np.argsort(x[rows])
        axes.plot(x[rows][order], sweep[value][rows][order], marker=".",
                  label=None if group is None else f"{keys[1]} = {group:g}")
    if np.all(x > 0) and x.max() / x.min() >= 100:
        axes.set_xscale("log")
    axes.set(xlabel=keys[0], ylabel=value, title=f"{value} over {keys[0]}")
    if len(keys) > 1:
        axes.legend(loc="best")
    return axes


MANIFEST = ".mdr-result"  # include/mdr/io/result_directory.hpp: the files mdr wrote into a result directory


def _listed_files(directory: str) -> Optional[set[str]]:
    try:
        with open(os.path.join(directory, MANIFEST), encoding="utf-8") as handle:
            return {line.rstrip("\n") for line in handle if line.strip() and not line.startswith("#")}
    except FileNotFoundError:
        return None


def _summary(directory: str) -> dict[str, Any]:
    """summary.json of a run or of mdr material, else fit.json of a fit (both hold ``units``); {} without either."""
    for name in ("summary.json", "fit.json"):
        try:
            with open(os.path.join(directory, name), encoding="utf-8") as handle:
                return json.load(handle)
        except FileNotFoundError:
            pass
    return {}


def plot_directory(directory: str, column: Optional[str] = None) -> list[str]:
    """Writes PNG figures for a result directory of mdr, beside its CSV files.

    Of ``mdr run``: force_depth, force_time, contact_radius, with tangential loading tangential_loop, with
    profiles pressure (and shear_stress); of ``mdr material``: material, dynamic; of ``mdr fit``: fit_curves,
    force_indentation (the contact point marked), material, dynamic (with 95 % bands); of ``mdr sweep``: sweep;
    of ``mdr fit --map``: map_KEY, one heat map per output of map.csv (mdr.map_figures).
    A directory of ``mdr fit`` with candidates (one folder per model) or ``--each`` (one folder per file) gets the
    figures of each folder, in the folder. The figures are added to the directory's manifest, so that mdr may
    still replace the directory; a file of the same name that mdr did not write is never overwritten.

    Parameters
    ----------
    directory : str
        The result directory.
    column : str, optional
        The column of sweep.csv that sweep.png plots (default: ``restitution`` for impacts, else
        ``max_force``).

    Returns
    -------
    list of str
        The paths of the figures written.

    Raises
    ------
    ValueError
        For a directory without result files, a figure's name taken by a file mdr did not write, or a
        `column` that sweep.csv does not have.

    Examples
    --------
    >>> mdr.plot.plot_directory("out/demo")   # doctest: +SKIP
    ['out/demo/force_depth.png', 'out/demo/force_time.png', 'out/demo/contact_radius.png', 'out/demo/pressure.png']
    """
    listed = _listed_files(directory)
    written: list[str] = []
    try:
        _plot_files(directory, listed, column, written)
        if not written:  # a fit's candidates or --each: one result folder per model or file
            for name in sorted(os.listdir(directory)):
                folder = os.path.join(directory, name)
                if os.path.isdir(folder) and not os.path.islink(folder) and \
                        os.path.exists(os.path.join(folder, "curves.csv")):
                    inner = None if listed is None else {e[len(name) + 1:] for e in listed if e.startswith(name + "/")}
                    _plot_files(folder, inner, column, written)
    finally:
        if listed is not None and written:
            names = [os.path.relpath(p, directory).replace(os.sep, "/") for p in written]
            with open(os.path.join(directory, MANIFEST), "a", encoding="utf-8") as handle:
                handle.writelines(name + "\n" for name in names if name not in listed)
    if not written:
        raise ValueError(f"{directory}: no history.csv, curves.csv, functions.csv, sweep.csv or map.csv, nor "
                         "folders of fit results (not a result directory of mdr)")
    return written


def _plot_files(directory: str, listed: Optional[set[str]], column: Optional[str], written: list[str]) -> None:
    """The figures of the result files in `directory` (not its folders), appended to `written` as drawn."""
    def path(name):
        return os.path.join(directory, name)

    def figure(name):
        target = path(name + ".png")
        if os.path.lexists(target) and (listed is None or name + ".png" not in listed):
            raise ValueError(f"{target}: exists and was not written by mdr; not overwritten")
        return target

    if os.path.exists(path("history.csv")):
        history = read_csv(path("history.csv"))
        units = _summary(directory)
        written.append(save(force_depth(history, units=units, control=units.get("control")),
                            figure("force_depth")))
        for name, draw in (("force_time", force_time), ("contact_radius", contact_radius)):
            written.append(save(draw(history, units=units), figure(name)))
        if "Fx" in history:
            written.append(save(tangential_loop(history, units=units), figure("tangential_loop")))
        if os.path.exists(path("profiles.csv")):
            profiles = read_csv(path("profiles.csv"))
            written.append(save(pressure_profiles(profiles, units=units), figure("pressure")))
            if "tau" in profiles:
                written.append(save(shear_stress_profiles(profiles, units=units), figure("shear_stress")))
    if os.path.exists(path("curves.csv")):
        curves = read_csv(path("curves.csv"))
        summary = _summary(directory)
        rebound = _rebound_rows(curves)
        if not rebound.all():
            written.append(save(fit_curves(_rows(curves, ~rebound), units=summary), figure("fit_curves")))
            if "drive" in curves and summary.get("curves"):
                written.append(save(force_indentation(curves, summary), figure("force_indentation")))
        if rebound.any():
            written.append(save(fit_rebounds(curves, units=summary), figure("fit_rebounds")))
    if os.path.exists(path("functions.csv")):
        functions = read_csv(path("functions.csv"))
        written.append(save(material_functions(functions, units=_summary(directory)), figure("material")))
    if os.path.exists(path("dynamic.csv")):
        dynamic = read_csv(path("dynamic.csv"))
        written.append(save(dynamic_moduli(dynamic, units=_summary(directory)), figure("dynamic")))
    if os.path.exists(path("map.csv")) and os.path.exists(path("map.json")):
        from .map_figures import map_heat_maps
        for name, drawn in map_heat_maps(directory):
            target = figure("map_" + name)
            drawn.savefig(target, dpi=120)
            written.append(target)
    if os.path.exists(path("sweep.csv")):
        sweep = read_csv(path("sweep.csv"))
        value = column or ("restitution" if "restitution" in sweep else "max_force")
        written.append(save(sweep_map(sweep, value), figure("sweep")))


def save(axes, path: str) -> str:
    """Writes the figure of `axes` to a PNG file and closes it.

    Parameters
    ----------
    axes : matplotlib.axes.Axes
        Any axes of the figure.
    path : str
        The file to write.

    Returns
    -------
    str
        `path`.

    Examples
    --------
    >>> mdr.plot.save(mdr.plot.force_depth(mdr.run("examples/default.toml").history), "fd.png")  # doctest: +SKIP
    'fd.png'
    """
    for each in axes.figure.axes:
        for axis in (each.xaxis, each.yaxis):
            if isinstance(axis.get_major_formatter(), matplotlib.ticker.ScalarFormatter):  # not on log axes
                axis.get_major_formatter().set_powerlimits((-3, 4))
                axis.get_major_formatter().set_useMathText(True)
    axes.figure.tight_layout()
    axes.figure.savefig(path, dpi=120)
    plt.close(axes.figure)
    return path
