"""Issue 24: the command line's rule for an indenter without a tip size holds for mdr.fit. A curve's largest
indentation (and its contact radius) must lie within the lengths of indentation contacts, 0.1 nm to 10 cm
(include/mdr/fit/plausibility.hpp); a cone given depths in the wrong unit is flagged naming units.length."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

import mdr

# Sneddon's cone in um-nN-s (G in kPa, lengths in um, forces in nN): F = 2 E* d^2 / (pi tan(slope)), E* = 4G
# (eq. 24, 25); half_angle_deg = 35 is slope 55 deg.
G = 0.2
SLOPE = math.radians(55.0)
CASE = {"units": "um-nN-s", "material": {"model": "elastic", "G": 0.05},
        "indenter": {"shape": "cone", "half_angle_deg": 35.0}, "fit": {"free": ["material.G"]}}
RULE = "is outside the lengths of indentation contacts (1e-10 m to 0.1 m, AFM to macroscopic indentation)"


def cone_curve(length_scale):
    """3 um deep after 1 um of approach; the depths in um times length_scale."""
    t = np.linspace(0.0, 1.0, 300)
    depth = -1.0 + 4.0 * t
    force = 8.0 * G * np.maximum(depth, 0.0) ** 2 / (math.pi * math.tan(SLOPE))
    return {"time": t, "depth": (depth + 1.0) * length_scale, "force": force}


def length_flags(result):
    return [flag for flag in result.summary["curves"][0]["flags"] if RULE in flag]


def test_a_sane_cone_fit_is_not_flagged():
    result = mdr.fit(CASE, data=[cone_curve(1.0)])
    # The exact curve is noise-free, and said to be (docs/case-format.md, "Noise-free data"); nothing else is flagged.
    flags = result.summary["curves"][0]["flags"]
    assert [flag for flag in flags if not flag.startswith("noise-free:")] == [] and result.summary["flags"] == []
    assert result.parameters["material.G"] == pytest.approx(G, rel=1e-3)


@pytest.mark.parametrize("units, length_scale, shown", [("um-nN-s", 1e-6, r"[234](\.\d+)?e-06 µm"),
                                                        ("SI", 1.0, r"[234](\.\d+)? m")],
                         ids=["metres-in-um-nN-s", "micrometres-in-SI"])
def test_lengths_in_another_unit_on_a_cone_are_flagged(units, length_scale, shown):
    """Metres in a um-nN-s case (3e-12 m deep), micrometres in an SI case (3 m deep): one flag naming the key."""
    (flag,) = length_flags(mdr.fit(CASE | {"units": units}, data=[cone_curve(length_scale)]))
    assert re.match("largest indentation " + shown, flag) and "units.length" in flag
