"""mdr.fit: curves from arrays or files, the same result object as fit.json, errors as ValueError, pickling, the
real measured curve of the examples."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

import mdr
from conftest import REPO_ROOT

R = 1.0e-3


def kelvin_voigt_creep_depth(t, G, eta, F):
    """Eq. 33 for a force step F at t = 0: a^3 = (3 F R / (16 G)) (1 - exp(-t G / eta)), d = a^2 / R."""
    radius = (3.0 * F * R / (16.0 * G) * (1.0 - np.exp(-t * G / eta))) ** (1.0 / 3.0)
    return radius ** 2 / R


def test_kelvin_voigt_from_a_creep_curve_given_as_arrays():
    # The measured force drives the model (a step, then held), the depth is fitted: eq. 33 in closed form.
    t = np.linspace(0.0, 2.0, 201)
    F = np.full_like(t, 0.2)
    d = kelvin_voigt_creep_depth(t, 1.0e6, 3.0e5, 0.2)
    case = {"material": {"model": "kelvin_voigt", "G": 3.0e5, "eta": 1.0e6},
            "indenter": {"shape": "sphere", "R": R},
            "fit": {"free": ["material.G", "material.eta"], "fitted": "depth",
                    "contact_point": "fixed", "baseline": "fixed"}}
    result = mdr.fit(case, data=[{"time": t, "depth": d, "force": F, "name": "creep"}])
    assert result.status == "converged"
    assert result.parameters["material.G"] == pytest.approx(1.0e6, rel=1e-3)
    assert result.parameters["material.eta"] == pytest.approx(3.0e5, rel=1e-3)
    assert result.curves[0]["name"] == "creep"
    assert set(result.summary) >= {"parameters", "standard_errors", "correlation", "aic", "bic", "evaluations"}
    again = pickle.loads(pickle.dumps(result))
    assert again.parameters == result.parameters
    # The fitted material under another load.
    predicted = result.predict({"control": "force", "history": [[0.0, 0.0], [0.5, 0.2], [2.0, 0.2]]})
    assert predicted.summary["max_force"] == pytest.approx(0.2)


def test_bad_input_is_a_value_error_with_the_command_line_message():
    case = {"material": {"model": "elastic", "G": 1.0e6}, "indenter": {"shape": "sphere", "R": R},
            "fit": {"free": ["material.G"], "bounds": {"material.G": [1.0e7, 1.0e8]}}}
    t = np.linspace(0.0, 1.0, 50)
    with pytest.raises(ValueError, match="material.G = 1000000: the start value must lie within its bounds"):
        mdr.fit(case, data=[{"time": t, "depth": 1e-6 * t, "force": 0.1 * t}])
    with pytest.raises(ValueError, match="fit.data = \\(missing\\)"):
        mdr.fit({**case, "fit": {"free": ["material.G"]}})
    with pytest.raises(ValueError, match="data\\[0\\].force"):
        mdr.fit(case, data=[{"time": t, "depth": t}])


def test_the_real_chiaro_curve_of_the_examples():
    result = mdr.fit(REPO_ROOT / "examples" / "fit" / "chiaro-standard.toml")
    assert result.status == "converged"
    # Its loading curve does not need a relaxation branch: the fit says so rather than report numbers for it.
    assert set(result.summary["undetermined"]) >= {"material.G1"}
    assert 30.0 < result.parameters["material.G_inf"] < 50.0
    assert result.summary["residual_to_noise"] < 10.0
