"""mdr.read_curves (docs/case-format.md, "Instrument files and maps"): the C++ readers through Python, checked
against the files' header values (the same values the C++ tests in tests/unit/instrument assert)."""

from __future__ import annotations

import numpy as np
import pytest

import mdr
from conftest import REPO_ROOT

VENDOR = REPO_ROOT / "examples" / "data" / "vendor"


def test_jpk_single_curve_has_the_header_calibration_and_si_arrays():
    curves = mdr.read_curves(VENDOR / "fmt-jpk-fd_spot3-0192.jpk-force")
    assert len(curves) == 1
    curve = curves[0]
    assert curve.spring_constant == 0.043493666407368466  # vDeflection's force multiplier in the header
    assert curve.segment_names == ["extend", "retract"]
    for name in ("time", "force", "height", "deflection", "segment"):
        assert isinstance(getattr(curve, name), np.ndarray) and getattr(curve, name).shape == (4000,), name
    assert np.issubdtype(curve.segment.dtype, np.integer)
    assert curve.segment[1999] == 0 and curve.segment[2000] == 1  # two segments of num-points = 2000
    assert curve.time[1999] < curve.time[2000]
    assert curve.position is None  # a single curve, not a map
    assert isinstance(curve.metadata, dict) and curve.metadata


def test_map_pixels_carry_their_position():
    curves = mdr.read_curves(VENDOR / "fmt-jpk-fd_2020.02.07-16.29.05.036.jpk-qi-data")
    assert len(curves) == 4
    assert [curve.pixel for curve in curves] == [(0, 0), (1, 0), (2, 0), (3, 0)]  # afmformats' grid indices
    assert all(len(curve.position) == 2 for curve in curves)


def test_afm_workshop_map_positions_in_metres():
    curves = mdr.read_curves(VENDOR / "fmt-afm-workshop-fd_mapping_16_2018-08-01_13.07.zip",
                             spring_constant=20.0, sensitivity=1e-8)
    assert len(curves) == 16
    x, y = curves[1].position  # the CSV's X, um = 7.333..., Y, um = 2.0
    assert x == pytest.approx(7.333333333333333e-06, rel=1e-12) and y == pytest.approx(2e-6, rel=1e-12)
    assert curves[1].spring_constant == 20.0


def test_nanoscope_curve_has_the_header_values():
    curve = mdr.read_curves(VENDOR / "20200904_Egel4-Z1.0_00025.spm")[0]
    assert curve.spring_constant == 0.1332  # \Spring Constant
    assert curve.sensitivity == pytest.approx(27.39e-9, rel=1e-12)  # \@Sens. DeflSens, nm/V
    assert curve.height[0] == pytest.approx(227.2211 * 13.203e-9, rel=1e-12)  # \@4:Ramp Size x \@Sens. Zsens
    assert curve.force.shape == (2048,)


def test_missing_calibration_is_named():
    path = VENDOR / "fmt-ntmdt-txt-fd_2015_01_17_gel4-0,1_mQ_adh_6B_Curve_DFL_Height_51.txt"
    with pytest.raises(mdr.InvalidInput, match="spring_constant"):
        mdr.read_curves(path)
    with pytest.raises(mdr.InvalidInput, match="sensitivity.*m/A"):
        mdr.read_curves(path, spring_constant=0.055)
    curve = mdr.read_curves(path, spring_constant=0.055, sensitivity=61.0)[0]
    assert curve.force[-1] == pytest.approx(-1.0926e-9 * 61.0 * 0.055, rel=1e-12)  # the last row's retract DFL


def test_calibration_for_a_file_with_its_own_is_refused():
    with pytest.raises(mdr.InvalidInput, match="spring_constant"):
        mdr.read_curves(VENDOR / "cell1-0001.jpk-force", spring_constant=0.1)


def test_unknown_ending_names_the_file(tmp_path):
    path = tmp_path / "curve.xyz"
    path.write_text("1 2\n")
    with pytest.raises(mdr.InvalidInput, match="curve.xyz"):
        mdr.read_curves(path)
