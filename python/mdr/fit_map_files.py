"""Fits of instrument map files: `mdr.fit_map(case, "map.jpk-force-map")` fits every curve of the file with the same
C++ as ``mdr fit CASE --map FILE --out DIR`` (mdr/fit/map_fit.hpp) and gives the rows of its map.csv."""

from __future__ import annotations

import csv
import os
import pathlib
import tempfile
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import numpy as np

from . import _mdr
from ._toml import to_toml

#: File endings of instrument maps (and single curves) that `fit_map` reads itself (docs/instrument-files.md).
INSTRUMENT_ENDINGS = (".jpk-force-map", ".jpk-qi-data", ".jpk-qi-series", ".jpk-force", ".spm", ".ibw", ".zip")

#: The columns of map.csv that hold text; every other column is a number.
TEXT_COLUMNS = ("status", "flags", "failure")


def is_instrument_file(path: Any) -> bool:
    """Whether `path` is a path whose ending names an instrument file that `fit_map` fits with `fit_map_file`."""
    return isinstance(path, (str, os.PathLike)) and os.fspath(path).lower().endswith(INSTRUMENT_ENDINGS)


@dataclass
class MapTable:
    """The per-pixel outputs of a map fit: the columns of map.csv (docs/instrument-to-map.md) and the grid.

    ``columns`` maps each column of map.csv to an array, one entry per pixel in the file's order: numbers as
    float64 (NaN where the pixel has no value, e.g. a failed pixel's parameters), ``status``, ``flags`` and
    ``failure`` as str. ``grid`` is (columns, rows) and ``size`` the map's edge lengths (x, y) in the case's length
    unit ((0, 0) for a file that is not a map)."""

    columns: dict[str, np.ndarray]
    grid: tuple[int, int]
    size: tuple[float, float]


def _read_table(path: pathlib.Path) -> dict[str, np.ndarray]:
    with open(path, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    names = list(rows[0].keys()) if rows else []
    columns = {}
    for name in names:
        values = [row[name] for row in rows]
        if name in TEXT_COLUMNS:
            columns[name] = np.array(values, dtype=object)
        else:
            columns[name] = np.array([float(value) if value != "" else np.nan for value in values])
    return columns


def fit_map_file(case: str | os.PathLike | Mapping[str, Any], path: str | os.PathLike, *,
                 out: str | os.PathLike | None = None,
                 progress: Callable[[int, int], None] | None = None) -> MapTable:
    """Fits every curve of the instrument file `path` alone with the fit case `case`, as ``mdr fit CASE --map``.

    The case's one ``[[fit.data]]`` table names no column (an instrument file's: ``segments``, ``until``,
    ``window``); its ``file`` and ``curve`` are replaced by each curve of `path`. A pixel that fails is a row with
    ``status`` "failed" and its ``failure``; the map goes on. With `out` (a file path), map.csv is written there.

    Raises
    ------
    ValueError
        For a bad case or file (the command line's message, ``key = value: rule``).
    """
    if isinstance(case, Mapping):
        text, source, directory = to_toml(case), "case", os.getcwd()
    else:
        source = os.fspath(case)
        with open(source, encoding="utf-8") as handle:
            text = handle.read()
        directory = os.path.dirname(os.path.abspath(source))
    with tempfile.TemporaryDirectory() as scratch:
        table = pathlib.Path(out) if out is not None else pathlib.Path(scratch) / "map.csv"
        columns, rows, size_x, size_y = _mdr._fit_map_file(text, source, directory, os.path.abspath(path),
                                                           os.fspath(table), progress)
        return MapTable(_read_table(table), (columns, rows), (size_x, size_y))
