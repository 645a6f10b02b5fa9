"""mdr.fit: identify the free parameters of a case from measured curves (the command line's ``mdr fit``)."""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass, field
from typing import Any, Mapping, Sequence, Union

import numpy as np

from . import _mdr
from ._arrays import real_array, real_number
from ._case_tree import plain_tree

CaseLike = Union[str, os.PathLike, Mapping[str, Any]]


@dataclass
class FitResult:
    """The outcome of :func:`fit`.

    Attributes
    ----------
    parameters : dict
        Fitted values keyed by the dotted names of ``fit.free``.
    standard_errors : dict
        One standard deviation of each (NaN where the data cannot determine it).
    status : str
        ``"converged"`` or the reason the fit stopped.
    summary : dict
        Everything ``fit.json`` holds: intervals, correlation, undetermined parameters, per-curve contact point
        and baseline, residual and noise, AIC, BIC, evaluations, wall time.
    curves : list of dict
        Per curve: ``name``, ``kind`` (``"curve"``), ``fitted`` (``"force"`` or ``"depth"``) and the columns of
        curves.csv as numpy arrays: ``t`` (nan where the file records no time), ``measured``, ``model``,
        ``residual`` (model - measured) and ``drive``. Rebound data give one entry per quantity (``kind``
        ``"rebound"``, ``fitted`` ``"restitution"`` or ``"contact_time"``) with ``t`` holding the approach speeds v0
        and ``drive`` nan. Numbers in the case's units (``summary["units"]``).
    fitted_case : str
        fitted.toml's text: the case with the fitted values; its ``[load]`` is the case's own, or the first curve's
        driving history (the contact point removed), as ``mdr fit`` writes it.
    fitted_tree : dict
        The same case as a tree of dicts, lists and numbers, given by the library without text: what ``predict``
        runs (with its ``[load]`` replaced), and what :func:`mdr.run` takes as a case.
    ranking : list of dict
        With ``fit.candidates``: one entry per candidate model in ascending BIC (``name``, ``free_count``,
        ``residual_to_noise``, ``aic``, ``bic``, ``delta_aic``, ``delta_bic``, ``undetermined``,
        ``better_special_case`` (the special case of that model that fits clearly better: this fit is a local
        minimum, flagged in its ``summary["flags"]``; None when none), ``refitted_from`` (the special case from
        whose solution it was fitted once more, the lower fit kept; None when none), ...: the ``candidates`` of
        ranking.json; one entry in spectrum mode); this result is the preferred candidate's.
        Empty for a single model.
    candidates : dict
        With ``fit.candidates`` or ``[fit.spectrum]``: every candidate's own :class:`FitResult`, by name.
    spectrum : dict or None
        In spectrum mode (or for the "spectrum" candidate): ``tau`` (the grid), ``G`` (its moduli) and
        ``G_inf``, in the case's units (SI: s, Pa).
    material : dict
        The identified material on the data's window: ``t``, ``G``, ``J`` and ``omega``, ``storage``, ``loss``
        (numpy arrays), each function with its 95 % band ``*_lower``, ``*_upper`` (NaN where an undetermined
        parameter enters); ``mdr.plot.material_functions(result.material)`` and ``dynamic_moduli`` draw them.
    """

    parameters: dict[str, float]
    standard_errors: dict[str, float]
    status: str
    summary: dict[str, Any]
    curves: list[dict[str, Any]] = field(default_factory=list)
    fitted_case: str = ""
    fitted_tree: dict[str, Any] = field(default_factory=dict)
    ranking: list[dict[str, Any]] = field(default_factory=list)
    candidates: dict[str, "FitResult"] = field(default_factory=dict)
    spectrum: dict[str, Any] | None = None
    material: dict[str, Any] = field(default_factory=dict)

    def predict(self, load: Mapping[str, Any]):
        """Run the fitted material and indenter under another load.

        Parameters
        ----------
        load : dict
            A ``[load]`` table, e.g. ``{"control": "displacement", "history": [[0, 0], [1, 1e-6]]}``.

        Returns
        -------
        mdr.Result
            As :func:`mdr.run` returns it.
        """
        from . import run

        return run({**self.fitted_tree, "load": dict(load)})


def _numbers(summary: Mapping[str, Any], key: str) -> dict[str, float]:
    return {name: (float("nan") if value is None else float(value)) for name, value in summary[key].items()}


def fit(case: CaseLike, data: Mapping[str, Any] | Sequence[Mapping[str, Any]] | None = None) -> FitResult:
    """Fit the free parameters of a case to measured curves, like ``mdr fit CASE --out DIR``.

    Parameters
    ----------
    case : str, os.PathLike or dict
        A case file with a ``[fit]`` table, or a dict of the same structure (docs/case-format.md, "Fitting").
        Paths of ``[[fit.data]]`` are relative to the case file's directory (the working directory for a dict).
    data : dict or sequence of dict, optional
        Curves as arrays instead of ``[[fit.data]]`` (one dict: one curve), every number in the case's units
        (``units``; SI: s, m, N, N/m); arrays of 1 dimension of real numbers (integers and float16/32 are taken as
        float64; bool, complex, text and 2-D arrays are refused naming the key), float64 arrays without a copy:
        each a dict with ``time``, ``depth`` (positive into the body) and ``force``, and optionally
        ``name``; or, for a raw AFM curve, ``piezo`` and ``deflection`` (lengths, both larger = farther from the
        sample) with ``spring_constant`` instead of ``depth`` and ``force`` (force = k x deflection, depth = fall of
        piezo + deflection from the first row, as the case file's AFM columns); the spring constant is in N/m in an
        SI (or nm-nN-s) case, and where the case's force / length is not N/m must state its unit like a case file's
        ``units.spring_constant``: ``"units": {"spring_constant": "N/m"}`` (or ``"nN/um"``, ...), since a bare
        0.019 reads as N/m to an AFM user and as nN/µm to the case. ``fitted`` (``"force"`` or ``"depth"``) sets
        what that curve fits when
        it differs from ``fit.fitted``: a creep curve beside an indentation curve, one material for both.
        ``start`` (``"at_rest"``, the default, or ``"preloaded"``) is the state at the first row, as a case file's
        ``[[fit.data]] start`` (docs/case-format.md): ``"preloaded"`` fits a relaxed preload depth d_0.
        Rebound data (one impact of the case's indenter per approach speed, the same material) are a dict with
        ``"kind": "rebound"``, ``velocity`` (approach speeds v0) and ``restitution`` (e in [0, 1]), and
        optionally ``contact_time`` (T), ``restitution_error`` and ``contact_time_error`` (standard
        deviations: a number or one per impact; estimated from the data's scatter when left out, which needs 3
        impacts), ``mass`` (default: the case's ``indenter.mass``) and ``name``.

    Returns
    -------
    FitResult
        The parameters with their errors; a fit that did not converge still returns, its status says why. With
        ``fit.candidates``, the preferred candidate's result, with ``ranking`` and every candidate's result in
        ``candidates``; with ``[fit.spectrum]``, the spectrum's result with ``spectrum``.

    Raises
    ------
    ValueError
        For bad input, with the command line's message (``key = value: rule``), or an array of other dimensions
        than 1.
    TypeError
        For data that are not dicts of arrays of real numbers (naming the key: ``data[0].force``).

    Examples
    --------
    >>> import numpy as np, mdr
    >>> t = np.linspace(0.0, 1.0, 101)
    >>> d = 1e-5 * t
    >>> F = 16.0 / 3.0 * 1e6 * np.sqrt(1e-3) * d ** 1.5          # Hertz, G = 1 MPa, R = 1 mm
    >>> case = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
    ...         "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
    >>> result = mdr.fit(case, data=[{"time": t, "depth": d, "force": F}])
    >>> round(result.parameters["material.G"] / 1e6, 4)
    1.0
    """
    if isinstance(case, Mapping):
        case_input, source, directory = plain_tree(case), "case", os.getcwd()
    elif isinstance(case, (str, os.PathLike)):
        source = os.fspath(case)
        text = None
        try:
            with open(source, encoding="utf-8") as handle:
                text = handle.read()
        except OSError:
            pass
        if text is None:
            _mdr._unreadable_case(source)  # raises the command line's line (mdr::unreadable_file)
        case_input = text
        directory = os.path.dirname(os.path.abspath(source))
    else:
        raise TypeError(f"case: expected a path or a dict, got {type(case).__name__}")
    curves, rebounds = [], []
    case_units = _case_units(case_input)
    for i, curve in enumerate(_data_list(data)):
        kind = curve.get("kind", "curve")
        if kind == "rebound":
            rebounds.append(_rebound_arrays(curve, i))
        elif kind == "curve":
            curves.append((str(curve.get("name", f"curve{i}")), *_curve_arrays(curve, f"data[{i}]", case_units),
                           str(curve.get("fitted", "")), str(curve.get("start", "")), str(curve.get("until", "")),
                           *_windows(curve, f"data[{i}]")))
        else:
            raise ValueError(f"data[{i}].kind = {kind!r}: one of curve, rebound")
    raw = _mdr._fit_case(case_input, source, directory, curves, rebounds)
    if "candidates" not in raw:
        return _result(raw)
    candidates = {str(entry["name"]): _result(entry) for entry in raw["candidates"]}
    ranking = raw["ranking"]
    preferred = candidates[ranking["preferred"]]
    preferred.ranking = ranking["candidates"]
    preferred.candidates = candidates
    return preferred


def _data_list(data: Any) -> list[Mapping[str, Any]]:
    """mdr.fit's ``data``: a sequence of dicts, or one dict for one curve (or one rebound data set)."""
    if data is None:
        return []
    if isinstance(data, Mapping):
        return [data]
    if isinstance(data, (str, bytes)) or not isinstance(data, Sequence):
        raise TypeError(f"data: a {type(data).__name__}; must be a dict of arrays (one curve) or a list of them")
    for i, item in enumerate(data):
        if not isinstance(item, Mapping):
            raise TypeError(f"data[{i}]: a {type(item).__name__}; must be a dict of arrays (time, depth, force, ...)")
    return list(data)


def _case_units(case: Mapping[str, Any] | str) -> str:
    """The case's ``units`` (SI when absent; SI too for a text that is not TOML, which the fit itself refuses)."""
    if not isinstance(case, Mapping):
        try:
            case = tomllib.loads(case)
        except tomllib.TOMLDecodeError:
            return "SI"
    return str(case.get("units", "SI"))


def _spring_constant(curve: Mapping[str, Any], key: str, case_units: str) -> float:
    """The spring constant of a raw AFM curve in the case's force / length: its unit stated in ``units`` (needed
    unless the case's force / length is N/m; the rule of a case file's ``units.spring_constant``)."""
    value = real_number(curve["spring_constant"], f"{key}.spring_constant")
    units = curve.get("units", {})
    if not isinstance(units, Mapping) or any(name != "spring_constant" for name in units):
        raise ValueError(f"{key}.units = {units!r}: a dict with the one key spring_constant (e.g. \"N/m\")")
    unit = units.get("spring_constant", "")
    if not isinstance(unit, str):
        raise ValueError(f"{key}.units.spring_constant = {unit!r}: must be a string such as \"N/m\"")
    try:
        return value * _mdr._spring_constant_unit(unit, case_units, f"{key}.spring_constant", f"{value:g}",
                                                  f"{key}.units.spring_constant")
    except _mdr.InvalidInput as error:
        raise ValueError(str(error)) from None


_CURVE_KEYS = ("kind", "name", "time", "depth", "force", "piezo", "deflection", "spring_constant", "units",
               "fitted", "start", "until", "window")
_WINDOW_KEYS = ("time", "depth", "force")


def _windows(curve: Mapping[str, Any], key: str) -> tuple:
    """The ``window`` of one curve of mdr.fit's ``data`` as (time, depth, force), each None or (lower, upper); the
    library checks the ends (finite, lower below upper) as a case file's."""
    window = curve.get("window", {})
    if not isinstance(window, Mapping):
        raise TypeError(f"{key}.window: a {type(window).__name__}; must be a dict of time, depth, force")
    unknown = [name for name in window if name not in _WINDOW_KEYS]
    if unknown:
        raise ValueError(f"{key}.window.{unknown[0]} = (given): unknown key; valid keys: {', '.join(_WINDOW_KEYS)}")
    ends = []
    for name in _WINDOW_KEYS:
        pair = window.get(name)
        if pair is not None:
            pair = real_array(pair, f"{key}.window.{name}")
            if pair.shape != (2,):
                raise ValueError(f"{key}.window.{name} = {pair.tolist()!r}: must be [lower, upper]")
            pair = (float(pair[0]), float(pair[1]))
        ends.append(pair)
    return tuple(ends)


def _curve_arrays(curve: Mapping[str, Any], key: str,
                  case_units: str = "SI") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """time, depth and force of one curve of mdr.fit's ``data``: given, or from the raw AFM arrays."""
    unknown = [name for name in curve if name not in _CURVE_KEYS]
    if unknown:
        raise ValueError(f"{key}.{unknown[0]} = (given): unknown key; valid keys: {', '.join(_CURVE_KEYS)}")

    def values(name):
        return real_array(curve[name], f"{key}.{name}")

    afm = [name for name in ("piezo", "deflection", "spring_constant") if name in curve]
    if afm:
        for name in ("depth", "force"):
            if name in curve:
                raise ValueError(f"{key}.{name} = (given): give either depth and force or piezo, deflection and "
                                 "spring_constant, not both")
        for name in ("time", "piezo", "deflection", "spring_constant"):
            if name not in curve:
                raise ValueError(f"{key}.{name} = (missing): a raw AFM curve needs time, piezo, deflection and "
                                 "spring_constant")
        try:
            depth, force = _mdr._afm_depth_and_force(values("piezo"), values("deflection"),
                                                     _spring_constant(curve, key, case_units))
        except _mdr.InvalidInput as error:
            raise ValueError(f"{key}.{error}") from None
        return values("time"), depth, force
    if "units" in curve:  # never ignored: arrays are in the case's units, only a spring constant states its own
        raise ValueError(f"{key}.units = {curve['units']!r}: the arrays are in the case's units; units states only "
                         "the spring_constant of a raw AFM curve (piezo, deflection)")
    missing = [name for name in ("time", "depth", "force") if name not in curve]
    if missing:
        raise ValueError(f"{key}.{missing[0]} = (missing): each curve needs time, depth and force (or the raw AFM "
                         "arrays piezo, deflection and spring_constant)")
    return values("time"), values("depth"), values("force")


_REBOUND_KEYS = ("kind", "name", "velocity", "restitution", "contact_time", "restitution_error",
                 "contact_time_error", "mass")


def _rebound_arrays(data: Mapping[str, Any], i: int) -> tuple:
    """The arrays of one rebound data set of mdr.fit's ``data`` (``kind = "rebound"``), checked by the library."""
    unknown = [name for name in data if name not in _REBOUND_KEYS]
    if unknown:
        raise ValueError(f"data[{i}].{unknown[0]} = (given): unknown key; valid keys: {', '.join(_REBOUND_KEYS)}")
    for name in ("velocity", "restitution"):
        if name not in data:
            raise ValueError(f"data[{i}].{name} = (missing): rebound data need velocity and restitution")

    def values(name):  # the errors: a number or one per impact
        dims = (0, 1) if name.endswith("_error") else (1,)
        return real_array(data.get(name, ()), f"data[{i}].{name}", dims=dims).reshape(-1)

    mass = data.get("mass")
    mass = None if mass is None else real_number(mass, f"data[{i}].mass")
    return (i, str(data.get("name", f"rebound{i}")), mass, values("velocity"),
            values("restitution"), values("contact_time"), values("restitution_error"), values("contact_time_error"))


def _result(raw: Mapping[str, Any]) -> FitResult:
    summary = raw["fit"]
    result = FitResult(parameters=_numbers(summary, "parameters"), standard_errors=_numbers(summary, "standard_errors"),
                       status=summary["status"], summary=summary,
                       curves=[dict(c, kind=s["kind"], fitted=s["fitted"]) for c, s in zip(raw["curves"], summary["curves"])],
                       fitted_case=raw["fitted_case"], fitted_tree=raw["fitted_tree"],
                       material=dict(raw["material"]))
    times = np.asarray(raw.get("relaxation_times", []), dtype=float)
    if times.size:
        result.spectrum = {"tau": times, "G_inf": result.parameters["material.G_inf"],
                           "G": np.array([result.parameters[f"spectrum.G[{j}]"] for j in range(times.size)])}
    return result


def spread_of_repeats(fits: Sequence[FitResult]) -> dict[str, Any]:
    """The spread of repeated records fitted one by one, set against the errors their fits report.

    What ``mdr fit CASE --each A B C`` writes to ``each.json`` (docs/case-format.md): for each free key, over the
    fits that converged, ``count``, ``mean``, ``standard_deviation`` (n - 1), ``standard_error_of_mean``,
    ``typical_error`` (the median of the fits' standard errors), ``error_to_spread`` and ``consistent_range`` (the
    95 % range of that ratio when each value scatters by exactly its error); and ``flags``, one line per key outside
    its range (a misfit the records share, or records that differ by more than their noise). A key's value from a
    fit that leaves it undetermined is no measurement: it is left out of the spread and counted in ``undetermined``.

    Parameters
    ----------
    fits : sequence of FitResult
        Results of :func:`fit` with the same free keys, e.g. one per repeated record of a sample.

    Returns
    -------
    dict
        ``{"spread": {key: {...}}, "flags": [...]}``; NaN values are None.
    """
    fits = list(fits)
    if not fits:
        raise ValueError("fits = []: give at least one mdr.FitResult")
    names = None
    for i, result in enumerate(fits):
        if not isinstance(result, FitResult):
            raise ValueError(f"fits[{i}] = {type(result).__name__}: must be an mdr.FitResult (what mdr.fit returns)")
        if names is None:
            names = list(result.parameters)
        elif list(result.parameters) != names:
            raise ValueError(f"fits[{i}]: its free keys {list(result.parameters)} differ from fits[0]'s {names}: "
                             "the fits of one batch must fit the same keys")
    values = [[float(result.parameters[name]) for name in names] for result in fits]
    errors = [[float(result.standard_errors[name]) for name in names] for result in fits]
    converged = [bool(result.summary.get("converged", False)) for result in fits]
    undetermined = [list(result.summary.get("undetermined") or {}) for result in fits]
    return _mdr._spread_of_repeats(names, values, errors, converged, undetermined)
