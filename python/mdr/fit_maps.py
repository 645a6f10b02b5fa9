"""Fits of force maps: `mdr.fit_map(case, stack)` fits every curve of a stack with `mdr.fit` — `mdr.map_curves` with a
per-curve fit (python/mdr/curve_maps.py), locally or on a Dask cluster (docs/distributed.md)."""

from __future__ import annotations

import functools
import math
import os
import tomllib
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from .curve_maps import CurveMap, map_curves

#: The channels of a curve, in the order of the last axis of a stack (ny, nx, nt, 3), and the names of its columns.
CHANNELS = ("time", "depth", "force")


class FitNotConverged(Exception):
    """A pixel whose fit stopped without converging (its reason is the fit's status)."""


def fit_curve(curve: Any, case: Mapping[str, Any], time: Sequence[float] | None = None,
              depth: Sequence[float] | None = None, columns: Mapping[str, str] | None = None) -> dict[str, float]:
    """Fits one curve with mdr.fit and returns {key: value, key + "_stderr": standard error} for every free key,
    `rms_residual` and `evaluations`. The curve: a dict of columns (named by `columns`, {"time": name, ...}, default
    the channel names), a (nt, 3) array of time, depth and force, or a (nt,) array of force with the common `time`
    and `depth`. Raises FitNotConverged with the fit's status when it did not converge, ValueError for a bad curve."""
    from .fitting import fit

    if isinstance(curve, Mapping):
        names = {channel: (columns or {}).get(channel, channel) for channel in CHANNELS}
        data = {channel: curve[name] for channel, name in names.items()}
    else:
        array = np.asarray(curve, dtype=float)
        if array.ndim == 2 and array.shape[1] == 3:
            data = dict(zip(CHANNELS, array.T))
        elif array.ndim == 1 and time is not None and depth is not None:
            data = {"time": time, "depth": depth, "force": array}
        else:
            raise ValueError(f"a curve of shape {array.shape}: expected (nt, 3) time, depth, force, or (nt,) force "
                             f"with time= and depth= given")
    result = fit(case, data=[data])
    if result.status != "converged":
        raise FitNotConverged(result.status)
    values: dict[str, float] = {}
    for key, value in result.parameters.items():
        values[key] = value
        values[key + "_stderr"] = result.standard_errors.get(key, math.nan)
    values["rms_residual"] = float(result.summary.get("rms_residual", math.nan))
    values["evaluations"] = float(result.summary.get("evaluations", math.nan))
    return values


def fit_map(case: str | os.PathLike | Mapping[str, Any], stack: Any, *, time: Sequence[float] | None = None,
            depth: Sequence[float] | None = None, columns: Mapping[str, str] | None = None, scheduler: Any = None,
            jobs: int | None = None, out: str | os.PathLike | None = None, figures: bool = True,
            progress: Callable[[int, int], None] | None = None) -> CurveMap:
    """Fits every curve of `stack` (mdr.curve_maps.open_stack: an array (ny, nx, nt) of force with `time` and
    `depth`, an array (ny, nx, nt, 3) of time, depth and force, an HDF5 file, or a directory of curve files with
    positions.csv whose columns `columns` names) with the fit case `case` (its [fit] table; its [[fit.data]], if
    any, is replaced by each pixel's curve). Returns a CurveMap: per free key a map of values and one of standard
    errors (`KEY_stderr`), `rms_residual` and `evaluations`; a pixel whose fit fails or does not converge is FAILED
    with the reason. Options: those of mdr.map_curves (a Dask `scheduler`, local `jobs`, a result directory `out`
    with arrays and heat maps)."""
    if isinstance(case, (str, os.PathLike)):
        with open(case, "rb") as handle:
            case = tomllib.load(handle)
    case = dict(case)
    case["fit"] = {key: value for key, value in dict(case.get("fit", {})).items() if key != "data"}
    per_curve = functools.partial(fit_curve, case=case, time=None if time is None else np.asarray(time, float),
                                  depth=None if depth is None else np.asarray(depth, float), columns=columns)
    return map_curves(per_curve, stack, scheduler=scheduler, jobs=jobs, out=out, figures=figures, progress=progress)
