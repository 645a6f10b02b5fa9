"""mdr's elastic layer (docs/theory.md section 4c: the Fredholm equation over the contact) against an independent
finite-element model of the layer (layer_fe.py: axisymmetric mixed u-p Taylor-Hood elements, exactly
incompressible, a frictionless sphere by an active set): force and contact radius of a sphere at a contact radius of
about 1.4 (bonded) and 1.25 (sliding) thicknesses, where the layer doubles (bonded) the half-space's force, with the
finite elements' own mesh convergence; and the surface under a uniform pressure against the layer's compliance L(u)
(eq. L1), of which mdr's kernel is made."""

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


def compliance_defect_bonded_incompressible(u):
    """1 - L(u) of eq. L1 with kappa = 1 (nu = 0.5), written with exp(-2u) (docs/theory.md section 4c)."""
    e = np.exp(-2.0 * u)
    return (2.0 * e * e + (2.0 + 4.0 * u + 4.0 * u * u) * e) / (1.0 + e * e + (2.0 + 4.0 * u * u) * e)


def surface_displacement_reference(r, radius, pressure):
    """w(r) = (2/E*) int P(xi) L(xi h) J0(xi r) dxi for a uniform pressure on r < c, P = p c J1(xi c)/xi, E* = 4 G:
    the half-space part in closed form at r = 0 (int J1(x)/x dx = 1), else by quadrature; the layer's part decays as
    exp(-2 xi h)."""
    from scipy.integrate import quad
    from scipy.special import j0, j1

    half_space = 1.0 if r == 0.0 else quad(lambda x: j1(x * radius) * j0(x * r) / x, 0.0, 2000.0, limit=5000)[0]
    layer = quad(lambda x: j1(x * radius) * compliance_defect_bonded_incompressible(x * THICKNESS) * j0(x * r) / x,
                 0.0, 60.0, limit=2000)[0]
    return 2.0 * pressure * radius / 4.0 * (half_space - layer)


def test_surface_displacement_under_a_pressure_is_the_layers_compliance():
    # The compliance L(u) that mdr's kernel is made of (eq. L1, L4), independently of mdr: the finite elements under
    # a uniform pressure on r < h meet it at r = 0, h/2 and 1.5 h (where the incompressible surface bulges up) to
    # 1.1e-4 of w(0) with 20 elements per thickness and 1.4e-6 with 40 (measured).
    points = (0.0, 0.5, 1.5)
    reference = [surface_displacement_reference(r, 1.0, 1.0) for r in points]
    for elements, tolerance in ((20, 2e-4), (40, 1e-5)):
        model = LayerFE(graded(20.0 * THICKNESS, 2.0 * THICKNESS, elements, 25),
                        np.linspace(0.0, THICKNESS, elements + 1), "bonded")
        surface = model.surface_displacement(lambda r: 1.0 if r < 1.0 else 0.0)
        for r, expected in zip(points, reference):
            assert -np.interp(r, model.r, surface) == pytest.approx(expected, abs=tolerance * reference[0]), r
