"""A per-curve function for the tests of mdr.map_curves: the closed-form least-squares fit of an elastic sphere
(Hertz) to one force-depth curve. Workers import it by name (the tests put this folder on their PYTHONPATH), as
they would import mdr.fit from the installed package."""

from __future__ import annotations

import math

import numpy as np

R = 1.0e-5  # m, the tip radius of the synthetic maps


def hertz_force(G: float, depth: np.ndarray, radius: float = R) -> np.ndarray:
    """F = (16/3) G sqrt(R) d^(3/2): eq. (35) F = 16 G a^3 / (3R) with eq. (31) a^2 = R d (incompressible)."""
    return 16.0 / 3.0 * G * math.sqrt(radius) * np.clip(depth, 0.0, None) ** 1.5


def fit_hertz(curve, radius: float = R) -> dict[str, float]:
    """G and its standard error from F = c G w with w = d^(3/2), c = (16/3) sqrt(R) (eq. 31, 35), by linear least
    squares in closed form: G = sum(F w) / (c sum(w^2)), var(G) = s^2 / (c^2 sum(w^2)), s^2 = sum(r^2)/(n - 1).
    `curve` is (nt, 2) [depth, force] or a dict with "depth" and "force"."""
    if isinstance(curve, dict):
        depth, force = np.asarray(curve["depth"]), np.asarray(curve["force"])
    else:
        depth, force = curve[:, 0], curve[:, 1]
    if not (np.all(np.isfinite(depth)) and np.all(np.isfinite(force))):
        raise ValueError("the curve has values that are not finite")
    w = np.clip(depth, 0.0, None) ** 1.5
    c = 16.0 / 3.0 * math.sqrt(radius)
    ww = float(np.dot(w, w))
    if ww == 0.0:
        raise ValueError("the curve never indents the sample")
    G = float(np.dot(force, w)) / (c * ww)
    residual = force - c * G * w
    s2 = float(np.dot(residual, residual)) / max(len(force) - 1, 1)
    return {"G": G, "G_stderr": math.sqrt(s2 / (c * c * ww))}


def slow_fit_hertz(curve, seconds: float = 0.02) -> dict[str, float]:
    """fit_hertz after a pause: a per-curve function as slow as a real fit, for the tests of Ctrl-C."""
    import time

    time.sleep(seconds)
    return fit_hertz(curve)
