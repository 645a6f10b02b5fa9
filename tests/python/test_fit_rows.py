"""Issue 24: the rows of a curve given as arrays follow a case file's rule (select_rows): an adhesive retract is
measured and cut at pull-off by default, ``until`` and ``window`` select as ``[[fit.data]]`` does, and a key that
mdr.fit does not know is refused, never ignored. The record is closed form, made here: a Hertz approach and
retract, F = k d^1.5 with k = 16/3 G sqrt(R) (Johnson eq. 4.22, nu = 1/2), from d = -3 um to 2 um and back, the
retract carrying a linear pull-off ramp of adhesion F_a (F - b0 = k d^1.5 - F_a for d >= 0, -F_a (d + delta) /
delta for -delta <= d < 0). So the pull-off force is -F_a and the retract first falls below the baseline at
d* = (F_a / k)^(2/3)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import mdr

G, RADIUS = 2e3, 5e-6                        # Pa, m
K = 16.0 / 3.0 * G * math.sqrt(RADIUS)       # N / m^1.5
ADHESION, DELTA, SIGMA, BASE = 2e-9, 0.5e-6, 1e-11, 1e-9   # N, m, N, N
STEP = 2e-9                                   # m per row

CASE = {"material": {"model": "elastic", "G": 1e3}, "indenter": {"shape": "sphere", "R": RADIUS},
        "fit": {"free": ["material.G"]}}


def record():
    approach = -3e-6 + STEP * np.arange(2501)
    retract = 2e-6 - STEP * np.arange(1, 2501)
    depth = np.concatenate([approach, retract])
    force = K * np.maximum(depth, 0.0) ** 1.5
    back = np.arange(depth.size) > 2500
    force -= np.where(back & (depth >= 0.0), ADHESION, 0.0)
    force -= np.where(back & (depth < 0.0) & (depth >= -DELTA), ADHESION * (depth + DELTA) / DELTA, 0.0)
    force += BASE + SIGMA * np.random.default_rng(11).standard_normal(depth.size)
    return {"time": 1e-3 * np.arange(depth.size), "depth": depth, "force": force}


def rows_after_pull_off():
    pull_off_depth = (ADHESION / K) ** (2.0 / 3.0)
    return math.ceil((pull_off_depth + 3e-6) / STEP)


def test_an_adhesive_retract_given_as_arrays_is_measured_and_cut_at_pull_off():
    """Once fitted through (every row), its adhesion reported as 0 and unflagged."""
    result = mdr.fit(CASE, data=[record()])
    curve = result.summary["curves"][0]
    assert curve["adhesion"]["pull_off_force"] == pytest.approx(-ADHESION, abs=5 * SIGMA)
    assert curve["rows_left_out"] == pytest.approx(rows_after_pull_off(), abs=3)
    assert any("the retract is adhesive" in flag for flag in curve["flags"]), curve["flags"]


def test_until_end_keeps_the_adhesive_retract_and_says_so():
    result = mdr.fit(CASE, data=[record() | {"until": "end"}])
    curve = result.summary["curves"][0]
    assert curve["rows_left_out"] == 0
    assert any("fitted through (until = \"end\")" in flag for flag in curve["flags"]), curve["flags"]


def test_a_window_fits_its_rows_only():
    data = record()
    inside = int(np.count_nonzero(data["time"] <= 2.0))
    result = mdr.fit(CASE, data=[data | {"until": "end", "window": {"time": [0.0, 2.0]}}])
    curve = result.summary["curves"][0]
    assert curve["points"] == inside
    assert curve["rows_left_out"] == data["time"].size - inside
    assert result.parameters["material.G"] == pytest.approx(G, rel=1e-3)


@pytest.mark.parametrize("extra, error, pattern", [
    ({"untill": "end"}, ValueError, r"^data\[0\]\.untill = \(given\): unknown key; valid keys: kind, name"),
    ({"until": "never"}, ValueError, r"^data\[0\]\.until = \"never\": one of pull_off, end"),
    ({"window": {"speed": [0, 1]}}, ValueError, r"^data\[0\]\.window\.speed = \(given\): unknown key"),
    ({"window": {"time": [2.0, 1.0]}}, ValueError, r"^data\[0\]\.window\.time = \[2, 1\]: the lower end must be below"),
    ({"window": {"time": [0.0, 1.0, 2.0]}}, ValueError, r"^data\[0\]\.window\.time = \[0\.0, 1\.0, 2\.0\]: must be"),
    ({"window": {"time": [0.0, 0.002]}}, ValueError, r"^data\[0\]\.window = 3 rows kept: a curve needs at least 10"),
    ({"window": [0.0, 1.0]}, TypeError, r"^data\[0\]\.window: a list; must be a dict"),
])
def test_bad_rows_are_refused_naming_the_key(extra, error, pattern):
    with pytest.raises(error, match=pattern):
        mdr.fit(CASE, data=[record() | extra])
