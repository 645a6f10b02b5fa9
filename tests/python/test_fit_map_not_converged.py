"""A pixel whose fit stops without converging is the same pixel by every route of a map: `mdr fit CASE --map FILE`
and `mdr.fit_map(case, FILE)` write it as a row with its values, errors and a `status` saying why it stopped
(mdr/fitcase/map_fit.hpp); `mdr.fit_map(case, stack)` on arrays, directories and HDF5 stacks (mdr.fit_maps.fit_curve
over mdr.map_curves) keeps the same row, its pixel NOT_CONVERGED with that reason, and its saved arrays and heat
maps say so. Before, the stack routes dropped its values and marked it FAILED (FitNotConverged)."""

from __future__ import annotations

import csv
import json
import math
import subprocess

import numpy as np
import pytest

import mdr
from conftest import REPO_ROOT
from mdr.curve_maps import FAILED, NOT_CONVERGED, OK

MAP = REPO_ROOT / "examples" / "data" / "vendor" / "fmt-jpk-fd_map-data-reference-points.jpk-force-map"
#: 12 iterations at most: the fit of the map's first curve (index/109) converges (with a misfit), those of the
#: other two stop short (the default 200 lets all three converge: docs/instrument-to-map.md).
CASE = {"material": {"model": "elastic", "G": 1000.0}, "indenter": {"shape": "sphere", "R": 5.0e-6},
        "fit": {"free": ["material.G"], "max_iterations": 12}}
#: CASE for the instrument file: its [[fit.data]] table names the file's extend segments.
FILE_CASE = dict(CASE, fit=dict(CASE["fit"], data=[{"file": "map.jpk-force-map", "segments": ["extend"]}]))
#: The columns of a row that are the pixel's place (the file's grid and positions; a stack states none).
PLACE = ("index", "column", "row", "x", "y")
STOPPED = "did not converge in 12 iterations"


def extend_curves() -> tuple[np.ndarray, np.ndarray]:
    """The curves the file route fits (fitcase::instrument_fit_curve with segments = ["extend"]), by the rule of
    fit::afm_depth_and_force written out here: the extend rows, force = k x deflection, depth = the fall of the tip
    height (height + deflection) from the first row; as a (1, 3, nt, 3) stack of time, depth and force, with the
    tip height of each curve's first row (the file route's contact_height is measured from it)."""
    curves, tip_heights = [], []
    for curve in mdr.read_curves(MAP):
        extend = curve.segment == curve.segment_names.index("extend")
        tip = curve.height[extend] + curve.deflection[extend]
        curves.append(np.stack([curve.time[extend], tip[0] - tip, curve.spring_constant * curve.deflection[extend]],
                               axis=-1))
        tip_heights.append(tip[0])
    return np.stack(curves)[None], np.array(tip_heights)


@pytest.fixture(scope="module")
def file_map() -> mdr.fit_map_files.MapTable:
    return mdr.fit_map(FILE_CASE, MAP, jobs=1)


@pytest.fixture(scope="module")
def stack() -> tuple[np.ndarray, np.ndarray]:
    return extend_curves()


def expect_the_file_maps_pixels(fits: mdr.curve_maps.CurveMap, table: mdr.fit_map_files.MapTable,
                                tip_heights: np.ndarray) -> None:
    """The stack's map `fits` holds, for every pixel, the row of the file's map `table` bit for bit, its place and
    the origin of contact_height aside; a pixel whose fit stopped short NOT_CONVERGED with the fit's status."""
    statuses = list(table.columns["status"])
    assert statuses[0].startswith("converged") and statuses[1:] == [STOPPED, STOPPED]  # both kinds of pixel
    assert fits.status[0].tolist() == [OK, NOT_CONVERGED, NOT_CONVERGED]
    assert fits.reasons[0].tolist() == ["", STOPPED, STOPPED]
    assert list(fits.values) == list(table.columns)
    for name, column in table.columns.items():
        if name in PLACE:
            continue
        ours = fits.values[name][0]
        if column.dtype.kind != "f":  # status, flags, failure
            assert ours.tolist() == column.tolist(), name
            continue
        if name == "contact_height":  # the file's is from the first row's tip height, a stack's from 0
            ours = tip_heights + ours
        assert np.all(np.isfinite(ours)), name
        assert ours.view(np.int64).tolist() == column.view(np.int64).tolist(), name


def test_a_fit_that_stops_short_is_the_same_pixel_from_an_array_as_from_the_instrument_file(mdr_binary, file_map,
                                                                                           stack, tmp_path):
    curves, tip_heights = stack
    expect_the_file_maps_pixels(mdr.fit_map(CASE, curves, jobs=1), file_map, tip_heights)
    # The file route is the command line's: the same map.csv, and exit code 1 (a pixel did not converge).
    (tmp_path / "case.toml").write_text('[material]\nmodel = "elastic"\nG = 1000.0\n\n[indenter]\nshape = "sphere"\n'
                                        'R = 5.0e-6\n\n[fit]\nfree = ["material.G"]\nmax_iterations = 12\n\n'
                                        '[[fit.data]]\nfile = "map.jpk-force-map"\nsegments = ["extend"]\n')
    run = subprocess.run([mdr_binary, "fit", "case.toml", "--map", MAP, "--out", "cli"], cwd=tmp_path,
                         capture_output=True, timeout=300)
    assert run.returncode == 1
    mdr.fit_map(FILE_CASE, MAP, jobs=1, out=tmp_path / "py", figures=False)
    assert (tmp_path / "cli" / "map.csv").read_text() == (tmp_path / "py" / "map.csv").read_text()


def test_directories_hdf5_files_and_local_processes_give_the_same_pixels(file_map, stack, tmp_path):
    curves, tip_heights = stack
    directory = tmp_path / "curves"
    directory.mkdir()
    with open(directory / "positions.csv", "w", encoding="utf-8") as handle:
        handle.write("file,row,col\n" + "".join(f"curve{col}.csv,0,{col}\n" for col in range(3)))
    for col in range(3):  # 17 significant digits: every double read back as it was
        np.savetxt(directory / f"curve{col}.csv", curves[0, col], delimiter=",", fmt="%.17g",
                   header="time,depth,force", comments="")
    expect_the_file_maps_pixels(mdr.fit_map(CASE, directory, jobs=1), file_map, tip_heights)
    expect_the_file_maps_pixels(mdr.fit_map(CASE, curves, jobs=2), file_map, tip_heights)
    h5py = pytest.importorskip("h5py")
    with h5py.File(tmp_path / "curves.h5", "w") as handle:
        handle["curves"] = curves
    expect_the_file_maps_pixels(mdr.fit_map(CASE, tmp_path / "curves.h5", jobs=1), file_map, tip_heights)


def hertz_map() -> tuple[np.ndarray, np.ndarray, np.ndarray, dict]:
    """Hertz curves F = (16/3) G sqrt(R) d^(3/2) (docs/theory.md eq. 31, nu = 1/2) of G = 1, 2 and 3 MPa, the third
    with a gap in its force, and a case whose fit starts at 0.3 MPa with 10 iterations at most: the first pixel
    converges (8 iterations), the second stops short (it needs 23), the third fails."""
    t = np.linspace(0.0, 1.0, 51)
    d = 1e-5 * t
    forces = 16.0 / 3.0 * np.array([1e6, 2e6, 3e6])[None, :, None] * math.sqrt(1e-3) * d ** 1.5
    forces[0, 2, 20] = np.nan
    case = {"material": {"model": "elastic", "G": 3e5}, "indenter": {"shape": "sphere", "R": 1e-3},
            "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed", "max_iterations": 10}}
    return forces, t, d, case


def test_saved_arrays_and_heat_maps_show_the_pixel_that_did_not_converge(tmp_path):
    forces, t, d, case = hertz_map()
    fits = mdr.fit_map(case, forces, time=t, depth=d, jobs=1, out=tmp_path / "out")
    out = tmp_path / "out"
    assert np.load(out / "status.npy").tolist() == [[OK, NOT_CONVERGED, FAILED]]
    stopped = "did not converge in 10 iterations"
    with open(out / "failures.csv", newline="") as handle:
        assert list(csv.reader(handle)) == [["row", "col", "status", "reason"], ["0", "1", "not converged", stopped],
                                            ["0", "2", "failed", fits.reasons[0, 2]]]
    G = np.load(out / "material.G.npy")[0]
    assert abs(G[0] / 1e6 - 1.0) < 1e-9 and np.isfinite(G[1]) and np.isnan(G[2])  # where the fit stopped
    assert np.isfinite(np.load(out / "material.G_stderr.npy")[0, 1])
    with open(out / "texts.csv", newline="") as handle:
        assert [row["status"] for row in csv.DictReader(handle)] == ["converged", stopped, ""]
    # map.json's "failed" counts the pixels without values, as the command line's does (a row without a fit).
    assert json.loads((out / "map.json").read_text())["failed"] == 1 == fits.summary()["failed"]
    # The heat map of every value marks the pixel that did not converge with an orange plus and counts it.
    figure = mdr.curve_maps.heat_map(fits.values["material.G"], "material.G", fits.status)
    axes = figure.axes[0]
    assert axes.get_title() == "material.G (2 of 3 pixels, 1 failed, 1 not converged)"
    assert {marks.get_label(): marks.get_offsets().tolist() for marks in axes.collections} == \
        {"failed": [[2.0, 0.0]], "not converged": [[1.0, 0.0]]}
    from matplotlib.image import imread
    image = imread(out / "material.G.png")[..., :3]  # what write_files drew: viridis has no orange
    orange = (image[..., 0] > 0.9) & (np.abs(image[..., 1] - 0.65) < 0.1) & (image[..., 2] < 0.2)
    assert np.count_nonzero(orange) > 0
