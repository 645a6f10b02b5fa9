"""Fits of instrument map files: `mdr.fit_map(case, "map.jpk-force-map")` fits every curve of the file with the same
C++ as ``mdr fit CASE --map FILE --out DIR`` (mdr/fitcase/map_fit.hpp) and gives the rows of its map.csv, taken from
the C++ result directly (mdr::fitcase::MapRows)."""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import numpy as np

from . import _mdr
from ._case_tree import plain_tree
from ._jobs import check_jobs, local_workers

#: File endings of instrument maps (and single curves) that `fit_map` reads itself (docs/instrument-files.md): the
#: C++ readers' own list (mdr::instrument::supported_extensions).
INSTRUMENT_ENDINGS = tuple(_mdr._instrument_endings)


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


def _columns(rows: list[dict[str, Any]], names: list[str]) -> dict[str, np.ndarray]:
    """The columns `names` of the rows (dicts) as arrays: a column that holds text as str ("" where a row lacks it),
    any other as float64 (NaN where a row lacks it or holds None)."""
    columns = {}
    for name in names:
        values = [row.get(name) for row in rows]
        if any(isinstance(value, str) for value in values):
            columns[name] = np.array(["" if value is None else value for value in values], dtype=object)
        else:
            columns[name] = np.array([np.nan if value is None else value for value in values], dtype=float)
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
    rows, names, write_tables, grid, units = _mdr._fit_map_file(case_input, source, directory, map_file,
                                                                lambda curves: local_workers(jobs, curves), progress)
    table = MapTable(_columns(rows, names), grid[:2], grid[2:], units)
    if result_directory is not None:
        def write_files(temporary: str) -> None:
            write_tables(temporary)
            if figures:
                from .map_figures import map_heat_maps
                for name, figure in map_heat_maps(temporary):
                    figure.savefig(os.path.join(temporary, f"map_{name}.png"), dpi=120)

        result_directory.write(write_files)
    return table
