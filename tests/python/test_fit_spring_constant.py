"""Issue 24: the spring constant of mdr.fit's raw AFM arrays follows the case file's rule. In SI it is N/m; in any
other system its unit is stated (`"units": {"spring_constant": "N/m"}`), a bare number refused naming the key:
0.05 reads as N/m to an AFM user and as nN/um to a um-nN-s case, 1000x apart."""

from __future__ import annotations

import numpy as np
import pytest

import mdr

# Hertz in um-nN-s (G in kPa, lengths in um, forces in nN): F = (16/3) G sqrt(R) d^1.5, E* = 4G.
G, RADIUS, K = 0.2, 5.0, 0.05   # kPa, um, N/m


def afm_arrays(k_case):
    t = np.linspace(0.0, 1.0, 300)
    depth = -1.0 + 4.0 * t
    force = 16.0 / 3.0 * G * np.sqrt(RADIUS) * np.maximum(depth, 0.0) ** 1.5
    deflection = force / k_case
    return {"time": t, "piezo": 10.0 - depth - deflection, "deflection": deflection}


CASE = {"units": "um-nN-s", "material": {"model": "elastic", "G": 0.05},
        "indenter": {"shape": "sphere", "R": RADIUS}, "fit": {"free": ["material.G"]}}


@pytest.mark.parametrize("value, unit", [(K, "N/m"), (K * 1e3, "nN/um"), (K * 1e3, "pN/nm")])
def test_a_stated_unit_gives_the_true_modulus(value, unit):
    curve = afm_arrays(K * 1e3) | {"spring_constant": value, "units": {"spring_constant": unit}}
    result = mdr.fit(CASE, data=[curve])
    assert result.parameters["material.G"] == pytest.approx(G, rel=1e-3)


def test_a_bare_spring_constant_in_a_non_si_case_is_refused():
    curve = afm_arrays(K * 1e3) | {"spring_constant": K}
    with pytest.raises(ValueError, match=r'^data\[0\]\.spring_constant = 0\.05: .*um-nN-s.*'
                                         r'data\[0\]\.units\.spring_constant = "N/m"'):
        mdr.fit(CASE, data=[curve])
    with pytest.raises(ValueError, match=r'data\[0\]\.units\.spring_constant = "N/cm2": must be a force / length'):
        mdr.fit(CASE, data=[curve | {"units": {"spring_constant": "N/cm2"}}])
    with pytest.raises(ValueError, match=r"data\[0\]\.units = .*one key spring_constant"):
        mdr.fit(CASE, data=[curve | {"units": {"length": "m"}}])
    # Depth and force arrays are in the case's units: a units dict beside them is refused, never ignored.
    t = curve["time"]
    with pytest.raises(ValueError, match=r"data\[0\]\.units = \{'length': 'm'\}: the arrays are in the case's units"):
        mdr.fit(CASE, data=[{"time": t, "depth": t, "force": t, "units": {"length": "m"}}])


def test_a_case_file_and_the_arrays_agree():
    """The same curve given as a um-nN-s case file's columns and as arrays: the same rule, the same modulus."""
    import os
    import tempfile

    curve = afm_arrays(K * 1e3)
    with tempfile.TemporaryDirectory() as directory:
        with open(os.path.join(directory, "afm.csv"), "w", encoding="utf-8") as handle:
            handle.write("t,piezo,defl\n")
            handle.writelines(f"{a!r},{b!r},{c!r}\n" for a, b, c in zip(curve["time"], curve["piezo"],
                                                                        curve["deflection"]))
        case = dict(CASE) | {"fit": {"free": ["material.G"], "data": [
            {"file": os.path.join(directory, "afm.csv"), "time": "t", "piezo": "piezo", "deflection": "defl",
             "spring_constant": K, "units": {"spring_constant": "N/m"}}]}}
        from_file = mdr.fit(case)
    from_arrays = mdr.fit(CASE, data=[curve | {"spring_constant": K, "units": {"spring_constant": "N/m"}}])
    assert from_file.parameters["material.G"] == pytest.approx(from_arrays.parameters["material.G"], rel=1e-9)


def test_lengths_in_metres_in_a_micrometre_case_are_flagged():
    """The plausibility rule of the command line holds for mdr.fit: a um-nN-s case given depths in metres (1e-6 of
    the sphere's radius) gets a curve flag naming units.length; the same arrays in micrometres none."""
    t = np.linspace(0.0, 1.0, 300)
    depth = -1.0 + 4.0 * t
    force = 16.0 / 3.0 * G * np.sqrt(RADIUS) * np.maximum(depth, 0.0) ** 1.5
    flagged = mdr.fit(CASE, data=[{"time": t, "depth": depth * 1e-6, "force": force}])
    # Among the curve's flags (such a fit is also a misfit, and its contact is flagged): the unit's, naming the key.
    (flag,) = [flag for flag in flagged.summary["curves"][0]["flags"] if "below 0.0001 of the sphere's R" in flag]
    assert "R = 5 µm" in flag and "units.length" in flag
    plain = mdr.fit(CASE, data=[{"time": t, "depth": depth + 1.0, "force": force}])
    assert plain.summary["curves"][0]["flags"] == []
