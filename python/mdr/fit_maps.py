"""Fits of force maps: `mdr.fit_map(case, stack)` fits every curve of a stack with `mdr.fit` — `mdr.map_curves` with a
per-curve fit (python/mdr/curve_maps.py), locally or on a Dask cluster (docs/distributed.md)."""

from __future__ import annotations

import functools
import math
import os
import tomllib
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from ._arrays import real_array
from ._case_tree import plain_tree
from .curve_maps import CurveMap, MapRow, map_curves, open_stack
from .fit_map_files import MapTable, fit_map_file, is_instrument_file
from .map_figures import is_result

#: The channels of a curve, in the order of the last axis of a stack (ny, nx, nt, 3), and the names of its columns.
CHANNELS = ("time", "depth", "force")


def fit_curve(curve: Any, case: Mapping[str, Any], time: Sequence[float] | None = None,
              depth: Sequence[float] | None = None, columns: Mapping[str, str] | None = None,
              pixel: tuple[int, int, int] = (0, 0, 0)) -> MapRow:
    """Fits one curve as a pixel of a map: the per-curve function of `fit_map`, the same C++ as a pixel of ``mdr fit
    CASE --map FILE`` (mdr/fitcase/map_fit.hpp), whose row of map.csv it returns.

    A fit that stops without converging returns its row too, as ``mdr fit --map`` writes it and `mdr.fit` returns
    it: the values and errors where the fit stopped, ``status`` saying why, and that reason as the row's
    `MapRow.stopped` ("" for a result: ``converged``, or ``converged, misfit`` with its flag), so that `map_curves`
    keeps the pixel as ``NOT_CONVERGED`` with its values.

    Parameters
    ----------
    curve : dict, numpy.ndarray
        A dict of columns (named by `columns`), a (nt, 3) array of time [s], depth [m] and force [N], or a (nt,)
        array of force with the common `time` and `depth`.
    case : dict
        A fit case (``[fit]`` table included) as a dict; its ``[[fit.data]]`` is not used; no model choice.
    time, depth : sequence of float, optional
        The common time [s] and depth [m] of curves given as force alone.
    columns : dict, optional
        The column names of a dict curve, ``{"time": name, "depth": name, "force": name}`` (default: those names).
    pixel : tuple of int, optional
        The curve's ``index`` in the stack (row-major), its ``column`` and its ``row``.

    Returns
    -------
    MapRow
        The row of map.csv (docs/instrument-to-map.md): ``index``, ``column``, ``row``, ``x``, ``y`` (0: a stack
        states no positions), every free key and ``KEY_stderr``, ``E_KEY`` and ``E_KEY_stderr`` for every Young
        modulus, ``contact_height`` (-contact point), ``residual_to_noise``, ``noise``, ``status``, ``flags`` and
        ``failure``, with the unit of each (``units``), the case's unit system and `MapRow.stopped`.

    Raises
    ------
    ValueError
        For a bad curve or case (the fit's message).

    Examples
    --------
    >>> t = np.linspace(0.0, 1.0, 51)
    >>> d = 1e-5 * t
    >>> F = 16.0 / 3.0 * 1e6 * math.sqrt(1e-3) * d ** 1.5          # Hertz, G = 1 MPa, R = 1 mm
    >>> case = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
    ...         "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
    >>> values = mdr.fit_maps.fit_curve(F, case, time=t, depth=d)
    >>> round(values["material.G"] / 1e6, 4), values["status"], values.units["material.G"], values.stopped
    (1.0, 'converged', 'Pa', '')
    >>> case["fit"]["max_iterations"] = 2                                   # too few: the fit stops short
    >>> values = mdr.fit_maps.fit_curve(F, case, time=t, depth=d)
    >>> values["status"], values.stopped, values["material.G"] > 0
    ('did not converge in 2 iterations', 'did not converge in 2 iterations', True)
    """
    from . import _mdr

    if isinstance(curve, Mapping):
        names = {channel: (columns or {}).get(channel, channel) for channel in CHANNELS}
        data = {channel: curve[name] for channel, name in names.items()}
    else:
        array = real_array(curve, "curve", dims=(1, 2))
        if array.ndim == 2 and array.shape[1] == 3:
            data = dict(zip(CHANNELS, array.T))
        elif array.ndim == 1 and time is not None and depth is not None:
            data = {"time": time, "depth": depth, "force": array}
        else:
            raise ValueError(f"curve: an array of shape {array.shape}; must be (nt, 3) time, depth, force, or (nt,) "
                             f"force with time= and depth= given")
    arrays = [real_array(data[channel], channel) for channel in CHANNELS]
    index, column, row = pixel
    values, units, unit_system = _mdr._fit_map_curve(plain_tree(case), "case", os.getcwd(), *arrays, index, column,
                                                     row)
    stopped = "" if is_result(values["status"]) else values["status"]
    return MapRow(values, units, unit_system, stopped)


class _NumberedStack:
    """A stack whose curves come with their place: (index, column, row, curve), None where it has no curve."""

    def __init__(self, stack: Any):
        self.stack, self.shape, self.inputs, self.source = stack, stack.shape, stack.inputs, stack.source

    def read(self, start: int, stop: int) -> list:
        nx = self.shape[1]
        return [None if curve is None else (index, index % nx, index // nx, curve)
                for index, curve in zip(range(start, stop), self.stack.read(start, stop))]

    def close(self) -> None:
        self.stack.close()


def _fit_pixel(numbered: tuple, **settings: Any) -> MapRow:
    """fit_curve of one curve of a _NumberedStack."""
    index, column, row, curve = numbered
    return fit_curve(curve, pixel=(index, column, row), **settings)


def fit_map(case: str | os.PathLike | Mapping[str, Any], stack: Any, *, time: Sequence[float] | None = None,
            depth: Sequence[float] | None = None, columns: Mapping[str, str] | None = None, scheduler: Any = None,
            jobs: int | None = None, out: str | os.PathLike | None = None, figures: bool = True,
            progress: Callable[[int, int], None] | None = None) -> CurveMap | MapTable:
    """Fits every curve of `stack` with the fit case `case`: `mdr.map_curves` with `fit_curve` for every pixel.

    A pixel whose fit fails is FAILED with the reason and no values; one whose fit stops without converging is
    NOT_CONVERGED with the values and errors where it stopped and the fit's status as its reason (the row ``mdr fit
    CASE --map FILE`` writes for it); the map goes on. Locally on `jobs` processes or on the workers of a Dask
    `scheduler`, with the same values bit for bit (docs/distributed.md).

    Parameters
    ----------
    case : str, os.PathLike or dict
        A fit case (docs/case-format.md, "Fitting"): its ``[fit]`` table is used; its ``[[fit.data]]``, if any, is
        replaced by each pixel's curve.
    stack : array-like, str or os.PathLike
        An instrument map file (``.jpk-force-map``, ``.jpk-qi-data``, ...: `mdr.fit_map_files.fit_map_file`, the
        same C++ as ``mdr fit CASE --map FILE``; returns a `MapTable` with the columns of map.csv; with `out`,
        map.csv, map.json and with `figures` the heat maps are written there; its pixels are fitted on `jobs`
        threads; `time`, `depth`, `columns` and `scheduler` are refused with it), or what
        ``mdr.curve_maps.open_stack`` takes: an array (ny, nx, nt) of force [N] with `time` and `depth`, an array
        (ny, nx, nt, 3) of time, depth and force, an HDF5 file of either, or a directory of curve files with
        positions.csv whose columns `columns` names.
    time, depth : sequence of float, optional
        The common time [s] and depth [m] of a stack of forces alone.
    columns : dict, optional
        The column names of a directory's curves, ``{"time": name, "depth": name, "force": name}`` (default: those
        names).
    scheduler, jobs, out, figures, progress
        As for `mdr.map_curves`: a Dask scheduler or local processes, a result directory with the arrays and heat
        maps, a progress callback ``progress(done, total)``.

    Returns
    -------
    CurveMap
        ``values``: the columns of `fit_curve`'s row (those of map.csv) as (ny, nx) maps: per free key a map of
        values and one of standard errors (``KEY_stderr``), ``residual_to_noise``, the fit's ``status`` (text), ...;
        ``status`` the pixels' codes (``OK``, ``FAILED``, ``NO_CURVE``, ``NOT_CONVERGED``) and ``reasons``.

    Examples
    --------
    A 2 x 2 map of Hertz curves F = (16/3) G sqrt(R) d^(3/2), one pixel with a gap in its force:

    >>> t = np.linspace(0.0, 1.0, 51)
    >>> d = 1e-5 * t
    >>> G = np.array([[1e6, 2e6], [3e6, 4e6]])
    >>> forces = 16.0 / 3.0 * G[..., None] * math.sqrt(1e-3) * d ** 1.5                  # (2, 2, 51)
    >>> forces[1, 1, 20] = np.nan
    >>> case = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
    ...         "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
    >>> fits = mdr.fit_map(case, forces, time=t, depth=d, jobs=1)
    >>> np.round(fits.values["material.G"] / 1e6, 4)
    array([[ 1.,  2.],
           [ 3., nan]])
    >>> fits.status[1, 1] == mdr.curve_maps.FAILED, fits.reasons[1, 1]
    (True, 'InvalidInput: force = nan: at index 20: must be a finite number')

    With 10 iterations at most, the fit of G = 2 MPa (from 0.3 MPa) stops short: its pixel keeps where it stopped.

    >>> case["fit"]["max_iterations"] = 10
    >>> fits = mdr.fit_map(case, forces[:1], time=t, depth=d, jobs=1)
    >>> fits.status.tolist(), fits.reasons[0, 1], fits.values["status"][0, 1]
    ([[0, 3]], 'did not converge in 10 iterations', 'did not converge in 10 iterations')
    >>> bool(np.isfinite(fits.values["material.G"][0, 1]))
    True
    """
    if is_instrument_file(stack):
        given = {"time": time, "depth": depth, "columns": columns, "scheduler": scheduler}
        for name, value in given.items():
            if value is not None:
                raise ValueError(f"{name}: not used with an instrument file ({os.fspath(stack)}), which states its "
                                 "own channels and is fitted here, on local threads")
        return fit_map_file(case, stack, jobs=jobs, out=out, figures=figures, progress=progress)
    if isinstance(case, (str, os.PathLike)):
        with open(case, "rb") as handle:
            case = tomllib.load(handle)
    case = dict(case)
    case["fit"] = {key: value for key, value in dict(case.get("fit", {})).items() if key != "data"}
    per_curve = functools.partial(_fit_pixel, case=case, time=None if time is None else real_array(time, "time"),
                                  depth=None if depth is None else real_array(depth, "depth"), columns=columns)
    opened = open_stack(stack)
    try:
        return map_curves(per_curve, _NumberedStack(opened), scheduler=scheduler, jobs=jobs, out=out, figures=figures,
                          progress=progress)
    finally:
        if opened is not stack:
            opened.close()
