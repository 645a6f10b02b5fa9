"""A cone with a flat tip on an elastic bonded layer (docs/theory.md, "Layers", eq. L3 to L6) against a reference
written here: k(eta) by scipy's Fourier quadrature of eq. L1 and a cubic spline, eq. L3 by the Nystroem method on
numpy's Gauss-Legendre nodes, 200 on the flat end [0, b] and 200 on the flank [b, a] mapped by x = b + (a - b) u^2
(g grows as sqrt(x - b) beyond the kink, eq. 9), converged to ~1e-12; the contact radius of each depth by brentq on
the force-free edge q(a) = 0 (eq. L6). It shares no code with mdr. Measured: 4.4e-9 of the peak force (before the
layer's Gauss rule was split at the kink: 4.2e-3)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

import mdr

H = 2.0e-6                          # bonded incompressible layer [m]
B = 2.0e-6                          # radius of the flat tip [m]
TANGENT = math.tan(math.radians(20.0))
R_MAX = 50.0e-6
G = 1.0e3                           # elastic shear modulus [Pa]; E* = 4 G
DEPTHS = [0.05e-6, 0.2e-6, 0.5e-6, 1.0e-6]


def one_minus_compliance(u):
    """1 - L(u) of a bonded incompressible layer (eq. L1 with kappa = 1), exp(-2u) factored out above and below."""
    e2 = np.exp(-2.0 * u)
    return (2.0 * e2 * e2 + (2.0 + 4.0 * u + 4.0 * u * u) * e2) / (1.0 + e2 * e2 + (2.0 + 4.0 * u * u) * e2)


@pytest.fixture(scope="module")
def kernel():
    """k(eta) = int_0^inf (1 - L(u)) cos(u eta) du (eq. L4) for eta up to 2 * 8 b / H."""
    eta = np.arange(0.0, 16.0 * B / H + 0.02, 0.005)
    values = [quad(one_minus_compliance, 0.0, 40.0, weight="cos", wvar=e, limit=200)[0] for e in eta]
    return CubicSpline(eta, values)


def equivalent(x):
    """g(x) = tan(theta) x arccos(b/x) beyond the flat tip, 0 on it (eq. 9 of f = (r - b) tan(theta))."""
    return np.where(x > B, TANGENT * x * np.arccos(np.minimum(B / np.maximum(x, B), 1.0)), 0.0)


def at_radius(kernel, a, nodes=200):
    """(depth, force / E*) of the contact radius a > b: q = d q_d - q_g, q(a) = 0."""
    u, w = np.polynomial.legendre.leggauss(nodes)
    u, w = 0.5 * (u + 1.0), 0.5 * w
    x = np.concatenate([B * u, B + (a - B) * u * u])
    weights = np.concatenate([B * w, 2.0 * (a - B) * u * w])
    coupling = lambda y, s: (kernel(np.abs(y - s) / H) + kernel((y + s) / H)) / (H * math.pi)
    matrix = np.eye(x.size) - coupling(x[:, None], x[None, :]) * weights[None, :]
    q_d = np.linalg.solve(matrix, np.ones_like(x))
    q_g = np.linalg.solve(matrix, equivalent(x))
    edge = coupling(a, x) * weights
    depth = (equivalent(np.array(a)) + edge @ q_g) / (1.0 + edge @ q_d)
    return depth, 2.0 * weights @ (depth * q_d - q_g)


def test_the_reference_is_the_closed_form_on_a_very_thick_layer():
    """With K = 0 the MDR's truncated cone: d = tan(theta) a arccos(b/a), F/E* = tan(theta) (a^2 arccos(b/a) +
    b sqrt(a^2 - b^2))."""
    zero = lambda eta: 0.0 * np.asarray(eta)
    a = 3.0 * B
    depth, force = at_radius(zero, a)
    assert depth == pytest.approx(TANGENT * a * math.acos(B / a), rel=1e-12)
    assert force == pytest.approx(TANGENT * (a * a * math.acos(B / a) + B * math.sqrt(a * a - B * B)), rel=1e-12)


def test_a_flat_tipped_cone_on_an_elastic_layer_meets_the_reference(kernel):
    case = {"material": {"model": "elastic", "G": G},
            "indenter": {"shape": "profile", "r": [0.0, B, R_MAX], "f": [0.0, 0.0, (R_MAX - B) * TANGENT],
                         "interpolation": "linear"},
            "load": {"control": "displacement", "history": [[0.0, 0.0], [1.0, DEPTHS[-1]]]},
            "layer": {"thickness": H, "interface": "bonded"}}
    result = mdr.run(case)
    t, d, F = result.history["t"], result.history["d"], result.history["F"]
    peak = float(np.max(F))
    for depth in DEPTHS:
        row = int(np.argmin(np.abs(d - depth)))
        assert d[row] == pytest.approx(depth, rel=1e-9)
        a = brentq(lambda r: at_radius(kernel, r)[0] - d[row], B * (1.0 + 1e-12), 8.0 * B, xtol=1e-16, rtol=1e-14)
        reference = 4.0 * G * at_radius(kernel, a)[1]
        assert abs(F[row] - reference) < 1e-5 * peak, (depth, F[row], reference)
        assert result.history["a"][row] == pytest.approx(a, rel=1e-5)
