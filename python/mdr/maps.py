"""The restitution map (handbook eq. 39, 40 and Fig. 3): the dimensionless groups of a sphere hitting a standard
solid, and the figure of e over p1 for several p2 from a `mdr sweep` over tau1 and G1."""

from __future__ import annotations

import math
import tomllib
from typing import Any, Mapping

import numpy as np


def sphere_density(mass: float, radius: float) -> float:
    """The density of a homogeneous sphere, rho = 3 m / (4 pi R^3).

    Parameters
    ----------
    mass : float
        Its mass m.
    radius : float
        Its radius R.

    Returns
    -------
    float
        rho.

    Examples
    --------
    >>> round(mdr.maps.sphere_density(mass=4.0 / 3.0 * math.pi, radius=1.0), 12)
    1.0
    """
    return 3.0 * mass / (4.0 * math.pi * radius**3)


def p1_scale(case: Mapping[str, Any]) -> float:
    """The factor of eq. (40) that turns tau1 into p1: p1 / tau1 = v0^(1/5) (G_inf / rho)^(2/5) / R.

    Parameters
    ----------
    case : dict
        A standard-solid impact case as a dict (``material.G_inf``, ``indenter.mass``, ``indenter.R``,
        ``load.velocity``).

    Returns
    -------
    float
        p1 / tau1.

    Examples
    --------
    >>> case = {"material": {"G_inf": 1e6}, "indenter": {"R": 0.01, "mass": 3.27e-2}, "load": {"velocity": 0.1}}
    >>> round(mdr.maps.p1_scale(case), 3)
    439.558
    """
    material, indenter, load = case["material"], case["indenter"], case["load"]
    rho = sphere_density(indenter["mass"], indenter["R"])
    return load["velocity"] ** 0.2 * (material["G_inf"] / rho) ** 0.4 / indenter["R"]


def read_case(path: str) -> dict[str, Any]:
    """Reads a case file into a dict (no validation: use mdr.check for that).

    Parameters
    ----------
    path : str
        The TOML case file.

    Returns
    -------
    dict
        Its tables and keys.

    Examples
    --------
    >>> mdr.maps.read_case("examples/default.toml")["indenter"]["shape"]
    'sphere'
    """
    with open(path, "rb") as handle:
        return tomllib.load(handle)


def restitution_map(sweep: Mapping[str, np.ndarray], case: Mapping[str, Any], axes=None):
    """The restitution map (Fig. 3): e over p1 (log axis), one line per p2 = G1 / G_inf.

    Parameters
    ----------
    sweep : dict of str to numpy.ndarray
        A sweep over ``material.tau1`` and ``material.G1`` with the column ``restitution`` (``mdr.sweep`` or
        sweep.csv).
    case : dict
        The swept case as a dict (for `p1_scale` and G_inf).
    axes : matplotlib.axes.Axes, optional
        Where to draw; a new figure by default.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> case = mdr.maps.read_case("examples/restitution_map.toml")            # doctest: +SKIP
    >>> table = mdr.sweep(case, {"material.tau1": "1e-5:1e-2:7:log", "material.G1": [1e6, 3e6]})  # doctest: +SKIP
    >>> axes = mdr.maps.restitution_map(table, case)                         # doctest: +SKIP
    """
    import matplotlib.pyplot as plt

    axes = axes or plt.figure(figsize=(6.5, 4.5)).add_subplot()
    scale = p1_scale(case)
    g_inf = case["material"]["G_inf"]
    for g1 in np.unique(sweep["material.G1"]):
        rows = (sweep["material.G1"] == g1) & np.isfinite(sweep["restitution"])
        order = np.argsort(sweep["material.tau1"][rows])
        axes.semilogx(sweep["material.tau1"][rows][order] * scale, sweep["restitution"][rows][order],
                      label=f"p2 = {g1 / g_inf:g}")
    axes.set(xlabel="p1 = tau1 v0^(1/5) (G_inf/rho)^(2/5) / R", ylabel="coefficient of restitution e",
             title="Restitution map of a sphere on a standard solid (Fig. 3)", ylim=(0.0, 1.02))
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(title="p2 = G1 / G_inf")
    return axes
