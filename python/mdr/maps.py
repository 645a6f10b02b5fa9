"""The restitution map (handbook eq. 39, 40 and Fig. 3): the dimensionless groups of a sphere hitting a standard
solid, and the figure of e over p1 for several p2 from a `mdr sweep` over tau1 and G1."""

from __future__ import annotations

import math
import tomllib
from typing import Any, Mapping

import numpy as np


def sphere_density(mass: float, radius: float) -> float:
    """rho = 3 m / (4 pi R^3) of a homogeneous sphere."""
    return 3.0 * mass / (4.0 * math.pi * radius**3)


def p1_scale(case: Mapping[str, Any]) -> float:
    """p1 / tau1 = v0^(1/5) (G_inf/rho)^(2/5) / R (eq. 40) for a standard-solid impact case (dict of the TOML)."""
    material, indenter, load = case["material"], case["indenter"], case["load"]
    rho = sphere_density(indenter["mass"], indenter["R"])
    return load["velocity"] ** 0.2 * (material["G_inf"] / rho) ** 0.4 / indenter["R"]


def read_case(path: str) -> dict[str, Any]:
    """A case file as a dict."""
    with open(path, "rb") as handle:
        return tomllib.load(handle)


def restitution_map(sweep: Mapping[str, np.ndarray], case: Mapping[str, Any], axes=None):
    """e over p1 (log axis) for each p2 = G1/G_inf of a sweep over material.tau1 and material.G1."""
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
