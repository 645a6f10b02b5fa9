"""mdr.read_curves (docs/case-format.md, "Instrument files and maps"): the C++ readers through Python, checked
against the files' header values (the same values the C++ tests in tests/unit/instrument assert)."""

from __future__ import annotations

import struct
import subprocess
import sys

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


def nanoscope_force_volume(tmp_path, columns, rows):
    """scripts/make_instrument_test_files.py forcevolume: the vendor curve made a force volume of columns x rows
    curves, curve k holding the vendor's stored integers times k + 1, by the layout docs/instrument-files.md cites."""
    path = tmp_path / f"force-volume-{columns}x{rows}.spm"
    subprocess.run([sys.executable, REPO_ROOT / "scripts" / "make_instrument_test_files.py", "forcevolume",
                    str(columns), str(rows), path], check=True)
    return path


def test_nanoscope_force_volume_curves_start_at_the_bottom_left_and_run_along_x(tmp_path):
    # Bruker's own nanoscope package (examples.py, force_volume_example_1, image drawn with origin "lower"): curve 0
    # is the force volume image's bottom-left pixel, curve samples_per_line - 1 its bottom-right, the last curve its
    # top-right. A 3 x 2 raster (not square) tells x from y.
    curves = mdr.read_curves(nanoscope_force_volume(tmp_path, 3, 2))
    assert len(curves) == 6
    # \Scan Size: 2000 nm centred on \X Offset, \Y Offset 0: pixel centres at x = -2/3, 0, 2/3 um, y = -1/2, 1/2 um
    low_x, high_x, low_y, high_y = -2e-6 / 3, 2e-6 / 3, -0.5e-6, 0.5e-6
    assert curves[0].position == pytest.approx((low_x, low_y), abs=1e-15)
    assert curves[2].position == pytest.approx((high_x, low_y), abs=1e-15)
    assert curves[5].position == pytest.approx((high_x, high_y), abs=1e-15)
    assert [curve.pixel for curve in curves] == [(0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (2, 1)]
    # Curve k is the k-th stored: its deflection at the turnaround is (k + 1) x the vendor's first stored integer x
    # \@4:Z scale (0.000375 V/LSB) x \@Sens. DeflSens (27.39 nm/V).
    turnaround = struct.unpack_from("<i", (VENDOR / "20200904_Egel4-Z1.0_00025.spm").read_bytes(), 80960)[0]
    for k, curve in enumerate(curves):
        assert curve.deflection[1023] == pytest.approx((k + 1) * turnaround * 0.000375 * 27.39e-9, rel=1e-12)


def test_nanoscope_force_volume_raster_may_come_from_its_image_alone(tmp_path):
    # Bruker's nanoscope package counts a line's curves by the force volume image's samples per line: with
    # \force/line 9, the scan list's \Samps/line 5 and \Lines 7 (63, 81, 35 or 25 curves), only the image list's
    # 3 x 2 holds the 6 curves stored.
    path = nanoscope_force_volume(tmp_path, 3, 2)
    data = path.read_bytes()
    for old, new in ((b"\\force/line: 3\r", b"\\force/line: 9\r"), (b"\\Lines: 2\r", b"\\Lines: 7\r"),
                     (b"\\Samps/line: 3\r\n\\Lines", b"\\Samps/line: 5\r\n\\Lines")):
        assert data.count(old) == 1
        data = data.replace(old, new)
    path.write_bytes(data)
    curves = mdr.read_curves(path)
    assert [curve.pixel for curve in curves] == [(0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (2, 1)]


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
