"""mdr's elastic layer (docs/theory.md section 4c: the Fredholm equation over the contact) against an independent
finite-element model of the layer (layer_fe.py: axisymmetric mixed u-p Taylor-Hood elements, exactly
incompressible, a frictionless sphere by an active set): force and contact radius of a sphere at a contact radius of
about 1.4 (bonded) and 1.25 (sliding) thicknesses, where the layer doubles (bonded) the half-space's force, with the
finite elements' own mesh convergence."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from layer_fe import LayerFE, graded

R, DEPTH, THICKNESS = 100.0, 0.01, 1.0   # sphere radius, depth, layer thickness (any unit); G = 1


def mdr_sphere(run_mdr, workdir, interface):
    case = workdir / f"{interface}.toml"
    case.write_text(f"""
[material]
model = "elastic"
G = 1.0
[indenter]
shape = "sphere"
R = {R}
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, {DEPTH}]]
[numerics]
time_step = 0.5
[layer]
thickness = {THICKNESS}
interface = "{interface}"
""", encoding="utf-8")
    result = run_mdr("run", case, "--out", workdir / interface)
    assert result.returncode == 0, result.stderr
    with open(workdir / interface / "history.csv", newline="", encoding="utf-8") as handle:
        last = list(csv.DictReader(handle))[-1]
    return float(last["F"]), float(last["a"])


def fe_sphere(interface, elements):
    """`elements` quadratic elements across the thickness and over the first two thicknesses of the surface (then
    25 growing ones to r = 20 h, where u = 0): returns force, contact radius (a surface node's) and node spacing."""
    radii = graded(20.0 * THICKNESS, 2.0 * THICKNESS, elements, 25)
    heights = np.linspace(0.0, THICKNESS, elements + 1)
    force, radius = LayerFE(radii, heights, interface).sphere(R, DEPTH)
    return force, radius, THICKNESS / elements


def test_bonded_sphere_converges_to_mdr(run_mdr, workdir):
    # Measured: FE/mdr - 1 = -1.6e-3, -5.8e-4, -3.2e-4 for 10, 20, 40 elements (the contact radius on the nodes).
    force, radius = mdr_sphere(run_mdr, workdir, "bonded")
    errors = []
    for elements in (10, 20, 40):
        fe_force, fe_radius, spacing = fe_sphere("bonded", elements)
        errors.append(abs(fe_force / force - 1.0))
        assert abs(fe_radius - radius) <= spacing, elements
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 5e-4


def test_sliding_sphere_meets_mdr(run_mdr, workdir):
    # Measured: FE/mdr - 1 = 5.9e-3 with 20 elements: the active set puts the edge on a node, and the consistent
    # nodal reactions of quadratic elements judge the last node's contact only to about a node's spacing.
    force, radius = mdr_sphere(run_mdr, workdir, "sliding")
    fe_force, fe_radius, spacing = fe_sphere("sliding", 20)
    assert fe_force == pytest.approx(force, rel=1e-2)
    assert abs(fe_radius - radius) <= spacing
