"""mdr: viscoelastic contact mechanics by the Method of Dimensionality Reduction (Popov & Hess).

    import mdr
    result = mdr.run("examples/default.toml")          # or a dict with the structure of the case file
    result.history["F"]                                 # numpy arrays keyed by the history.csv columns
    result.summary["max_force"]                         # the summary.json keys
    mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1).creep([0.1, 1.0])
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field
from typing import Any, Mapping, Union

import numpy as np

from . import _mdr
from ._mdr import Indenter, InvalidInput, Material
from ._toml import to_toml
from .curve_maps import map_curves
from .fit_maps import fit_map
from .fitting import FitResult, fit

__all__ = ["run", "check", "sweep", "SweepTable", "fit", "FitResult", "map_curves", "fit_map", "Material", "Indenter",
           "Result", "InvalidInput", "__version__"]
__version__ = _mdr.__version__

CaseLike = Union[str, os.PathLike, Mapping[str, Any]]


@dataclass
class Result:
    """What a run produced: `history` and `profiles` are dicts of numpy arrays keyed by the CSV column names,
    `summary` the summary.json object, `description` the one-line description of the case."""

    history: dict[str, np.ndarray]
    summary: dict[str, Any]
    profiles: dict[str, np.ndarray] = field(default_factory=dict)
    description: str = ""


def _case_text(case: CaseLike) -> tuple[str, str]:
    if isinstance(case, Mapping):
        return to_toml(case), "case"
    if isinstance(case, (str, os.PathLike)):
        path = os.fspath(case)
        try:
            with open(path, encoding="utf-8") as handle:
                return handle.read(), path
        except OSError:
            # The same line as the command line's (src/io/case_file.cpp, load_case).
            raise InvalidInput(f"case = {path}: cannot be read (no such file, or no permission)") from None
    raise TypeError(f"case: expected a path or a dict, got {type(case).__name__}")


def run(case: CaseLike) -> Result:
    """Runs a case (a TOML file path or a dict with the same structure) and returns a Result.
    Bad input raises ValueError with the same message as the command line."""
    text, source = _case_text(case)
    raw = _mdr._run_toml(text, source)
    return Result(history=dict(raw["history"]), summary=json.loads(raw["summary_json"]),
                  profiles=dict(raw["profiles"]), description=raw["description"])


def check(case: CaseLike) -> str:
    """Validates a case and returns its one-line description; raises ValueError for bad input."""
    text, source = _case_text(case)
    return _mdr._check_toml(text, source)


def _axis_spec(key: str, values: Any) -> str:
    if isinstance(values, str):
        return f"{key}={values}"
    array = np.asarray(values, dtype=float)
    if array.ndim != 1 or array.size == 0:
        raise ValueError(f"vary[{key!r}]: expected a 1-D list of numbers or 'START:STOP:COUNT[:log]'")
    return f"{key}=" + ",".join(repr(float(v)) for v in array)


class SweepTable(dict):
    """The table of a sweep: a dict of numpy arrays (column name -> one value a row); `batch` tells how it ran
    (mdr.distributed.MapOutcome without the outputs: scheduler, workers, tasks, retried, seconds; None for a local
    sweep)."""

    batch: Any = None


def sweep(case: CaseLike, vary: Mapping[str, Any], jobs: int | None = None, scheduler: Any = None) -> SweepTable:
    """Runs a case over the cartesian product of `vary` ({dotted key: values or "START:STOP:COUNT[:log]"}, the
    last key varying fastest) on `jobs` threads (default: all cores), like `mdr sweep`; or, with `scheduler` (a
    Dask scheduler address "tcp://HOST:PORT" or a distributed.Client), in chunks on its workers (docs/distributed.md),
    with the same rows bit for bit. Returns a table as a dict of numpy arrays: the varied keys, every numeric key of
    summary.json (nan where a point failed), and `error` (the failure message, "" where the point ran)."""
    if not isinstance(vary, Mapping) or not vary:
        raise TypeError("vary: expected a non-empty dict {key: values}")
    if jobs is not None and (not isinstance(jobs, int) or jobs < 1):
        raise ValueError(f"jobs = {jobs!r}: must be an integer >= 1")
    if jobs is not None and scheduler is not None:
        raise ValueError(f"jobs = {jobs!r}: not used with a scheduler (its workers' threads run the chunks)")
    text, source = _case_text(case)
    specs = [_axis_spec(key, values) for key, values in vary.items()]
    batch = None
    if scheduler is None:
        raw = _mdr._sweep_toml(text, source, specs, jobs or 0)
    else:
        from . import distributed

        _, points, batch = distributed.sweep_rows(text, source, specs, scheduler)
        raw = {"points": points, "summaries": [row[0] for row in batch.outputs],
               "errors": [row[1] for row in batch.outputs]}
        batch.outputs = []
    summaries = [json.loads(s) if s else {} for s in raw["summaries"]]
    columns = next((list(s) for s in summaries if s), [])
    table = SweepTable()
    table.batch = batch
    points = np.asarray(raw["points"], dtype=float).reshape(len(summaries), len(specs))
    for i, key in enumerate(vary):
        table[key] = points[:, i]
    for column in columns:
        values = [s.get(column, math.nan) if s else math.nan for s in summaries]
        if all(isinstance(v, (int, float)) for v in values):
            table[column] = np.asarray(values, dtype=float)
    table["error"] = np.asarray(raw["errors"], dtype=str)
    return table
