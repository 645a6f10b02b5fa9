"""Maps over stacks of curves (force maps of AFM: one curve a pixel): `map_curves(per_curve, stack)` runs a picklable
per-curve function over every pixel, locally or on a Dask cluster (mdr.distributed), and collects parameter maps,
the status of every pixel and the reason of every failure; `CurveMap.write` stores arrays and heat maps.

The hook for fits: `mdr.fit_map` is `map_curves` with a per-curve function that fits one curve with `mdr.fit` and
returns {parameter: value, parameter + "_stderr": standard error, ...}; a fit that fails raises, and its reason is
kept for the pixel; a fit that stops without converging returns its values in a `MapRow` that says why it stopped
(`MapRow.stopped`), and the pixel keeps them as NOT_CONVERGED. docs/distributed.md shows the contract with a
closed-form fit.

Stacks (`open_stack`):
- a numpy array (ny, nx, nt) or (ny, nx, nt, channels): the curve of pixel (row, col) is `array[row, col]`;
- an HDF5 file `PATH.h5` (`dataset=`, default "curves"), the same layout, read in slices (needs h5py);
- a directory with `positions.csv` (columns `file,row,col`) and one CSV file a listed curve (a header of column
  names, then numbers): the curve is a dict {column name: numpy array}; pixels without a file are "no curve".
The curves are read here, in chunks, and travel with the tasks: workers need no shared file system.
"""

from __future__ import annotations

import csv
import json
import math
import os
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping, Sequence

import numpy as np

from . import distributed
from ._jobs import check_jobs

#: Pixel status codes of `CurveMap.status` (status.npy): a result; no values (the per-curve function raised); no
#: curve; the values where a fit stopped without converging (not a result: `MapRow.stopped` says why).
OK, FAILED, NO_CURVE, NOT_CONVERGED = 0, 1, 2, 3
STATUS_NAMES = {OK: "ok", FAILED: "failed", NO_CURVE: "no curve", NOT_CONVERGED: "not converged"}


class ArrayStack:
    """Curves in an array (ny, nx, nt[, channels]), or anything indexable like one (an h5py dataset)."""

    def __init__(self, array: Any, source: str = "array", inputs: Sequence[str] = (), handle: Any = None):
        if len(array.shape) < 3:
            raise ValueError(f"{source}: expected an array (ny, nx, nt[, channels]), got shape {tuple(array.shape)}")
        self.array, self.source, self.inputs, self._handle = array, source, list(inputs), handle
        self.shape = (int(array.shape[0]), int(array.shape[1]))

    def close(self) -> None:
        """Closes the file it read from, if it opened one."""
        if self._handle is not None:
            self._handle.close()

    def read(self, start: int, stop: int) -> list:
        """The curves of the pixels start..stop-1 (row-major), read a block of rows at a time."""
        nx = self.shape[1]
        first_row, last_row = start // nx, (stop - 1) // nx
        block = np.asarray(self.array[first_row:last_row + 1])
        return [block[i // nx - first_row, i % nx] for i in range(start, stop)]


class DirectoryStack:
    """Curves in CSV files listed with their grid positions in `DIRECTORY/positions.csv` (file,row,col)."""

    def __init__(self, directory: str):
        self.source = directory
        index = os.path.join(directory, "positions.csv")
        self.inputs = [index]  # the result directory may be neither this directory nor a parent of it
        try:
            with open(index, newline="", encoding="utf-8") as handle:
                rows = list(csv.DictReader(handle))
        except OSError as error:
            raise ValueError(f"{directory}: a directory of curves needs positions.csv (file,row,col): {error}") from None
        self.files: dict[tuple[int, int], str] = {}
        for line, row in enumerate(rows, start=2):
            try:
                position = (int(row["row"]), int(row["col"]))
                name = row["file"]
            except (KeyError, TypeError, ValueError):
                raise ValueError(f"{index}:{line}: expected file,row,col with integer row and col") from None
            if min(position) < 0:
                raise ValueError(f"{index}:{line}: row and col must be >= 0")
            if position in self.files:
                raise ValueError(f"{index}:{line}: position {position} listed twice")
            self.files[position] = os.path.join(directory, name)
        if not self.files:
            raise ValueError(f"{index}: lists no curve")
        self.shape = (max(r for r, _ in self.files) + 1, max(c for _, c in self.files) + 1)

    def read(self, start: int, stop: int) -> list:
        nx = self.shape[1]
        return [self._curve(self.files.get(divmod(i, nx))) for i in range(start, stop)]

    def close(self) -> None:
        pass

    @staticmethod
    def _curve(path: str | None) -> dict[str, np.ndarray] | None:
        if path is None:
            return None
        with open(path, newline="", encoding="utf-8") as handle:
            names = next(csv.reader(handle))
            values = np.loadtxt(handle, delimiter=",", ndmin=2)
        if values.shape[1] != len(names):
            raise ValueError(f"{path}: {len(names)} column names, {values.shape[1]} columns of numbers")
        return {name.strip(): values[:, i] for i, name in enumerate(names)}


def open_stack(source: Any, dataset: str = "curves"):
    """A stack of curves from an array (numpy, or indexable like one: an h5py dataset, a memmap), an HDF5 file
    (dataset `dataset`) or a directory with positions.csv.

    Parameters
    ----------
    source : array-like, str or os.PathLike
        An array (ny, nx, nt) or (ny, nx, nt, channels), the curve of pixel (row, col) being ``source[row, col]``;
        an HDF5 file ``*.h5`` or ``*.hdf5`` holding such an array (needs h5py); or a directory with
        ``positions.csv`` (columns ``file,row,col``) and one CSV file a listed curve. A stack (this function's, or
        anything with its ``shape``, ``read``, ``inputs``, ``source`` and ``close``) is returned as it is.
    dataset : str, optional
        The dataset of an HDF5 file (default ``"curves"``).

    Returns
    -------
    ArrayStack or DirectoryStack
        ``shape`` (ny, nx), ``read(start, stop)`` (the curves of the pixels start..stop-1, row-major; a directory's
        curve is a dict {column name: numpy array}, None where no file is listed) and ``close()`` (closes an HDF5
        file that it opened).

    Raises
    ------
    ValueError
        For an array of fewer than 3 dimensions, a missing or malformed positions.csv, an HDF5 file without the
        dataset, or a path that is neither.

    Examples
    --------
    >>> stack = mdr.curve_maps.open_stack(np.zeros((2, 3, 50)))
    >>> stack.shape, stack.read(4, 6)[1].shape     # pixels (1, 1) and (1, 2)
    ((2, 3), (50,))
    >>> stack = mdr.curve_maps.open_stack("force-map.h5", dataset="forces")   # doctest: +SKIP
    """
    if isinstance(source, (ArrayStack, DirectoryStack)) or (callable(getattr(source, "read", None))
                                                           and hasattr(source, "inputs")):
        return source  # a stack: shape, read, inputs, source and close
    if isinstance(source, (str, os.PathLike)):
        path = os.fspath(source)
        if os.path.isdir(path):
            return DirectoryStack(path)
        if path.endswith((".h5", ".hdf5")):
            try:
                import h5py  # python3-h5py, optional
            except ImportError:
                raise ValueError(f"{path}: reading HDF5 needs h5py (Debian: python3-h5py)") from None
            handle = h5py.File(path, "r")
            if dataset not in handle:
                names = ", ".join(handle)
                handle.close()
                raise ValueError(f"{path}: no dataset '{dataset}' (it has: {names})")
            return ArrayStack(handle[dataset], f"{path}:{dataset}", inputs=[path], handle=handle)
        raise ValueError(f"{path}: expected a directory with positions.csv or an HDF5 file (.h5, .hdf5)")
    if not isinstance(source, np.ndarray) and hasattr(source, "shape") and hasattr(source, "__getitem__"):
        return ArrayStack(source, type(source).__name__)  # read in slices, never whole
    return ArrayStack(np.asarray(source))


class MapRow(dict):
    """The values of one pixel, {name: number or text}, with the SI unit of each (`units`, as map.json's
    ``column_units`` states them: "" for no quantity, "1" for a ratio), the unit system of the numbers
    (`unit_system`) and, for the values where a fit stopped without converging, why it stopped (`stopped`, the
    fit's status; "" for a result): what `mdr.fit_maps.fit_curve` returns. `map_curves` keeps a row with a
    `stopped` as a NOT_CONVERGED pixel with its values and that reason. A per-curve function may return a plain
    dict instead (its values without units, in SI; a result)."""

    def __init__(self, values: Mapping[str, Any], units: Mapping[str, str], unit_system: str = "SI",
                 stopped: str = ""):
        super().__init__(values)
        self.units, self.unit_system, self.stopped = dict(units), unit_system, stopped


@dataclass
class CurveMap:
    """Per-pixel results: `values[name]` (ny, nx) arrays, float (nan where a pixel has no value) or, for a value that
    is text, str ("" where a pixel has none), `status` (ny, nx) codes (OK, FAILED, NO_CURVE, NOT_CONVERGED: values
    where the fit stopped, no result), `reasons` (ny, nx) strings ("" where ok or no curve; why a pixel failed or
    why its fit stopped), `batch` how the map ran (mdr.distributed.MapOutcome without outputs), `units` the SI unit
    of each value ("" where unknown), `unit_system` that of the numbers and `source` what the stack was read from."""

    values: dict[str, np.ndarray]
    status: np.ndarray
    reasons: np.ndarray
    batch: distributed.MapOutcome | None = None
    units: dict[str, str] = field(default_factory=dict)
    unit_system: str = "SI"
    source: str = ""

    def summary(self) -> dict[str, Any]:
        """map.json as a dict: the layout of the command line's map.json (``mdr fit CASE --map FILE``), written by
        the same C++: the grid's ``columns`` and ``rows`` (nx, ny; ``size`` and ``pixel_size`` 0: a stack states no
        positions), ``pixels``, ``failed`` (pixels without values: failed or without a curve; a pixel that did not
        converge has its values, as a row of map.csv does), ``source``, the unit system and ``column_units`` (the
        unit of every value). How the map ran is ``batch``."""
        return json.loads(self._summary_json())

    def _summary_json(self) -> str:
        from . import _mdr

        ny, nx = self.status.shape
        names = list(self.values)
        return _mdr._map_summary_json(int(nx), int(ny), self.unit_system, self.source, names,
                                      [self.units.get(name, "") for name in names], int(self.status.size),
                                      int(np.count_nonzero((self.status == FAILED) | (self.status == NO_CURVE))))

    def write_files(self, directory: str, figures: bool = True) -> list[str]:
        """Writes NAME.npy per value that is a number, texts.csv (row,col and the values that are text, if any),
        status.npy (the codes), failures.csv (row,col,status,reason of every pixel that is not OK: "failed", "no
        curve", "not converged"), map.json (`summary`) and, with `figures`, a heat map NAME.png per value that is a
        number and no pixel's place (mdr.map_figures.NOT_DRAWN; `heat_map` with the pixels that are no results
        marked) into an existing directory; returns the file names."""
        from .map_figures import NOT_DRAWN

        names = []
        texts = [name for name, array in self.values.items() if array.dtype.kind != "f"]
        for name in self.values:  # every check before the first file, so that a refusal writes nothing
            if name not in texts and (name in ("", ".", "..", "status") or "/" in name or "\\" in name
                                      or os.sep in name):
                raise ValueError(f"values[{name!r}]: must be a plain file name (no '/' or '\\', not '.' or '..') "
                                 "other than status (the codes' status.npy): write_files names NAME.npy by a value "
                                 "that is a number")
        for name, array in self.values.items():
            if name not in texts:
                np.save(os.path.join(directory, f"{name}.npy"), array)
                names.append(f"{name}.npy")
        if texts:  # e.g. a fit's status, flags and failure: text, one line a pixel
            with open(os.path.join(directory, "texts.csv"), "w", newline="", encoding="utf-8") as handle:
                writer = csv.writer(handle)
                writer.writerow(["row", "col", *texts])
                for row, col in np.ndindex(self.status.shape):
                    writer.writerow([row, col, *(self.values[name][row, col] for name in texts)])
            names.append("texts.csv")
        np.save(os.path.join(directory, "status.npy"), self.status)
        with open(os.path.join(directory, "failures.csv"), "w", newline="", encoding="utf-8") as handle:
            writer = csv.writer(handle)
            writer.writerow(["row", "col", "status", "reason"])
            for row, col in zip(*np.nonzero(self.status != OK)):
                writer.writerow([row, col, STATUS_NAMES[int(self.status[row, col])], self.reasons[row, col]])
        with open(os.path.join(directory, "map.json"), "w", encoding="utf-8") as handle:
            handle.write(self._summary_json())
        names += ["status.npy", "failures.csv", "map.json"]
        if figures:
            for name, array in self.values.items():
                if name in NOT_DRAWN or array.dtype.kind != "f":
                    continue
                heat_map(array, name, self.status).savefig(os.path.join(directory, f"{name}.png"), dpi=120)
                names.append(f"{name}.png")
        return names


def heat_map(values: np.ndarray, name: str, status: np.ndarray | None = None):
    """A figure of a (ny, nx) map (pixels without a value left white), the heat maps of CurveMap.write_files.

    With `status`, the pixels that are no results are marked as on the heat maps of ``mdr fit --map``
    (mdr.map_figures.mark_pixels) and counted in the title where there are any: a FAILED pixel crossed in red, a
    NOT_CONVERGED one (drawn with the values where its fit stopped) with an orange plus.

    Parameters
    ----------
    values : numpy.ndarray
        The (ny, nx) map; nan where a pixel has no value.
    name : str
        The value's name, for the colour bar and the title.
    status : numpy.ndarray, optional
        The (ny, nx) codes of the pixels (`CurveMap.status`).

    Returns
    -------
    matplotlib.figure.Figure
        Made without pyplot (no GUI backend; safe in any thread): save it with ``savefig``.

    Examples
    --------
    >>> values = np.array([[1.0, 2.0, 3.0], [4.0, np.nan, 6.0]])
    >>> figure = mdr.curve_maps.heat_map(values, "material.G")
    >>> figure.axes[0].get_title()
    'material.G (5 of 6 pixels)'
    >>> from mdr.curve_maps import OK, FAILED, NOT_CONVERGED
    >>> status = np.array([[OK, OK, NOT_CONVERGED], [OK, FAILED, OK]])
    >>> figure = mdr.curve_maps.heat_map(values, "material.G", status)
    >>> figure.axes[0].get_title()
    'material.G (5 of 6 pixels, 1 failed, 1 not converged)'
    >>> [(marks.get_label(), marks.get_offsets().tolist()) for marks in figure.axes[0].collections]   # (col, row)
    [('failed', [[1.0, 1.0]]), ('not converged', [[2.0, 0.0]])]
    """
    from matplotlib.figure import Figure  # no pyplot: no GUI backend, safe in any thread
    from .map_figures import mark_pixels

    figure = Figure(figsize=(5.5, 4.5))
    axes = figure.add_subplot()
    image = axes.imshow(np.ma.masked_invalid(values), origin="upper", interpolation="nearest", cmap="viridis")
    figure.colorbar(image, ax=axes, label=name)
    counts = ""
    if status is not None:
        rows, cols = np.indices(status.shape)
        failed, not_converged = status == FAILED, status == NOT_CONVERGED
        mark_pixels(axes, cols.ravel(), rows.ravel(), failed.ravel(), not_converged.ravel())
        counts = "".join(f", {np.count_nonzero(where)} {label}" for where, label in ((failed, "failed"),
                                                                                     (not_converged, "not converged"))
                         if where.any())
    axes.set(xlabel="col", ylabel="row", title=f"{name} ({np.count_nonzero(np.isfinite(values))} of {values.size} "
                                                   f"pixels{counts})")
    figure.tight_layout()
    return figure


def map_curves(per_curve: Callable[[Any], Mapping[str, float]], stack: Any, *, scheduler: Any = None,
               jobs: int | None = None, out: str | os.PathLike | None = None, figures: bool = True,
               progress: Callable[[int, int], None] | None = None) -> CurveMap:
    """Runs `per_curve(curve)` for every pixel of `stack` and collects a map per value, the status of every pixel
    and the reason of every failure.

    A pixel whose function raises is FAILED with the reason ("ExceptionType: message") and does not stop the map; one
    whose function returns a `MapRow` with a `stopped` (a fit that did not converge: `mdr.fit_maps.fit_curve`) is
    NOT_CONVERGED with its values and that reason. The pixels run locally on `jobs` processes, or with `scheduler`
    on the workers of a Dask cluster, with the same values bit for bit (docs/distributed.md).

    Parameters
    ----------
    per_curve : callable
        ``per_curve(curve)`` returns a dict {name: number or text} or a `MapRow` for one pixel's curve (as
        `open_stack` reads it). It must be picklable: a function of an installed module (``functools.partial`` for
        settings), or one defined in ``__main__`` with a scheduler.
    stack : array-like, str or os.PathLike
        The curves: anything `open_stack` takes (an array (ny, nx, nt[, channels]), an HDF5 file, a directory with
        positions.csv), or a stack it returned.
    scheduler : str or distributed.Client, optional
        A Dask scheduler address ``"tcp://HOST:PORT"`` or a client; the pixels then run in chunks on its workers.
    jobs : int, optional
        Local processes (default: all cores); min(jobs, cores, pixels) start (``batch.workers``, ``workers`` of
        map.json), and more than the cores warns (RuntimeWarning); not with a scheduler.
    out : str or os.PathLike, optional
        A result directory for the files of ``CurveMap.write_files``, with the rules of ``--out``: checked before
        any computing, written whole or not at all.
    figures : bool, optional
        With `out`: a heat map NAME.png per value too (default True).
    progress : callable, optional
        Called as ``progress(done, total)`` with the number of pixels finished, at least every 0.2 s.

    Returns
    -------
    CurveMap
        ``values[name]`` (ny, nx) per name the function returned (nan where a pixel failed or has no curve),
        ``status`` (``OK``, ``FAILED``, ``NO_CURVE``, ``NOT_CONVERGED``), ``reasons`` ("" where ok or no curve) and
        ``batch`` (how the map ran).

    Examples
    --------
    Hertz force curves F = (16/3) G sqrt(R) d^(3/2) of a 1 x 2 map, each fitted by ``mdr.fit_maps.fit_curve`` (a
    function of the package, so picklable; ``mdr.fit_map`` does the same in one call):

    >>> import functools
    >>> t = np.linspace(0.0, 1.0, 51)
    >>> d = 1e-5 * t
    >>> forces = np.stack([16.0 / 3.0 * G * math.sqrt(1e-3) * d ** 1.5 for G in (1e6, 2e6)])[None]   # (1, 2, 51)
    >>> case = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
    ...         "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
    >>> per_curve = functools.partial(mdr.fit_maps.fit_curve, case=case, time=t, depth=d)
    >>> result = mdr.map_curves(per_curve, forces, jobs=1)
    >>> np.round(result.values["material.G"] / 1e6, 4), result.status
    (array([[1., 2.]]), array([[0, 0]], dtype=int8))
    """
    check_jobs(jobs, scheduler)
    opened = open_stack(stack)
    try:
        directory = None
        if out is not None:
            from . import _mdr

            directory = _mdr._ResultDirectory(os.fspath(out), "out", opened.inputs)
        ny, nx = opened.shape
        results, errors, batch = distributed.map_items(
            _Guarded(per_curve), _LazyCurves(opened), scheduler=scheduler, jobs=jobs, progress=progress)
    finally:
        if opened is not stack:
            opened.close()
    batch.outputs = []
    names: list[str] = []
    units: dict[str, str] = {}
    unit_system = "SI"
    for result in results:
        if result is None:
            continue
        values_of, units_of, unit_system, _ = result
        units.update(units_of)
        for name in values_of:
            if name not in names:
                names.append(name)
    texts = {name for result in results if result for name, value in result[0].items() if isinstance(value, str)}
    values = {name: np.full((ny, nx), "", dtype=object) if name in texts else np.full((ny, nx), math.nan)
              for name in names}
    status = np.full((ny, nx), OK, dtype=np.int8)
    reasons = np.full((ny, nx), "", dtype=object)
    for index, (result, error) in enumerate(zip(results, errors)):
        row, col = divmod(index, nx)
        if error:
            status[row, col] = NO_CURVE if error == _NO_CURVE else FAILED
            reasons[row, col] = "" if error == _NO_CURVE else error
            continue
        values_of, _, _, stopped = result
        if stopped:
            status[row, col], reasons[row, col] = NOT_CONVERGED, stopped
        for name, value in values_of.items():
            values[name][row, col] = value
    values = {name: array.astype(str) if name in texts else array for name, array in values.items()}
    curve_map = CurveMap(values=values, status=status, reasons=reasons.astype(str), batch=batch, units=units,
                         unit_system=unit_system, source=str(opened.source))
    if directory is not None:
        directory.write(lambda temporary: curve_map.write_files(temporary, figures))
    return curve_map


_NO_CURVE = "NoCurve: no curve at this position"


class NoCurve(Exception):
    """A pixel without a curve (a directory stack lists no file for it)."""

    pass


class _Guarded:
    """The per-curve function, with the checks of its output (a mapping of names to numbers or texts): its values,
    units, unit system and why its fit stopped short ("" for a result)."""

    def __init__(self, per_curve: Callable[[Any], Mapping[str, float]]):
        self.per_curve = per_curve

    def __call__(self, curve: Any) -> tuple[dict[str, float | str], dict[str, str], str, str]:
        if curve is None:
            raise NoCurve("no curve at this position")
        result = self.per_curve(curve)
        if not isinstance(result, Mapping):
            raise TypeError(f"the per-curve function returned {type(result).__name__}, not a dict of numbers")
        values = {str(name): value if isinstance(value, str) else math.nan if value is None else float(value)
                  for name, value in result.items()}
        if isinstance(result, MapRow):
            return values, result.units, result.unit_system, str(result.stopped)
        return values, {}, "SI", ""


class _LazyCurves(Sequence):
    """The pixels of a stack as a sequence whose slices read the curves (mdr.distributed reads chunk by chunk)."""

    def __init__(self, stack: Any):
        self.stack = stack

    def __len__(self) -> int:
        return self.stack.shape[0] * self.stack.shape[1]

    def __getitem__(self, index):
        if isinstance(index, slice):
            start, stop, _ = index.indices(len(self))
            return self.stack.read(start, stop)
        return self.stack.read(index, index + 1)[0]
