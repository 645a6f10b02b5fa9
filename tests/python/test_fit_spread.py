"""mdr.spread_of_repeats: the spread of repeated records fitted one by one against the errors of their fits (what
`mdr fit --each` writes to each.json), on Hertz curves made here with numpy; its bad input."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

import mdr

R = 5.0e-6  # m


def hertz_fit(modulus, seed):
    """mdr.fit of an elastic sphere's curve F = (16/3) G sqrt(R) d^1.5 with white noise, the contact at 1 um."""
    generator = np.random.default_rng(seed)
    depth = np.linspace(0.0, 4.0e-6, 300)
    force = 16.0 / 3.0 * modulus * np.sqrt(R) * np.clip(depth - 1.0e-6, 0.0, None) ** 1.5
    case = {"material": {"model": "elastic", "G": 50.0}, "indenter": {"shape": "sphere", "R": R},
            "fit": {"free": ["material.G"]}}
    data = {"time": np.linspace(0.0, 1.0, 300), "depth": depth, "force": force + generator.normal(0.0, 2e-12, 300)}
    return mdr.fit(case, data=[data])


def test_the_spread_of_repeats_is_set_against_their_errors():
    fits = [hertz_fit(200.0, seed) for seed in range(10, 15)]  # errors / spread 0.85 (95 % range 0.60-2.87)
    result = mdr.spread_of_repeats(fits)
    values = np.array([fit.parameters["material.G"] for fit in fits])
    errors = np.array([fit.standard_errors["material.G"] for fit in fits])
    spread = result["spread"]["material.G"]
    assert spread["count"] == 5
    assert spread["mean"] == pytest.approx(values.mean(), rel=1e-12)
    assert spread["standard_deviation"] == pytest.approx(values.std(ddof=1), rel=1e-10)
    assert spread["standard_error_of_mean"] == pytest.approx(values.std(ddof=1) / np.sqrt(5), rel=1e-10)
    assert spread["typical_error"] == pytest.approx(np.median(errors), rel=1e-12)
    assert spread["consistent_range"] == pytest.approx(
        [np.sqrt(4 / stats.chi2.ppf(0.975, 4)), np.sqrt(4 / stats.chi2.ppf(0.025, 4))], rel=1e-9)
    assert result["flags"] == [] and spread["consistent_range"][0] < spread["error_to_spread"]
    # Samples that differ by 10 %: far more than the fits' errors, flagged.
    differing = mdr.spread_of_repeats([hertz_fit(modulus, 9) for modulus in (180.0, 200.0, 220.0)])
    assert len(differing["flags"]) == 1 and "differ by more than their noise" in differing["flags"][0]


def test_bad_input_is_refused_naming_it():
    fit = hertz_fit(200.0, 1)
    with pytest.raises(ValueError, match=r"fits = \[\]"):
        mdr.spread_of_repeats([])
    with pytest.raises(ValueError, match=r"fits\[1\] = dict: must be an mdr.FitResult"):
        mdr.spread_of_repeats([fit, {"material.G": 1.0}])
    other = mdr.FitResult(parameters={"material.G_inf": 1.0}, standard_errors={"material.G_inf": 0.1},
                          status="converged", summary={"converged": True})
    with pytest.raises(ValueError, match=r"fits\[1\]: its free keys \['material.G_inf'\] differ"):
        mdr.spread_of_repeats([fit, other])


def test_an_undetermined_key_is_left_out_of_the_spread_as_by_fit_each():
    # G and R of an elastic sphere enter only as G sqrt(R): each fit leaves both undetermined. Their values are no
    # measurement; spread_of_repeats counted them as one (undetermined 0), where `mdr fit --each` leaves them out.
    fits = []
    for seed in range(3):
        generator = np.random.default_rng(seed)
        depth = np.linspace(0.0, 4.0e-6, 300)
        force = 16.0 / 3.0 * 200.0 * np.sqrt(R) * np.clip(depth - 1.0e-6, 0.0, None) ** 1.5
        case = {"material": {"model": "elastic", "G": 50.0}, "indenter": {"shape": "sphere", "R": R},
                "fit": {"free": ["material.G", "indenter.R"]}}
        data = {"time": np.linspace(0.0, 1.0, 300), "depth": depth,
                "force": force + generator.normal(0.0, 2e-12, 300)}
        fits.append(mdr.fit(case, data=[data]))
    assert all(set(fit.summary["undetermined"]) == {"material.G", "indenter.R"} for fit in fits)
    result = mdr.spread_of_repeats(fits)
    for key in ("material.G", "indenter.R"):
        spread = result["spread"][key]
        assert spread["count"] == 0 and spread["undetermined"] == 3, spread
        assert spread["mean"] is None and spread["error_to_spread"] is None, spread
    assert len(result["flags"]) == 2 and all("left out of its spread" in flag for flag in result["flags"])
