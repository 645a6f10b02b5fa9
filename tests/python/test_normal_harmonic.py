"""A harmonic normal load and spring control from Python: the summary carries the last-cycle results and the
history the spring's columns, with nothing new in mdr.run (issue 11)."""

from __future__ import annotations

import math

import numpy as np

import mdr

MATERIAL = {"model": "standard", "G_inf": 1.0e6, "G1": 2.0e6, "tau1": 0.1}


def test_harmonic_summary_from_a_dict():
    result = mdr.run({
        "material": MATERIAL,
        "indenter": {"shape": "flat", "a": 1.0e-3},
        "load": {"control": "displacement", "history": [[0.0, 0.0], [0.1, 1.0e-5], [3.0, 1.0e-5]],
                 "harmonic": {"amplitude": 1.0e-7, "frequency": 1.0 / (2 * math.pi * 0.1),
                              "start": 0.1, "end": 3.0}},
        "numerics": {"elements": 50},
    })
    summary = result.summary
    omega_tau = 1.0  # 2 pi f tau1
    modulus = 1.0e6 + 2.0e6 * (1j * omega_tau) / (1 + 1j * omega_tau)
    expected = 8 * 1.0e-3 * modulus
    measured = summary["storage_stiffness"] + 1j * summary["loss_stiffness"]
    assert abs(measured - expected) < 1e-4 * abs(expected)
    assert summary["loss_tangent"] == summary["loss_stiffness"] / summary["storage_stiffness"]


def test_spring_history_columns():
    result = mdr.run({"material": MATERIAL, "indenter": {"shape": "sphere", "R": 0.01},
                      "load": {"control": "spring", "spring_constant": 1.0e4,
                               "history": [[0.0, -1.0e-6], [0.5, 2.0e-4], [1.0, 2.0e-4]]},
                      "numerics": {"elements": 100}})
    history = result.history
    assert set(history) >= {"t", "d", "F", "a", "z", "deflection"}
    np.testing.assert_allclose(history["deflection"], history["z"] - history["d"], rtol=0, atol=1e-18)
    np.testing.assert_allclose(history["F"], 1.0e4 * history["deflection"], rtol=1e-9, atol=1e-12)
    assert result.summary["control"] == "spring"
