"""mdr.fit with rebound data given as arrays (``{"kind": "rebound", ...}``): a Kelvin-Voigt viscosity recovered
from e(v0) made by the independent impact ODE, the uncertainty estimated from the data when not given, the
result's rebound entries, and bad rebound arrays as ValueError."""

from __future__ import annotations

import pytest

import mdr

ETA_TRUE = 300.0  # Pa s (G = 1 MPa; sphere R = 10 mm, m = 10 g)
SPEEDS = [0.01, 0.025, 0.063, 0.16, 0.4, 1.0]  # m/s
# e at SPEEDS: tests/support/reference/impact_ode.hpp (sphere_impact_ting, e to ~1e-9) for that body, 17 digits.
RESTITUTION = [0.78971185038736336, 0.75609200320439296, 0.71835277755485927, 0.67649882903512637,
               0.63190360752271135, 0.58434891220329788]

CASE = {"material": {"model": "kelvin_voigt", "G": 1.0e6, "eta": 1500.0},
        "indenter": {"shape": "sphere", "R": 0.01, "mass": 0.01},
        "fit": {"free": ["material.eta"]}}


def test_kelvin_voigt_viscosity_from_rebound_arrays():
    # No uncertainty given: estimated from the scatter about the neighbours' line (here the curvature of e(ln v0)).
    result = mdr.fit(CASE, data=[{"kind": "rebound", "name": "drops", "velocity": SPEEDS,
                                  "restitution": RESTITUTION}])
    assert result.status == "converged"
    # Limited by the impact model at its fit resolution (e within 6e-5 for Kelvin-Voigt bodies).
    assert result.parameters["material.eta"] == pytest.approx(ETA_TRUE, rel=2e-3)
    entry = result.curves[0]
    assert (entry["name"], entry["kind"], entry["fitted"]) == ("drops", "rebound", "restitution")
    assert list(entry["t"]) == SPEEDS and entry["model"] == pytest.approx(RESTITUTION, abs=2e-4)
    assert result.summary["curves"][0]["noise"] > 0.0
    assert result.summary["points"] == 6


@pytest.mark.parametrize("data, fragments", [
    ({"velocity": SPEEDS[:2], "restitution": RESTITUTION[:2]}, ["data[0].restitution_error = (missing)", "3"]),
    ({"velocity": [-0.01] + SPEEDS[1:], "restitution": RESTITUTION}, ["data[0].velocity = -0.01", "> 0"]),
    ({"velocity": SPEEDS, "restitution": [1.5] + RESTITUTION[1:]}, ["data[0].restitution = 1.5", "[0, 1]"]),
    ({"velocity": SPEEDS, "restitution": RESTITUTION[1:]}, ["data[0].restitution", "as many values as velocity"]),
    ({"velocity": SPEEDS}, ["data[0].restitution = (missing)"]),
    ({"velocity": SPEEDS, "restitution": RESTITUTION, "mass": 0.0}, ["data[0].mass = 0", "> 0"]),
    ({"velocity": SPEEDS, "restitution": RESTITUTION, "speed": 1.0}, ["data[0].speed", "unknown key"]),
])
def test_bad_rebound_arrays(data, fragments):
    with pytest.raises(ValueError) as error:
        mdr.fit(CASE, data=[{"kind": "rebound", **data}])
    for fragment in fragments:
        assert fragment in str(error.value)


def test_an_unknown_kind_of_data():
    with pytest.raises(ValueError, match=r"data\[0\].kind = 'bounce': one of curve, rebound"):
        mdr.fit(CASE, data=[{"kind": "bounce", "velocity": SPEEDS, "restitution": RESTITUTION}])


def test_a_power_law_is_not_fitted_to_rebound_data():
    # A power law stands as a series certified over the runs' lags (docs/case-format.md, "The forward model"); an
    # impact's lags are known only once it has run, so rebound data are refused naming the material. Before, the
    # fit ran on a series certified over a placeholder's lags (1e-4 to 1 s) that no impact had asked for.
    case = {**CASE, "material": {"model": "power_law", "G0": 1.0e6, "beta": 0.2}, "fit": {"free": ["material.G0"]}}
    with pytest.raises(ValueError) as error:
        mdr.fit(case, data=[{"kind": "rebound", "velocity": SPEEDS, "restitution": RESTITUTION}])
    assert str(error.value).startswith("material = power_law (G0 = 1000000 Pa, beta = 0.2, t0 = 1 s): ")
    assert "rebound data need a finite Prony series" in str(error.value)
