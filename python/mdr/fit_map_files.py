"""Fits of instrument map files: `mdr.fit_map(case, "map.jpk-force-map")` fits every curve of the file with the same
C++ as ``mdr fit CASE --map FILE --out DIR`` (mdr/fit/map_fit.hpp) and gives the rows of its map.csv."""

from __future__ import annotations

import csv
import json
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
    units: str = "SI"


def write_summary(path: str | os.PathLike, table: MapTable, source: str, length_unit: str,
                  length_size: float) -> None:
    """Writes map.json as ``mdr fit --map`` does: the grid, its size and pixel size in the case's length unit."""
    columns, rows = table.grid
    failed = int(np.count_nonzero(table.columns["status"] == "failed")) if "status" in table.columns else 0
    summary = {"source": source, "units": table.units, "length_unit": length_unit, "length_size": length_size,
               "columns": columns, "rows": rows, "size": list(table.size),
               "pixel_size": [table.size[0] / columns if columns else 0.0, table.size[1] / rows if rows else 0.0],
               "pixels": len(next(iter(table.columns.values()), [])), "failed": failed}
    with open(path, "w", encoding="utf-8") as handle:
        json.dump(summary, handle, indent=1)
        handle.write("\n")


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
                 out: str | os.PathLike | None = None, figures: bool = True,
                 progress: Callable[[int, int], None] | None = None) -> MapTable:
    """Fits every curve of the instrument file `path` alone with the fit case `case`, as ``mdr fit CASE --map``.

    The case's one ``[[fit.data]]`` table names no column (an instrument file's: ``segments``, ``until``,
    ``window``); its ``file`` and ``curve`` are replaced by each curve of `path`. A pixel that fails is a row with
    ``status`` "failed" and its ``failure``; the map goes on. With `out` (a directory, created if need be),
    map.csv and map.json are written there as by the command line, and with `figures` the heat maps
    (``map_KEY.png``, mdr.map_figures).

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
        folder = pathlib.Path(out) if out is not None else pathlib.Path(scratch)
        folder.mkdir(parents=True, exist_ok=True)
        map_file = os.path.abspath(path)
        columns, rows, size_x, size_y, units, length_unit, length_size = _mdr._fit_map_file(
            text, source, directory, map_file, os.fspath(folder / "map.csv"), progress)
        table = MapTable(_read_table(folder / "map.csv"), (columns, rows), (size_x, size_y), units)
        if out is not None:
            write_summary(folder / "map.json", table, map_file, length_unit, length_size)
            if figures:
                from .map_figures import map_heat_maps
                for name, figure in map_heat_maps(os.fspath(folder)):
                    figure.savefig(folder / f"map_{name}.png", dpi=120)
        return table
