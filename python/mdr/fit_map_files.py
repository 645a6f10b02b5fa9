"""Fits of instrument map files: `mdr.fit_map(case, "map.jpk-force-map")` fits every curve of the file with the same
C++ as ``mdr fit CASE --map FILE --out DIR`` (mdr/fitcase/map_fit.hpp) and gives the rows of its map.csv."""

from __future__ import annotations

import csv
import os
import pathlib
import shutil
import tempfile
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import numpy as np

from . import _mdr
from ._case_tree import plain_tree
from ._jobs import check_jobs, local_workers

#: File endings of instrument maps (and single curves) that `fit_map` reads itself (docs/instrument-files.md): the
#: C++ readers' own list (mdr::instrument::supported_extensions).
INSTRUMENT_ENDINGS = tuple(_mdr._instrument_endings)

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
                 jobs: int | None = None, out: str | os.PathLike | None = None, figures: bool = True,
                 progress: Callable[[int, int], None] | None = None) -> MapTable:
    """Fits every curve of the instrument file `path` alone with the fit case `case`, as ``mdr fit CASE --map``.

    The case's one ``[[fit.data]]`` table names no column (an instrument file's: ``segments``, ``until``,
    ``window``); its ``file`` and ``curve`` are replaced by each curve of `path`. A pixel that fails is a row with
    ``status`` "failed" and its ``failure``; the map goes on. The pixels are fitted on min(`jobs`, cores, curves)
    threads (`jobs` None: every core; mdr._jobs.local_workers), the rows the same bit for bit whatever `jobs`;
    ``progress(done, total)`` is called at least every 0.2 s. With `out`, map.csv and map.json are written there as
    by the command line, and with `figures` the heat maps (``map_KEY.png``, mdr.map_figures); `out` follows the
    rules of ``--out`` (docs/cli.md): a new directory or one mdr wrote, checked before the fit and written whole
    or not at all.

    Raises
    ------
    ValueError
        For a bad case or file, `jobs` not an integer >= 1, or an `out` that is not mdr's (the command line's
        message, ``key = value: rule``).
    """
    check_jobs(jobs)
    if isinstance(case, Mapping):
        case_input, source, directory = plain_tree(case), "case", os.getcwd()
        inputs = []
    else:
        source = os.fspath(case)
        with open(source, encoding="utf-8") as handle:
            case_input = handle.read()
        directory = os.path.dirname(os.path.abspath(source))
        inputs = [source]
    map_file = os.path.abspath(path)
    # Checked before the fit: an output folder that is not mdr's is refused, and it is written whole or not at all.
    result_directory = None if out is None else _mdr._ResultDirectory(os.fspath(out), "out", inputs + [map_file])
    with tempfile.TemporaryDirectory() as scratch:
        folder = pathlib.Path(scratch)
        columns, rows, size_x, size_y, units = _mdr._fit_map_file(case_input, source, directory, map_file,
                                                                 os.fspath(folder),
                                                                 lambda curves: local_workers(jobs, curves), progress)
        table = MapTable(_read_table(folder / "map.csv"), (columns, rows), (size_x, size_y), units)
        if result_directory is not None:
            def write_files(temporary: str) -> None:
                for name in ("map.csv", "map.json"):
                    shutil.copyfile(folder / name, os.path.join(temporary, name))
                if figures:
                    from .map_figures import map_heat_maps
                    for name, figure in map_heat_maps(temporary):
                        figure.savefig(os.path.join(temporary, f"map_{name}.png"), dpi=120)

            result_directory.write(write_files)
        return table
