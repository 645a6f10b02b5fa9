"""mdr: viscoelastic contact mechanics by the Method of Dimensionality Reduction (Popov & Hess).

    import mdr
    result = mdr.run(material=mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1),
                     indenter=mdr.Indenter.sphere(R=0.01),
                     load={"control": "displacement", "history": [[0, 0], [1, 1e-4], [2, 0]]})
    result = mdr.run("examples/default.toml")          # or a case file, or a dict with its structure
    result.history["F"]                                 # numpy arrays keyed by the history.csv columns
    result.summary["max_force"]                         # the summary.json keys
    mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.1).creep(0.1)

`mdr.plot` (figures, matplotlib) and `mdr.maps` are imported on first use.
"""

from __future__ import annotations

import importlib
import math
import os
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _mdr
from ._arrays import real_array
from ._jobs import check_jobs, local_workers
# Every public class of the core (Material, ContactCase, the controls, ...): the names _mdr.__all__ lists (its stub
# _mdr.pyi too), exported below as they are, so that a class bound in python/bindings needs no line here.
from ._mdr import *  # noqa: F401,F403
from ._case_tree import plain_tree
from .curve_maps import map_curves
from .fit_maps import fit_map
from .fitting import FitResult, fit, spread_of_repeats
from .instruments import read_curves

__all__ = ["run", "check", "sweep", "SweepTable", "fit", "FitResult", "spread_of_repeats", "map_curves", "fit_map",
           "Result", "read_curves", "__version__"]
__all__ += _mdr.__all__
__version__ = _mdr.__version__

CaseLike = Union[str, os.PathLike, Mapping[str, Any]]
RunCase = Union[ContactCase, str, os.PathLike, Mapping[str, Any]]
_LAZY_MODULES = ("plot", "maps")


def __getattr__(name: str) -> Any:
    # mdr.plot and mdr.maps import matplotlib; they load on first use (PEP 562), so that `import mdr` neither
    # needs matplotlib nor chooses its backend.
    if name in _LAZY_MODULES:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'mdr' has no attribute {name!r}")


@dataclass
class Result:
    """What a run produced.

    Attributes
    ----------
    history : dict of str to numpy.ndarray
        One array per column of history.csv (``t``, ``d``, ``F``, ``a``; ``v`` for an impact; ``u``, ``Fx``,
        ``c`` with tangential loading), in the case's units.
    summary : dict
        The summary.json object (``max_force``, ``max_depth``, ``steps``, ...).
    profiles : dict of str to numpy.ndarray
        One array per column of profiles.csv (``t``, ``r``, ``p``, ``w``; ``tau`` with tangential loading),
        empty without ``[output] snapshots``.
    description : str
        The one-line description of the case (what ``mdr check`` prints).

    Examples
    --------
    >>> result = mdr.run("examples/default.toml")
    >>> result.history["F"].max() == result.summary["max_force"]
    True
    """

    history: dict[str, np.ndarray]
    summary: dict[str, Any]
    profiles: dict[str, np.ndarray] = field(default_factory=dict)
    description: str = ""


def _case_input(case: CaseLike) -> tuple[Union[str, dict[str, Any]], str]:
    """What the bindings read and the name of the case in messages: a file's TOML text, or a dict as its plain tree
    (no text)."""
    if isinstance(case, Mapping):
        return plain_tree(case), "case"
    if isinstance(case, (str, os.PathLike)):
        path = os.fspath(case)
        try:
            with open(path, encoding="utf-8") as handle:
                return handle.read(), path
        except OSError:
            pass
        _mdr._unreadable_case(path)  # raises the command line's line (mdr::unreadable_file), without the OSError
    raise TypeError(f"case: expected a path or a dict, got {type(case).__name__}")


def _case_of(case: Optional[RunCase], tables: Mapping[str, Any]) -> RunCase:
    """The case of run and check: an mdr.ContactCase, a path or dict, or the tables given as keywords (a dict like
    the file's)."""
    given = {key: value for key, value in tables.items() if value is not None}
    if case is not None and given:
        raise TypeError(f"give a case or its tables ({', '.join(given)}) as keywords, not both")
    if case is not None:
        return case
    if not given:
        raise TypeError("case: give a case file, a dict, or material=..., indenter=..., load=...")
    return given


def _callable_or_none(progress: Any) -> Any:
    if progress is not None and not callable(progress):
        raise TypeError(f"progress: expected a callable or None, got {type(progress).__name__}")
    return progress


def run(case: Optional[RunCase] = None, *, material: Union[Material, Mapping[str, Any], None] = None,
        indenter: Union[Indenter, Mapping[str, Any], None] = None, load: Optional[Mapping[str, Any]] = None,
        numerics: Optional[Mapping[str, Any]] = None, tangential: Optional[Mapping[str, Any]] = None,
        output: Optional[Mapping[str, Any]] = None, title: Optional[str] = None,
        progress: Optional[Callable[[float], Any]] = None,
        observers: Optional[Sequence[Callable[[Step], Any]]] = None) -> Result:
    """Runs a contact case.

    Give either `case` (an ``mdr.ContactCase``, a case file or a dict with its structure) or the case's tables as
    keywords.

    Parameters
    ----------
    case : mdr.ContactCase, str, os.PathLike or dict, optional
        An ``mdr.ContactCase`` (run as it is, without text), a TOML case file (docs/case-format.md) or a dict with
        the same structure; values may be numpy numbers or arrays, ``mdr.Material`` (for ``material``) and
        ``mdr.Indenter`` (for ``indenter``).
    material : mdr.Material or dict, optional
        The half-space: an ``mdr.Material`` or a dict like ``[material]``.
    indenter : mdr.Indenter or dict, optional
        The indenter: an ``mdr.Indenter`` or a dict like ``[indenter]`` (a dict also takes ``mass`` and the
        indenter's own ``material``).
    load : dict, optional
        A dict like ``[load]``: ``control`` and ``history`` (or ``velocity`` for an impact), optional ``end``.
    numerics, tangential, output : dict, optional
        Dicts like ``[numerics]``, ``[tangential]`` and ``[output]``.
    title : str, optional
        The case's title.
    progress : callable, optional
        Called as ``progress(fraction)`` with the fraction of the simulated time done (0 to 1; in an impact, whose
        end is not known beforehand, 0.9 at its expected end of contact) as the run goes on, and with 1.0 at its
        end. An exception it raises stops the run and propagates.
    observers : sequence of callables, optional
        Each is called as ``observer(step)`` with an ``mdr.Step`` (time, depth, force, contact radius, ...) for
        every state of the run, the initial one first, in time order. A true return value ends the run with that
        state; an exception stops the run and propagates. On a ``[layer]`` too (docs/python.md).

    Returns
    -------
    Result
        The history, summary, profiles and description of the run.

    Raises
    ------
    mdr.InvalidInput
        (a ValueError) for bad input, with the command line's message ``key = value: rule``.
    TypeError
        For a case that is neither a path nor a dict, or a case given both ways.

    Examples
    --------
    >>> result = mdr.run(material=mdr.Material.standard(G_inf=1e6, G1=3e6, tau1=0.2),
    ...                  indenter=mdr.Indenter.sphere(R=0.01),
    ...                  load={"control": "displacement", "history": [[0.0, 0.0], [1.0, 1e-4], [2.0, 0.0]]})
    >>> round(result.summary["max_force"], 3)
    0.958
    >>> mdr.run("examples/default.toml").summary["control"]
    'displacement'
    """
    progress = _callable_or_none(progress)
    given = _case_of(case, dict(title=title, material=material, indenter=indenter, load=load, tangential=tangential,
                                output=output, numerics=numerics))
    if isinstance(given, ContactCase):
        raw = _mdr._run_contact_case(given, progress, observers)
    else:
        case_input, source = _case_input(given)
        raw = _mdr._run_case(case_input, source, progress, observers)
    return Result(history=dict(raw["history"]), summary=raw["summary"],
                  profiles=dict(raw["profiles"]), description=raw["description"])


def check(case: Optional[RunCase] = None, *, material: Union[Material, Mapping[str, Any], None] = None,
          indenter: Union[Indenter, Mapping[str, Any], None] = None, load: Optional[Mapping[str, Any]] = None,
          numerics: Optional[Mapping[str, Any]] = None, tangential: Optional[Mapping[str, Any]] = None,
          output: Optional[Mapping[str, Any]] = None, title: Optional[str] = None) -> str:
    """Validates a case without running it, like ``mdr check``.

    Parameters
    ----------
    case : mdr.ContactCase, str, os.PathLike or dict, optional
        An ``mdr.ContactCase``, a case file or a dict with its structure, as for `run`.
    material, indenter, load, numerics, tangential, output, title
        The case's tables as keywords, as for `run`.

    Returns
    -------
    str
        The one-line description of the case.

    Raises
    ------
    mdr.InvalidInput
        (a ValueError) for bad input, with the command line's message.

    Examples
    --------
    >>> mdr.check(material={"model": "elastic", "G": 1e6}, indenter={"shape": "sphere", "R": 0.01},
    ...           load={"control": "force", "history": [[0.0, 0.0], [1.0, 0.1]]})  # doctest: +ELLIPSIS
    'sphere R = 0.01 on an elastic half-space elastic (G = 1000000 Pa) (G(0+) = 1e+06 Pa, ...), force control, ...'
    """
    given = _case_of(case, dict(title=title, material=material, indenter=indenter, load=load, tangential=tangential,
                                output=output, numerics=numerics))
    if isinstance(given, ContactCase):
        return _mdr._check_contact_case(given)
    case_input, source = _case_input(given)
    return _mdr._check_case(case_input, source)


def _axis_spec(key: str, values: Any) -> Union[str, tuple[str, list[float]]]:
    """An axis of the bindings: a `--vary` spec for a grid given as text, else the key and its numbers as floats."""
    if isinstance(values, str):
        return f"{key}={values}"
    array = real_array(values, f"vary[{key!r}]")
    if array.size == 0:
        raise ValueError(f"vary[{key!r}]: an empty array; must be a 1-D list of numbers or 'START:STOP:COUNT[:log]'")
    return key, array.tolist()


class SweepTable(dict):
    """The table of a sweep: a dict of numpy arrays (column name -> one value a row); `batch` tells how it ran
    (mdr.distributed.MapOutcome without the outputs: scheduler, workers, tasks, retried, seconds; None for a local
    sweep); `threads` the threads of a local sweep, min(jobs, cores, points) (None for a scheduled one)."""

    batch: Any = None
    threads: Optional[int] = None


def sweep(case: Optional[RunCase] = None, vary: Optional[Mapping[str, Any]] = None, jobs: Optional[int] = None,
          progress: Optional[Callable[[int, int], Any]] = None, scheduler: Any = None, *,
          material: Union[Material, Mapping[str, Any], None] = None,
          indenter: Union[Indenter, Mapping[str, Any], None] = None, load: Optional[Mapping[str, Any]] = None,
          numerics: Optional[Mapping[str, Any]] = None, tangential: Optional[Mapping[str, Any]] = None,
          output: Optional[Mapping[str, Any]] = None, title: Optional[str] = None) -> SweepTable:
    """Runs a case over the cartesian product of grids of numeric keys, like ``mdr sweep``.

    Give either `case` (an ``mdr.ContactCase``, a case file or a dict with its structure) or the case's tables as
    keywords, as for `run`.

    Parameters
    ----------
    case : mdr.ContactCase, str, os.PathLike or dict, optional
        An ``mdr.ContactCase`` (each point built from its objects, without text: a key sets a typed value on a copy
        of the part it names, and a part no key names is used as it is, so that an ``mdr.ConvertedMaterial`` keeps
        its series and certificate; docs/python.md), a case file or a dict with its structure.
    vary : dict of str to sequence or str
        ``{dotted key: values}``: a 1-D sequence of numbers or ``"START:STOP:COUNT[:log]"``; the last key varies
        fastest. A key names a number of the case, also inside an array (``"load.history[1][1]"``: the value of
        the second history point), by the names of its case file (an ``mdr.ContactCase``: of the file or dict it
        would be read from).
    jobs : int, optional
        Threads (default: all cores); min(jobs, cores, points) run (``.threads`` of the table), and more than the
        cores warns (RuntimeWarning).
    progress : callable, optional
        Called as ``progress(done, total)`` with the number of points finished, as points finish and at least
        every 0.2 s. An exception it raises stops the sweep and propagates (local sweeps).
    scheduler : str or distributed.Client, optional
        A Dask scheduler address ``"tcp://HOST:PORT"`` or a client: the points run in chunks on its workers
        (docs/distributed.md), with the same rows bit for bit; an ``mdr.ContactCase`` travels to the workers
        pickled with its typed parts (no text), each point set on its objects as locally.
    material, indenter, load, numerics, tangential, output, title
        The case's tables as keywords, as for `run` (``mdr.Material`` and ``mdr.Indenter`` objects or dicts).

    Returns
    -------
    SweepTable
        The table of sweep.csv as a dict of numpy arrays, its columns in its order: the varied keys, every numeric
        key (a number or a count, not a flag) of any point's summary.json (the union; nan where a point failed or
        lacks the key) and ``error`` (the failure message, ""
        where the point ran); ``.batch`` tells how a scheduled sweep ran (None for a local one).

    Raises
    ------
    mdr.InvalidInput
        For a bad case or a key that is not a number of the case.
    ValueError
        For `jobs` not an integer >= 1 (a bool included), or given with a scheduler.
    TypeError
        For a case given both ways, or none.

    Examples
    --------
    >>> table = mdr.sweep("examples/default.toml", {"material.G_inf": [0.5e6, 1e6, 2e6]}, jobs=2)
    >>> table["max_force"].shape
    (3,)

    The tables as keywords, and the peak depth of the history varied:

    >>> table = mdr.sweep(material=mdr.Material.elastic(G=1e6), indenter=mdr.Indenter.sphere(R=0.01),
    ...                   load={"control": "displacement", "history": [[0.0, 0.0], [1.0, 1e-4]]},
    ...                   vary={"load.history[1][1]": [1e-4, 4e-4]}, jobs=1)
    >>> ratio = table["max_force"][1] / table["max_force"][0]   # Hertz: F grows as d^(3/2)
    >>> round(ratio, 2)
    8.0
    """
    if not isinstance(vary, Mapping) or not vary:
        raise TypeError("vary: expected a non-empty dict {key: values}")
    check_jobs(jobs, scheduler)
    progress = _callable_or_none(progress)
    given = _case_of(case, dict(title=title, material=material, indenter=indenter, load=load, tangential=tangential,
                                output=output, numerics=numerics))
    specs = [_axis_spec(key, values) for key, values in vary.items()]
    batch = threads = None
    if scheduler is None:
        threads = local_workers(jobs, _mdr._sweep_size(specs))
        if isinstance(given, ContactCase):
            raw = _mdr._sweep_contact_case(given, specs, threads, progress)
        else:
            case_input, source = _case_input(given)
            raw = _mdr._sweep_case(case_input, source, specs, threads, progress)
    else:
        from . import distributed

        case_input, source = (given, "") if isinstance(given, ContactCase) else _case_input(given)
        _, points, batch = distributed.sweep_rows(case_input, source, specs, scheduler)
        summaries = [row[0] for row in batch.outputs]
        raw = {"points": points, "summaries": summaries, "errors": [row[1] for row in batch.outputs],
               "columns": _mdr._sweep_columns(summaries)}
        batch.outputs = []
    summaries = raw["summaries"]
    table = SweepTable()
    table.batch = batch
    table.threads = threads
    points = np.asarray(raw["points"], dtype=float).reshape(len(summaries), len(specs))
    for i, key in enumerate(vary):
        table[key] = points[:, i]
    for column in raw["columns"]:  # the union of the rows' numeric keys, as sweep.csv has it (io::sweep_columns)
        table[column] = np.asarray([s.get(column, math.nan) for s in summaries], dtype=float)
    table["error"] = np.asarray(raw["errors"], dtype=str)
    return table
