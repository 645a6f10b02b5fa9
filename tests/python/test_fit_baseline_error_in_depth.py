"""A curve fitted in depth (`fit.fitted = "depth"`) is driven by its force less the baseline held from the rows before
contact; that baseline's error (sigma / sqrt(n) of n rows) moves every row's driving force at once, and now enters the
covariance through the model's change of depth with the baseline (issue 24). Before, it was left out and only a flag
said so: after a short approach the 95 % intervals of the moduli covered the truth in 33 and 44 of 60 seeds.

The data (numpy, not mdr): the creep of a standard solid (G(t) = G_inf + G1 exp(-t / tau1), creep compliance
J(t) = 1 / G_inf - G1 / (G_inf G0) exp(-t / tau_c), G0 = G_inf + G1, tau_c = tau1 G0 / G_inf) under a sphere, by
Lee and Radok's a^3(t) = 3 R / 16 integral J(t - s) dF(s) (equations.md, eq. (33) with the hereditary integral of the
force, incompressible: E* = 4 G), d = a^2 / R, for a piecewise-linear force (the integral in closed form): a convex
ramp to F_MAX over 0.1 s, then a hold that eases by 10 % over 3 s (a grows throughout: Lee-Radok holds). 15 rows of
approach at zero force before it, white noise on the force and on the depth, in um-nN-s."""

from __future__ import annotations

import numpy as np

import mdr

R = 5.0                                   # um
G_INF, G1, TAU1 = 1.0, 2.0, 0.5           # kPa, kPa, s
F_MAX, RAMP, HOLD, STEP = 2.0, 0.1, 3.0, 5e-3   # nN, s, s, s
FORCE_NOISE, DEPTH_NOISE = 0.03, 0.0012  # nN, um
APPROACH_ROWS = 15


def creep_integral(u: np.ndarray) -> np.ndarray:
    """The integral of J from 0 to u (u >= 0)."""
    g0 = G_INF + G1
    tau_c = TAU1 * g0 / G_INF
    return u / G_INF + G1 * tau_c / (G_INF * g0) * (np.exp(-u / tau_c) - 1.0)


def force_pieces() -> list[tuple[float, float, float]]:
    """(start, end, slope) after the contact: the ramp in four pieces (F ~ t^2 at their ends), then the hold."""
    quarter = RAMP / 4.0
    ramp = [(k * quarter, (k + 1) * quarter, (2 * k + 1) * F_MAX / 16.0 / quarter) for k in range(4)]
    return ramp + [(RAMP, RAMP + HOLD, -0.1 * F_MAX / HOLD)]


def creep_curve(seed: int) -> dict:
    rng = np.random.default_rng(seed)
    contact = APPROACH_ROWS * STEP
    time = np.arange(APPROACH_ROWS + int(round((RAMP + HOLD) / STEP)) + 1) * STEP
    after = np.clip(time - contact, 0.0, None)
    hereditary = np.zeros_like(time)
    force = np.zeros_like(time)
    for start, end, slope in force_pieces():
        since = np.clip(after - start, 0.0, None)
        hereditary += slope * (creep_integral(since) - creep_integral(since - np.minimum(since, end - start)))
        force += slope * np.minimum(since, end - start)
    radius = (3.0 * R * hereditary / 16.0) ** (1.0 / 3.0)
    assert np.all(np.diff(radius) >= 0.0)  # Lee-Radok's condition
    depth = np.where(time > contact, radius ** 2 / R, -0.05 * (contact - time) / contact)
    return {"time": time, "depth": depth + rng.normal(0.0, DEPTH_NOISE, time.size),
            "force": force + rng.normal(0.0, FORCE_NOISE, time.size)}


CASE = {"units": "um-nN-s", "material": {"model": "standard", "G_inf": 0.7, "G1": 1.5, "tau1": 0.3},
        "indenter": {"shape": "sphere", "R": R},
        "fit": {"free": ["material.G_inf", "material.G1", "material.tau1"], "fitted": "depth",
                "contact_point": "fixed"}}


def test_the_creep_curve_is_lee_radok():
    # The closed form against a quadrature of a^3 = 3 R / 16 integral J(t - s) F'(s) ds at one time in the hold.
    g0 = G_INF + G1
    tau_c = TAU1 * g0 / G_INF
    t = 1.0
    s = np.linspace(0.0, t, 400001)
    rate = np.zeros_like(s)
    for start, end, slope in force_pieces():
        rate += np.where((s >= start) & (s < end), slope, 0.0)
    compliance = 1.0 / G_INF - G1 / (G_INF * g0) * np.exp(-(t - s) / tau_c)
    integrand = compliance * rate
    quadrature = np.sum(0.5 * (integrand[1:] + integrand[:-1]) * np.diff(s))
    closed = sum(slope * (creep_integral(np.array(max(t - start, 0.0))) -
                          creep_integral(np.array(max(t - start, 0.0) - min(max(t - start, 0.0), end - start))))
                 for start, end, slope in force_pieces())
    assert abs(closed - quadrature) < 1e-4 * closed


def test_a_depth_fitted_curve_carries_its_baseline_error_and_no_longer_says_it_does_not():
    curve = mdr.fit(CASE, data=[creep_curve(0)]).summary["curves"][0]
    assert curve["baseline_error"] > 0.0
    assert not [flag for flag in curve["flags"] if flag.startswith("the baseline's error")], curve["flags"]


def test_the_95_percent_intervals_of_the_moduli_cover_the_truth_with_the_baseline_error():
    # The baseline from 15 rows before contact is off by sigma / sqrt(15) ~ 0.4 % of F_MAX, the whole creep alike;
    # the rows' own noise averages over 621 rows. Measured: G_inf 58, G1 58 of 60 (before: 33, 44; over 200 seeds
    # 185 and 183). tau1 is no modulus and barely moves with the baseline: its coverage is set by the force noise in
    # the drive (errors in the variables, now in the errors too: test_fit_drive_noise.py).
    seeds = 60
    truth = {"material.G_inf": G_INF, "material.G1": G1}
    covered = dict.fromkeys(truth, 0)
    for seed in range(seeds):
        result = mdr.fit(CASE, data=[creep_curve(seed)])
        for name, value in truth.items():
            covered[name] += abs(result.parameters[name] - value) < 1.96 * result.standard_errors[name]
    assert all(0.85 * seeds <= count <= seeds for count in covered.values()), covered


def elastic_curve_under_a_rising_force(seed: int) -> dict:
    """Hertz (eq. (H1), E* = 4 G): d = (3 F / (16 G sqrt(R)))^(2/3) under F = 2 nN (t / 0.4 s)^2, after 20 rows of
    approach at zero force."""
    rng = np.random.default_rng(seed)
    time = np.arange(420) * 1e-3
    force = 2.0 * (np.clip(time - 0.02, 0.0, None) / 0.4) ** 2
    depth = np.where(time > 0.02, (3.0 * force / (16.0 * G_INF * np.sqrt(R))) ** (2.0 / 3.0), -(0.02 - time))
    return {"time": time, "depth": depth + rng.normal(0.0, 0.001, time.size),
            "force": force + rng.normal(0.0, 0.01, time.size)}


def test_the_baseline_term_of_an_elastic_depth_fit_is_the_closed_form():
    # One parameter, ln G: the model depth d = c (F - b)^(2/3) G^(-2/3) gives dr/d ln G = j = -(2/3) d / noise and
    # dr/db = -(2/3) d / ((F - b) noise) exactly, so var(ln G) = s^2 / sum j^2 + sigma_b^2 (sum j dr/db / sum j^2)^2
    # from the fit's own model, drive and residuals (before: the first term alone, 0.00095 of G where this is 0.0041).
    # The driving force's noise sigma_F (drive_noise) moves each row's depth alone (elastic: no memory), S diagonal,
    # w_i = S_ii sigma_F / noise = -(dr/db)_i sigma_F: it adds M / (sum j^2)^2, M = sum (j w)^2, and s^2 keeps the
    # share of the residuals it does not explain, (RSS - sum w^2 + M / sum j^2) / (n - 1). The fit estimates M from
    # 24 draws (relative standard error sqrt(2 / 24) = 0.29): within three of them.
    case = {"units": "um-nN-s", "material": {"model": "elastic", "G": 0.5}, "indenter": {"shape": "sphere", "R": R},
            "fit": {"free": ["material.G"], "fitted": "depth", "contact_point": "fixed"}}
    result = mdr.fit(case, data=[elastic_curve_under_a_rising_force(0)])
    curve, fitted = result.summary["curves"][0], result.curves[0]
    assert result.summary["error_kind"].startswith("white noise (chi-square)")
    model, measured, drive = (np.asarray(fitted[key]) for key in ("model", "measured", "drive"))
    noise = curve["noise"]
    residuals = (model - measured) / noise
    along_log_modulus = -2.0 / 3.0 * model / noise
    along_baseline = -2.0 / 3.0 * model / (drive * noise)
    gram = along_log_modulus @ along_log_modulus
    drive_weights = -along_baseline * curve["drive_noise"]
    meat = np.sum((along_log_modulus * drive_weights) ** 2)
    kept = residuals @ residuals - drive_weights @ drive_weights + meat / gram
    variance = (kept / (residuals.size - 1) / gram + meat / gram ** 2 +
                (curve["baseline_error"] * (along_log_modulus @ along_baseline) / gram) ** 2)
    modulus = result.parameters["material.G"]
    reported = (result.standard_errors["material.G"] / modulus) ** 2
    assert abs(reported - variance) < 3.0 * np.sqrt(2.0 / 24.0) * meat / gram ** 2, (reported, variance, meat / gram ** 2)


def test_a_fixed_baseline_has_no_error():
    case = {**CASE, "fit": {**CASE["fit"], "baseline": "fixed"}}
    curve = mdr.fit(case, data=[creep_curve(0)]).summary["curves"][0]
    assert not curve["baseline_error"], curve
