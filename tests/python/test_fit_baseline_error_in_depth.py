"""A curve fitted in depth (`fit.fitted = "depth"`) is driven by its force less the baseline; the held baseline's
error (from the rows before contact) is not propagated into its errors, and the curve's flags say so (issue 24).
Before, baseline_error was reported and silently left out. The data: the Kelvin-Voigt creep of a sphere under a force
step F at t0 (eq. 33: a^3 = (3 F R / (16 G)) (1 - exp(-(t - t0) G / eta)), d = a^2 / R), after 50 rows of approach
at zero force, plus white force noise."""

from __future__ import annotations

import numpy as np

import mdr

R = 1.0e-5      # m
G, ETA, F = 1.0e6, 3.0e5, 2.0e-4   # Pa, Pa s, N
NOISE = 1.0e-6  # N


def creep_after_an_approach(seed: int = 0) -> dict:
    t = np.linspace(0.0, 2.5, 251)
    held = t >= 0.5
    radius = (3.0 * F * R / (16.0 * G) * (1.0 - np.exp(-np.clip(t - 0.5, 0.0, None) * G / ETA))) ** (1.0 / 3.0)
    depth = np.where(held, radius ** 2 / R, -1.0e-7 * (0.5 - t))
    force = np.where(held, F, 0.0) + np.random.default_rng(seed).normal(0.0, NOISE, t.size)
    return {"time": t, "depth": depth, "force": force}


CASE = {"material": {"model": "kelvin_voigt", "G": 3.0e5, "eta": 1.0e6}, "indenter": {"shape": "sphere", "R": R},
        "fit": {"free": ["material.G", "material.eta"], "fitted": "depth", "contact_point": "fixed"}}


def test_a_depth_fitted_curve_says_its_baseline_error_is_not_in_its_errors():
    curve = mdr.fit(CASE, data=[creep_after_an_approach()]).summary["curves"][0]
    assert curve["baseline_error"] > 0.0
    said = [flag for flag in curve["flags"] if flag.startswith("the baseline's error")]
    assert len(said) == 1 and "not included in the errors" in said[0] and "fitted in depth" in said[0], curve["flags"]


def test_a_fixed_baseline_has_no_error_to_leave_out():
    case = {**CASE, "fit": {**CASE["fit"], "baseline": "fixed"}}
    curve = mdr.fit(case, data=[creep_after_an_approach()]).summary["curves"][0]
    assert not [flag for flag in curve["flags"] if flag.startswith("the baseline's error")], curve["flags"]
