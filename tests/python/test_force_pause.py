"""Constant-force pauses under spring control from Python (`load.force_pauses`, issue 11): the same key works in an
mdr.run dict, numpy arrays included, and a bad pause raises ValueError with the CLI's message."""

from __future__ import annotations

import numpy as np
import pytest

import mdr

CASE = {"material": {"model": "standard", "G_inf": 1.0e6, "G1": 2.0e6, "tau1": 1.0},
        "indenter": {"shape": "sphere", "R": 0.01},
        "numerics": {"elements": 200}}
K = 2.0e4


def load(pauses):
    return {"control": "spring", "spring_constant": K,
            "history": [[0.0, 0.0], [1.0, 1.0e-4], [4.0, 1.0e-4], [5.0, -5.0e-5]], "force_pauses": pauses}


def test_force_pause_from_a_dict():
    result = mdr.run({**CASE, "load": load(np.array([[1.0, 4.0]]))})
    history = result.history
    t, d, F, z = history["t"], history["d"], history["F"], history["z"]
    pause = (t >= 1.0) & (t <= 4.0)
    held = F[pause][0]
    np.testing.assert_allclose(F[pause], held, rtol=1e-12)
    np.testing.assert_allclose(z[pause], d[pause] + held / K, rtol=1e-12)
    assert d[pause][-1] > 1.2 * d[pause][0]  # it crept
    after = t > 4.0
    np.testing.assert_allclose(z[after], z[pause][-1] - 1.5e-4 * (t[after] - 4.0), rtol=0, atol=1e-16)


def test_bad_force_pause_raises_value_error():
    with pytest.raises(ValueError, match=r"load.force_pauses\[1\] = \[2, 4\]: must start after the previous pause"):
        mdr.run({**CASE, "load": load([[1.0, 3.0], [2.0, 4.0]])})
