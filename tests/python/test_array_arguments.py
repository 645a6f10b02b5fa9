"""The array arguments of the mdr package (issue 23, items 3 and 4): one check (python/mdr/_arrays.py) takes float16,
float32 and integer arrays as float64, refuses None, text, bool, complex, objects and other dimensions with an error
naming the argument (before: numpy's or pybind11's errors, "force = 1 values", or silent flattening), and passes
float64 arrays to the library without a copy through Python lists (before, mdr.fit with 10^7 points peaked at
3.9 GB)."""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

import mdr
from mdr._arrays import real_array

T = np.linspace(0.0, 1.0, 101)
D = 1e-5 * T
F = 16.0 / 3.0 * 1e6 * math.sqrt(1e-3) * D ** 1.5  # Hertz, G = 1 MPa, R = 1 mm (handbook eq. 13)
CASE = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
        "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}


def fitted_modulus(data):
    return mdr.fit(CASE, data=data).parameters["material.G"]


def test_one_dict_is_one_curve():
    assert fitted_modulus({"time": T, "depth": D, "force": F}) == fitted_modulus([{"time": T, "depth": D, "force": F}])
    assert fitted_modulus({"time": T, "depth": D, "force": F}) == pytest.approx(1e6, rel=1e-9)


@pytest.mark.parametrize("data, error, message", [
    ("curve.csv", TypeError, r"^data: a str; must be a dict of arrays \(one curve\) or a list of them$"),
    (["curve.csv"], TypeError, r"^data\[0\]: a str; must be a dict of arrays"),
])
def test_data_that_are_not_dicts_are_refused_naming_data(data, error, message):
    with pytest.raises(error, match=message):
        mdr.fit(CASE, data=data)


@pytest.mark.parametrize("dtype", [np.float16, np.float32, np.int64, np.int32, np.uint16])
def test_real_dtypes_are_taken_as_float64(dtype):
    # Floats: every array in the dtype. Integers: the time in seconds (an elastic fit does not depend on it).
    if np.dtype(dtype).kind == "f":
        given = {"time": T.astype(dtype), "depth": D.astype(dtype), "force": F.astype(dtype)}
    else:
        given = {"time": np.arange(T.size, dtype=dtype), "depth": D, "force": F}
    expected = fitted_modulus([{key: values.astype(np.float64) for key, values in given.items()}])
    assert fitted_modulus([given]) == expected
    assert expected == pytest.approx(1e6, rel=1e-2)  # float16 keeps ~3 digits


@pytest.mark.parametrize("force, error, message", [
    (None, TypeError, r"^data\[0\]\.force = None: must be a 1-D array of real numbers$"),
    ("1, 2, 3", TypeError, r"^data\[0\]\.force = '1, 2, 3': must be a 1-D array of real numbers$"),
    (F + 0j, TypeError, r"^data\[0\]\.force: complex numbers \(dtype complex128\); must be a 1-D array"),
    (F > 0, TypeError, r"^data\[0\]\.force: booleans \(dtype bool\); must be a 1-D array"),
    ([0.0, None] * 50 + [1.0], TypeError, r"^data\[0\]\.force: objects \(None, mixed types\) \(dtype object\)"),
    (np.array(["1"] * 101), TypeError, r"^data\[0\]\.force: text \(dtype <U1\)"),
    (F.reshape(1, -1), ValueError, r"^data\[0\]\.force: a 2-D array of shape \(1, 101\); must be a 1-D array of "
                                   r"real numbers \(never flattened\)$"),
    (1.0, ValueError, r"^data\[0\]\.force: a number; must be a 1-D array of real numbers$"),
    ([[1.0], [1.0, 2.0]], ValueError, r"^data\[0\]\.force: a ragged sequence"),
])
def test_bad_arrays_are_refused_naming_the_key(force, error, message):
    with pytest.raises(error, match=message):
        mdr.fit(CASE, data=[{"time": T, "depth": D, "force": force}])


def test_the_other_array_arguments_share_the_check():
    with pytest.raises(TypeError, match=r"^data\[0\]\.spring_constant = None: must be a real number$"):
        mdr.fit(CASE, data=[{"time": T, "piezo": D, "deflection": D, "spring_constant": None}])
    with pytest.raises(TypeError, match=r"^data\[0\]\.velocity: complex numbers"):
        mdr.fit(CASE, data=[{"kind": "rebound", "velocity": [1j], "restitution": [0.5]}])
    with pytest.raises(ValueError, match=r"^vary\['material.G'\]: a 2-D array of shape \(1, 2\)"):
        mdr.sweep(CASE, {"material.G": [[1e6, 2e6]]})
    with pytest.raises(ValueError, match=r"^time: a 2-D array of shape \(1, 101\)"):
        mdr.fit_map(CASE, np.zeros((1, 1, 101)), time=T[None], depth=D, jobs=1)
    with pytest.raises(TypeError, match=r"^curve: complex numbers"):
        mdr.fit_maps.fit_curve(F + 0j, CASE, time=T, depth=D)


def test_float64_arrays_are_not_copied():
    assert real_array(F, "force") is F
    assert real_array(F[::2], "force").flags.c_contiguous  # a strided view is made contiguous once


PEAK_SCRIPT = """
import json, math, resource, sys
import numpy as np
import mdr
n = int(sys.argv[1])
t = np.linspace(0.0, 1.0, n)
d = 1e-5 * t
F = 16.0 / 3.0 * 1e6 * math.sqrt(1e-3) * d ** 1.5
case = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
        "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
G = mdr.fit(case, data=[{"time": t, "depth": d, "force": F}]).parameters["material.G"]
after = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print(json.dumps({"increase_bytes": (after - before) * 1024, "G": G}))
"""


def test_a_long_curve_costs_a_few_times_its_data(package_env):
    # ru_maxrss in KiB (Linux). The library's fit keeps its own copies (the curve, the model's history, residuals,
    # the result's curves: ~7 times the data at 1e6 points); Python lists of the arrays added ~6 more (13x).
    points = 1_000_000
    completed = subprocess.run([sys.executable, "-c", PEAK_SCRIPT, str(points)], capture_output=True, text=True,
                               env=package_env, timeout=300, check=True)
    measured = json.loads(completed.stdout)
    data_bytes = 3 * 8 * points
    assert measured["G"] == pytest.approx(1e6, rel=1e-6)
    assert measured["increase_bytes"] < 10 * data_bytes, measured["increase_bytes"] / data_bytes


def test_float16_forces_that_underflow_to_zero_are_refused_naming_the_key():
    # Forces of ~1e-10 N are below float16's smallest subnormal (6e-8): every value becomes 0. Issue 23 found a
    # RuntimeError ("the model cannot be evaluated") here; the fit must refuse the data as a ValueError naming it.
    force = (F * 1e-6).astype(np.float16)
    assert not force.any()
    with pytest.raises(ValueError, match=r"^fit\.data\[0\]\.force = 0 in every row: .*must differ from 0"):
        mdr.fit(CASE, data=[{"time": T, "depth": D, "force": force}])
