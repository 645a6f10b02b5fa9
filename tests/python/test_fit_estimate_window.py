"""A defect of the contact estimate (src/fit/contact_estimate.cpp), fixed: on a slowly rising Hertz onset the
baseline window crept into the contact (each move of step 2 refitted a sloped line that followed the early rise),
and the force noise came out 20 times too large (with it the residual/noise ratio and the weights). The window now
stops moving where it curves upward."""

from __future__ import annotations

import numpy as np
import pytest

import mdr


def test_noise_of_a_slow_hertz_onset_is_estimated_within_20_percent():
    t = np.linspace(0.0, 2.2, 2000)[:700]
    depth = np.where(t < 0.2, -0.4e-6 + 2e-6 * t, 4e-6 * (t - 0.2))      # approach, then loading at 4 um/s
    hertz = 16.0 / 3.0 * 3e3 * np.sqrt(1e-5) * np.maximum(depth, 0.0) ** 1.5   # G = 3 kPa, R = 10 um
    force = 5e-9 + hertz + np.random.default_rng(2).normal(0.0, 1e-9, t.size)
    case = {"material": {"model": "elastic", "G": 3e3}, "indenter": {"shape": "sphere", "R": 1e-5},
            "fit": {"free": ["material.G"], "max_iterations": 1, "elements": 100}}
    result = mdr.fit(case, data=[{"time": t, "depth": depth, "force": force}])
    assert result.summary["curves"][0]["noise"] == pytest.approx(1e-9, rel=0.2)
