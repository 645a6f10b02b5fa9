"""mdr.fit with fit.candidates and [fit.spectrum]: the ranking and every candidate's result, on Hertz data (closed
form, G = 1 MPa) with Gaussian noise: the elastic model is preferred, the spectrum's G(t) is flat."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

import mdr

R = 1.0e-3
G = 1.0e6


def hertz_curve(seed):
    t = np.linspace(0.0, 1.0, 201)
    d = 1.0e-5 * t
    F = 16.0 / 3.0 * G * np.sqrt(R) * d ** 1.5
    noise = 1.0e-3 * F.max()
    return {"time": t, "depth": d, "force": F + np.random.default_rng(seed).normal(0.0, noise, t.size)}, noise


def case(fit):
    return {"material": {"model": "elastic", "G": 3.0e5}, "indenter": {"shape": "sphere", "R": R},
            "fit": {"contact_point": "fixed", "baseline": "fixed", "elements": 300, **fit}}


def test_candidates_are_ranked_and_the_simplest_sufficient_model_preferred():
    curve, noise = hertz_curve(3)
    result = mdr.fit(case({"candidates": ["standard", "elastic"]}), data=[curve])
    assert [entry["name"] for entry in result.ranking][0] == "elastic"
    assert set(result.candidates) == {"elastic", "standard"}
    assert result is result.candidates["elastic"]
    assert result.parameters["material.G"] == pytest.approx(G, rel=1e-2)
    assert result.ranking[0]["delta_bic"] == 0.0 and result.ranking[1]["delta_bic"] > 0.0
    assert tomllib.loads(result.fitted_case)["material"] == {"model": "elastic", "G": result.parameters["material.G"]}
    assert result.candidates["standard"].summary["undetermined"]  # its relaxation term is not needed


def test_spectrum_of_an_elastic_body_is_flat():
    curve, _ = hertz_curve(4)
    result = mdr.fit(case({"spectrum": {"per_decade": 1}}), data=[curve])
    spectrum = result.spectrum
    assert spectrum["tau"][-1] == pytest.approx(1.0)
    assert np.all(spectrum["G"] >= 0.0)
    t = np.geomspace(spectrum["tau"][0], spectrum["tau"][-1], 20)
    relaxation = spectrum["G_inf"] + np.exp(-t[:, None] / spectrum["tau"][None, :]) @ spectrum["G"]
    assert relaxation == pytest.approx(np.full_like(t, G), rel=2e-2)


def test_free_material_keys_with_candidates_are_refused():
    curve, _ = hertz_curve(5)
    with pytest.raises(ValueError, match="fit.free"):
        mdr.fit(case({"candidates": ["standard"], "free": ["material.G"]}), data=[curve])
