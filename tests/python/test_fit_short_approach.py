"""A defect of the contact estimate (src/fit/contact_estimate.cpp, step 4), fixed: with a short approach before the
contact (10 or 30 rows), the first baseline window reached into the slow d^1.5 onset of a sphere, its line tilted
with the rise, and one refit (step 4) did not bring it back before the contact. The constant baseline averaged
contact rows (5.5 noise deviations high at 10 rows), G came out 13 errors high, a tilt was flagged that the data do
not have, and the 95 % intervals covered G in none of 200 seeds. Step 4 now repeats until the window holds only
rows shallower than the contact less the depth over which the onset rises by one noise deviation.

The data are the closed-form Hertz force, F = 16/3 G sqrt(R) d^1.5 (equations.md, eq. (H1) with E* = 4 G for an
incompressible material), plus a baseline 0.3 nN and white noise 0.01 nN, in um-nN-s."""

from __future__ import annotations

import re

import numpy as np
import pytest

import mdr

TRUE_G = 0.2        # kPa
RADIUS = 5.0        # um
BASELINE = 0.3      # nN
NOISE = 0.01        # nN
CASE = {"units": "um-nN-s", "material": {"model": "elastic", "G": 0.1}, "indenter": {"shape": "sphere", "R": RADIUS},
        "fit": {"free": ["material.G"]}}


def hertz_curve(approach_rows: int, seed: int) -> dict:
    """`approach_rows` rows from -0.2 um to the contact at 0, then 1000 rows to 2 um, one row per ms."""
    time = np.arange(approach_rows + 1000) * 1e-3
    depth = np.concatenate([np.linspace(-0.2, 0.0, approach_rows, endpoint=False), np.linspace(0.0, 2.0, 1000)])
    hertz = 16.0 / 3.0 * TRUE_G * np.sqrt(RADIUS) * np.clip(depth, 0.0, None) ** 1.5
    force = hertz + BASELINE + np.random.default_rng(seed).normal(0.0, NOISE, time.size)
    return {"time": time, "depth": depth, "force": force}


@pytest.mark.parametrize("approach_rows", [10, 30])
def test_a_short_approach_gives_the_true_modulus_and_no_tilt(approach_rows):
    result = mdr.fit(CASE, data=[hertz_curve(approach_rows, seed=0)])
    curve = result.summary["curves"][0]
    assert abs(result.parameters["material.G"] - TRUE_G) < 3.0 * result.standard_errors["material.G"]
    assert abs(curve["baseline"] - BASELINE) < 3.0 * NOISE / np.sqrt(8)   # a mean of at least 8 rows before contact
    assert not [flag for flag in curve["flags"] if "tilt" in flag]


def test_the_95_percent_intervals_cover_the_modulus_after_a_short_approach():
    seeds = 60
    covered = 0
    for seed in range(seeds):
        result = mdr.fit(CASE, data=[hertz_curve(30, seed)])
        error = result.standard_errors["material.G"]
        covered += abs(result.parameters["material.G"] - TRUE_G) < 1.96 * error
    assert 0.85 * seeds <= covered <= seeds


@pytest.mark.parametrize("approach_rows", [3, 5])
def test_an_approach_shorter_than_the_baseline_window_is_said_to_be_short_not_a_start_in_contact(approach_rows):
    # Before: "starts in contact: no approach out of contact is recorded", untrue for a record whose depth moves
    # from -0.2 um. The flag counts the rows before the contact estimate and the window's rows past it (none now).
    curve = hertz_curve(approach_rows, seed=0)
    result = mdr.fit(CASE, data=[curve])
    flags = result.summary["curves"][0]["flags"]
    assert not [flag for flag in flags if "starts in contact" in flag], flags
    short = [flag for flag in flags if flag.startswith("short approach: only ")]
    assert len(short) == 1, flags
    numbers = re.match(r"short approach: only (\d+) rows before the contact estimate \(depth (\S+)\); the "
                       r"baseline is taken from (\d+) rows, (\d+) of them past", short[0])
    before, contact, window, past = int(numbers[1]), float(numbers[2]), int(numbers[3]), int(numbers[4])
    assert before == int(np.argmax(curve["depth"] > contact))   # the rows shallower than the stated contact
    assert approach_rows <= before < approach_rows + 10          # the true contact is at row approach_rows
    assert 2 <= window <= before and past == 0
    assert "their mean, no tilt" in short[0]


@pytest.mark.parametrize("approach_rows", [3, 5])
def test_under_8_approach_rows_the_baseline_is_the_mean_of_the_rows_before_contact(approach_rows):
    # estimate_contact's step 4 kept a window of about 20 rows, most of them in the Hertz onset, when fewer than 8
    # lay before the contact: the baseline was 0.45 (3 rows) and 0.32 (5 rows) noise deviations high on average,
    # which no error stated, and the 95 % intervals covered G in 34 and 42 of 60 seeds. The window is now the rows
    # before the contact however few (at least 2), their mean the baseline, its error sigma / sqrt(n) carried:
    # measured 55 and 52 of 60, the baseline 0.08 and 0.02 deviations high on average. Since the onset is fitted
    # against a window's line only where its tilt is measured (contact_estimate.cpp, step 3; in 1 of 9 mt19937 seeds
    # of tests/unit/fit/contact_estimate_test.cpp a 9-21-row window's tilt drew the contact 50-300 nm deep): 55 and
    # 51 of 60, the baseline -0.005 and -0.02 deviations on average; over 200 seeds 180 and 175 covered (180 and 177
    # before), the baseline 0.02 and -0.005 deviations (0.09 and 0.05 before, largest 1.8 both), the fitted contact
    # within 1.96 of its errors in 181 and 176 (180 and 176 before; largest 6.8 and 4.9 errors, 8 nm).
    seeds = 60
    covered = 0
    offsets = []
    for seed in range(seeds):
        result = mdr.fit(CASE, data=[hertz_curve(approach_rows, seed)])
        curve = result.summary["curves"][0]
        covered += abs(result.parameters["material.G"] - TRUE_G) < 1.96 * result.standard_errors["material.G"]
        offsets.append((curve["baseline"] - BASELINE) / NOISE)
        assert abs(curve["baseline"] - BASELINE) < 4.0 * curve["baseline_error"], (seed, curve)
        assert abs(curve["contact_point"]) < 4.0 * curve["contact_point_error"], (seed, curve)   # the truth is 0
    assert 0.85 * seeds <= covered <= seeds
    assert abs(np.mean(offsets)) < 0.2   # a mean of 3-8 rows: its seed-to-seed spread over sqrt(60) is < 0.08


def test_a_line_baseline_from_fewer_than_8_rows_before_contact_is_refused_naming_the_key():
    case = {**CASE, "fit": {**CASE["fit"], "baseline": "line"}}
    with pytest.raises(mdr.InvalidInput, match=r'^fit\.baseline = "line": fit\.data\[0\] .* only \d rows before '
                                               r'contact .* a line\'s tilt needs 8'):
        mdr.fit(case, data=[tilted_hertz_curve(5, seed=0)])


def tilted_hertz_curve(approach_rows: int, seed: int, tilt: float = 0.5) -> dict:
    """hertz_curve on a baseline tilted by `tilt` nN/s: 0.5 nN over the 1 s of contact, 50 noise deviations."""
    curve = hertz_curve(approach_rows, seed)
    return {**curve, "force": curve["force"] + tilt * curve["time"]}


def test_the_95_percent_intervals_cover_the_modulus_over_a_line_baseline_from_a_short_approach():
    # A line through 30 rows before contact (0.03 s) is extrapolated over the 1 s of contact: its slope's error,
    # sigma / sqrt(sum (t - mean t)^2) = 0.2 nN/s, moves the force by 0.2 nN (20 noise deviations) at the end. Before,
    # only the line's value error at the contact entered the covariance: 2 of 60 seeds covered G. Now the level's
    # and the slope's errors both do.
    case = {**CASE, "fit": {**CASE["fit"], "baseline": "line"}}
    seeds = 100
    covered = 0
    for seed in range(seeds):
        result = mdr.fit(case, data=[tilted_hertz_curve(30, seed)])
        error = result.standard_errors["material.G"]
        covered += abs(result.parameters["material.G"] - TRUE_G) < 1.96 * error
    assert 0.85 * seeds <= covered <= seeds
