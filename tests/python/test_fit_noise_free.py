"""Noise-free data (values computed in closed form): the estimated noise is at round-off level, and a residual measured
against it says nothing (issue 24). Before, a depth-fitted creep curve reported "misfit: residual RMS 3.3e-08 is
6.35e+09 x the noise 5.196e-18" and status "converged, misfit"; a noise-free cone curve reported a residual_to_noise
against a noise at round-off. Now the noise is 0, there is no ratio (null) and no misfit from it, and the
curve's flag says what its residual is. The data are made here in closed form, never by mdr."""

from __future__ import annotations

import numpy as np

import mdr

R = 1.0e-5      # sphere radius [m]


def kelvin_voigt_creep(force_noise: float) -> dict:
    """A force step F at t0 = 0.5 s after 50 rows of approach; the depth of the Kelvin-Voigt creep in closed form
    (eq. 33: a^3 = (3 F R / (16 G)) (1 - exp(-(t - t0) G / eta)), d = a^2 / R), the force with white noise."""
    G, eta, F = 1.0e6, 3.0e5, 2.0e-4
    t = np.linspace(0.0, 2.5, 251)
    held = t >= 0.5
    radius = (3.0 * F * R / (16.0 * G) * (1.0 - np.exp(-np.clip(t - 0.5, 0.0, None) * G / eta))) ** (1.0 / 3.0)
    depth = np.where(held, radius ** 2 / R, -1.0e-7 * (0.5 - t))
    force = np.where(held, F, 0.0) + np.random.default_rng(0).normal(0.0, force_noise, t.size)
    return {"time": t, "depth": depth, "force": force}


def noise_free_flag(curve: dict) -> str:
    flags = [flag for flag in curve["flags"] if flag.startswith("noise-free")]
    assert len(flags) == 1, curve["flags"]
    return flags[0]


def test_noise_free_depths_driven_by_a_noisy_force_are_no_misfit_against_round_off():
    # The depth is exact; the driving force carries noise 1e-6 N (0.5 % of the step), which the model carries into
    # the depth: a residual of ~0.6 % of the depth that no noise of the depth explains, and that noise-free data
    # cannot tell from a misfit. The errors are the residual's own scatter: G within a few of them of the truth.
    case = {"material": {"model": "kelvin_voigt", "G": 3.0e5, "eta": 1.0e6}, "indenter": {"shape": "sphere", "R": R},
            "fit": {"free": ["material.G", "material.eta"], "fitted": "depth", "contact_point": "fixed"}}
    data = kelvin_voigt_creep(1.0e-6)
    summary = mdr.fit(case, data=[data]).summary
    curve = summary["curves"][0]
    assert curve["noise"] == 0.0 and summary["noise"] == 0.0
    assert summary["residual_to_noise"] is None
    assert summary["misfit"] is False and summary["status"] == "converged"
    assert not [flag for flag in curve["flags"] if flag.startswith("misfit")], curve["flags"]
    flag = noise_free_flag(curve)
    assert "measured depth's noise is at round-off" in flag and "above the model's accuracy" in flag, flag
    largest = np.max(np.abs(data["depth"]))
    assert 1e-3 * largest < curve["rms_residual"] < 1e-2 * largest
    G, error = summary["parameters"]["material.G"], summary["standard_errors"]["material.G"]
    assert 0.0 < error < 0.01 * G and abs(G - 1.0e6) < 4.0 * error


def test_a_noise_free_cone_curve_is_reproduced_and_says_so():
    # Force and depth exact: 50 rows of approach at zero force, then F = (2/pi) E* tan(alpha) d^2 (Sneddon's cone,
    # half-angle alpha = 45 degrees, E* = 4 G for nu = 0.5) over a depth ramp. The model reproduces it to its own
    # accuracy; the flag says so, with no ratio against the round-off.
    G = 2.0e3
    t = np.linspace(-0.25, 1.0, 251)
    depth = 1.0e-6 * t
    force = 2.0 / np.pi * 4.0 * G * np.clip(depth, 0.0, None) ** 2
    case = {"material": {"model": "elastic", "G": 1.0e3}, "indenter": {"shape": "cone", "half_angle_deg": 45.0},
            "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
    summary = mdr.fit(case, data=[{"time": t, "depth": depth, "force": force}]).summary
    curve = summary["curves"][0]
    assert curve["noise"] == 0.0 and summary["residual_to_noise"] is None
    assert summary["misfit"] is False and summary["status"] == "converged"
    flag = noise_free_flag(curve)
    assert "measured force's noise is at round-off" in flag and "the model reproduces the data" in flag, flag
    assert abs(summary["parameters"]["material.G"] / G - 1.0) < 1e-6


def test_a_noise_free_curve_beside_a_noisy_one_leaves_the_ratio_to_the_noisy_one():
    # The fit's residual_to_noise is the RMS residual over the RMS noise of the curves that have a noise: a noise-free
    # curve has no noise to measure its residual against. Before, its residual entered the numerator and its noise 0
    # the denominator: 44.3 for a fit whose one noisy curve has 31.3 (sqrt(2) too large with two curves of 201 rows).
    case = {"material": {"model": "kelvin_voigt", "G": 3.0e5, "eta": 1.0e6}, "indenter": {"shape": "sphere", "R": R},
            "fit": {"free": ["material.G", "material.eta"], "fitted": "depth", "contact_point": "fixed"}}
    noise_free = kelvin_voigt_creep(1.0e-6)
    noisy = kelvin_voigt_creep(1.0e-6)
    noisy["depth"] = noisy["depth"] + np.random.default_rng(5).normal(0.0, 1.0e-9, noisy["depth"].size)
    summary = mdr.fit(case, data=[noise_free, noisy]).summary
    free_entry, noisy_entry = summary["curves"]
    assert free_entry["noise"] == 0.0 and noisy_entry["noise"] > 0.0
    assert free_entry["rms_residual"] > 10.0 * noisy_entry["noise"]  # a residual that would move the ratio
    ratio = noisy_entry["rms_residual"] / noisy_entry["noise"]
    assert abs(summary["residual_to_noise"] / ratio - 1.0) < 1e-12, (summary["residual_to_noise"], ratio)
