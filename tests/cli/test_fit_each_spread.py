"""`mdr fit CASE --each ...`: each.json sets the spread of the files' values against the errors their fits report
(fit::spread_of_repeats), on batches of Hertz curves made here with numpy: repeats that scatter by their noise (no
flag), records that differ by more than their noise, and a misfit that the records share."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest
from scipy import stats

CASE = """
units = "um-nN-s"
[material]
model = "elastic"
G = 0.05
[indenter]
shape = "sphere"
R = 5.0
[fit]
free = ["material.G"]
[[fit.data]]
file = "c0.csv"
depth = "d"
force = "F"
time = "t"
"""


def write_curves(workdir, moduli, stiffening=0.0, seed=11, rows=400, noise=0.002):
    """Depth-force curves (um, nN) of an elastic sphere, F = (16/3) G sqrt(R) d^1.5 (1 + stiffening d), the contact
    one um after the first row, with white noise of `noise` nN; one file per modulus."""
    generator = np.random.default_rng(seed)
    names = []
    for i, modulus in enumerate(moduli):
        t = np.linspace(0.0, 1.0, rows)
        depth = -1.0 + 4.0 * t
        indentation = np.clip(depth, 0.0, None)
        force = 16.0 / 3.0 * modulus * np.sqrt(5.0) * indentation ** 1.5 * (1.0 + stiffening * indentation)
        force += generator.normal(0.0, noise, rows)
        name = f"c{i}.csv"
        with open(workdir / name, "w", newline="", encoding="utf-8") as handle:
            writer = csv.writer(handle)
            writer.writerow(["t", "d", "F"])
            writer.writerows(zip(t, depth + 1.0, force))
        names.append(name)
    return names


def fit_each(run_mdr, workdir, names):
    path = workdir / "case.toml"
    path.write_text(CASE, encoding="utf-8")
    result = run_mdr("fit", path, "--each", *names, "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    with open(workdir / "out" / "each.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    return result, rows, json.loads((workdir / "out" / "each.json").read_text())


def test_repeats_scattering_by_their_noise_agree_with_their_errors(run_mdr, workdir):
    result, rows, each = fit_each(run_mdr, workdir, write_curves(workdir, [0.2] * 6))
    values = np.array([float(row["material.G"]) for row in rows])
    errors = np.array([float(row["material.G_stderr"]) for row in rows])
    spread = each["spread"]["material.G"]
    assert spread["count"] == 6
    assert spread["mean"] == pytest.approx(values.mean(), rel=1e-12)
    assert spread["standard_deviation"] == pytest.approx(values.std(ddof=1), rel=1e-10)
    assert spread["standard_error_of_mean"] == pytest.approx(values.std(ddof=1) / np.sqrt(6), rel=1e-10)
    assert spread["typical_error"] == pytest.approx(np.median(errors), rel=1e-12)
    # The 95 % range of sigma / s for 6 normal values: sqrt(5 / chi^2_5(0.975)) to sqrt(5 / chi^2_5(0.025)).
    assert spread["consistent_range"] == pytest.approx(
        [np.sqrt(5 / stats.chi2.ppf(0.975, 5)), np.sqrt(5 / stats.chi2.ppf(0.025, 5))], rel=1e-9)
    low, high = spread["consistent_range"]
    assert low < spread["error_to_spread"] < high
    assert each["flags"] == []
    assert "spread of the 6 converged: material.G" in result.stdout


def test_records_that_differ_beyond_their_noise_are_flagged(run_mdr, workdir):
    _, _, each = fit_each(run_mdr, workdir, write_curves(workdir, [0.18, 0.2, 0.22]))
    spread = each["spread"]["material.G"]
    assert spread["mean"] == pytest.approx(0.2, rel=2e-3)
    assert spread["error_to_spread"] < spread["consistent_range"][0]
    assert len(each["flags"]) == 1 and "differ by more than their noise" in each["flags"][0]


def test_a_misfit_the_records_share_is_flagged(run_mdr, workdir):
    # A stiffening the elastic sphere cannot follow: every fit says "misfit" and its errors (inflated for the
    # correlated residuals) far exceed how the five fits scatter, which is by their noise alone.
    _, rows, each = fit_each(run_mdr, workdir, write_curves(workdir, [0.2] * 5, stiffening=0.3))
    assert all(row["status"] == "converged, misfit" for row in rows)
    spread = each["spread"]["material.G"]
    assert spread["error_to_spread"] > spread["consistent_range"][1]
    assert len(each["flags"]) == 1 and "model misfit" in each["flags"][0]


def test_an_undetermined_key_is_left_out_of_the_spread(run_mdr, workdir):
    # G and R of an elastic sphere enter only as G sqrt(R): each fit leaves both undetermined (at G = 0.1, not the
    # 0.2 of the data). The batch gave "G = 0.1 +- 1.8e-06" without a flag; an undetermined value is no measurement.
    names = write_curves(workdir, [0.2] * 3)
    path = workdir / "case.toml"
    path.write_text(CASE.replace('free = ["material.G"]', 'free = ["material.G", "indenter.R"]'), encoding="utf-8")
    result = run_mdr("fit", path, "--each", *names, "--out", workdir / "out", timeout=300)
    assert result.returncode == 0, result.stderr
    each = json.loads((workdir / "out" / "each.json").read_text())
    for key in ("material.G", "indenter.R"):
        spread = each["spread"][key]
        assert spread["count"] == 0 and spread["undetermined"] == 3, spread
        assert spread["mean"] is None and spread["error_to_spread"] is None, spread
        assert f"{key}: undetermined in 3 of the 3 converged fits" in result.stdout
        assert f"undetermined (c0): {key}:" in result.stdout
    assert len(each["flags"]) == 2 and all("left out of its spread" in flag for flag in each["flags"])
    assert "spread of the" not in result.stdout
