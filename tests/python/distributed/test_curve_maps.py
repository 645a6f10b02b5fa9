"""mdr.map_curves, verified with a closed-form Hertz fit (hertz_curves.py) on synthetic force maps: the fitted
modulus against the one the curves were made with, failures kept per pixel, the three kinds of stack, the result
directory, and the same maps bit for bit through a real Dask scheduler and two workers."""

from __future__ import annotations

import functools
import json
import os

import numpy as np
import pytest

import mdr
from hertz_curves import R, fit_hertz, hertz_force
from mdr import curve_maps

NY, NX, NT = 6, 7, 200


def synthetic_map(noise: float = 0.0, seed: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Curves (NY, NX, NT, 2) of [depth, force] with G rising across the map, and the G of each pixel."""
    rng = np.random.default_rng(seed)
    G = 1.0e5 * (1.0 + np.add.outer(np.arange(NY), 2.0 * np.arange(NX)) / 10.0)
    depth = np.linspace(0.0, 1.0e-6, NT)
    curves = np.empty((NY, NX, NT, 2))
    curves[..., 0] = depth
    for row in range(NY):
        for col in range(NX):
            force = hertz_force(G[row, col], depth)
            curves[row, col, :, 1] = force + noise * force.max() * rng.standard_normal(NT)
    return curves, G


def test_an_exact_map_gives_back_its_moduli():
    curves, G = synthetic_map()
    result = mdr.map_curves(fit_hertz, curves, jobs=2)
    assert np.all(result.status == curve_maps.OK)
    np.testing.assert_allclose(result.values["G"], G, rtol=1e-12)
    assert np.all(result.values["G_stderr"] < 1e-9 * G)
    assert result.batch.tasks >= 2 and result.batch.retried == 0


def test_noisy_maps_recover_the_modulus_within_their_standard_errors():
    curves, G = synthetic_map(noise=1e-2)
    result = mdr.map_curves(fit_hertz, curves, jobs=2)
    z = (result.values["G"] - G) / result.values["G_stderr"]
    assert np.all(np.abs(z) < 5.0)
    assert 0.5 < np.std(z) < 1.5  # the standard errors are right, not only large


def test_failed_pixels_keep_their_reason_and_do_not_stop_the_map():
    curves, G = synthetic_map()
    curves[2, 3, 10, 1] = np.nan
    curves[4, 0, :, 0] = 0.0  # never indents
    result = mdr.map_curves(fit_hertz, curves, jobs=2)
    assert result.status[2, 3] == curve_maps.FAILED and "not finite" in result.reasons[2, 3]
    assert result.status[4, 0] == curve_maps.FAILED and "never indents" in result.reasons[4, 0]
    assert np.isnan(result.values["G"][2, 3]) and np.isnan(result.values["G"][4, 0])
    assert np.count_nonzero(result.status == curve_maps.OK) == NY * NX - 2
    ok = result.status == curve_maps.OK
    np.testing.assert_allclose(result.values["G"][ok], G[ok], rtol=1e-12)


def test_a_directory_of_curve_files_with_their_positions(tmp_path):
    curves, G = synthetic_map()
    with open(tmp_path / "positions.csv", "w") as index:
        index.write("file,row,col\n")
        for row in range(NY):
            for col in range(NX):
                if (row, col) == (1, 1):
                    continue  # a pixel without a curve
                name = f"curve_{row}_{col}.csv"
                np.savetxt(tmp_path / name, curves[row, col], delimiter=",", header="depth,force", comments="")
                index.write(f"{name},{row},{col}\n")
    result = mdr.map_curves(fit_hertz, str(tmp_path), jobs=2)
    assert result.status.shape == (NY, NX)
    assert result.status[1, 1] == curve_maps.NO_CURVE and np.isnan(result.values["G"][1, 1])
    ok = result.status == curve_maps.OK
    assert np.count_nonzero(ok) == NY * NX - 1
    np.testing.assert_allclose(result.values["G"][ok], G[ok], rtol=1e-12)
    with pytest.raises(ValueError, match="holds the input file .*positions.csv"):
        mdr.map_curves(fit_hertz, str(tmp_path), jobs=2, out=tmp_path.parent)


def test_an_hdf5_stack_is_read_in_slices(tmp_path):
    h5py = pytest.importorskip("h5py")
    curves, G = synthetic_map()
    with h5py.File(tmp_path / "map.h5", "w") as handle:
        handle["curves"] = curves
    result = mdr.map_curves(fit_hertz, str(tmp_path / "map.h5"), jobs=2)
    np.testing.assert_array_equal(result.values["G"], mdr.map_curves(fit_hertz, curves, jobs=1).values["G"])
    with h5py.File(tmp_path / "map.h5", "r") as handle:  # an open dataset is read in slices too
        np.testing.assert_array_equal(mdr.map_curves(fit_hertz, handle["curves"], jobs=2).values["G"],
                                      result.values["G"])
    with pytest.raises(ValueError, match="no dataset 'other'"):
        curve_maps.open_stack(str(tmp_path / "map.h5"), dataset="other")


def test_the_result_directory_holds_arrays_figures_and_failures(tmp_path):
    curves, _ = synthetic_map()
    curves[0, 0, :, 1] = np.inf
    out = tmp_path / "map"
    result = mdr.map_curves(fit_hertz, curves, jobs=2, out=out)
    names = sorted(os.listdir(out))
    assert names == sorted([".mdr-result", "G.npy", "G_stderr.npy", "G.png", "G_stderr.png", "status.npy",
                            "failures.csv", "map.json"])
    np.testing.assert_array_equal(np.load(out / "G.npy"), result.values["G"])
    np.testing.assert_array_equal(np.load(out / "status.npy"), result.status)
    assert (out / "failures.csv").read_text().splitlines()[1].startswith("0,0,failed,ValueError: the curve has")
    summary = json.loads((out / "map.json").read_text())
    assert (summary["rows"], summary["columns"]) == (NY, NX)  # map.json of `mdr fit --map`: its layout
    assert summary["failed"] == 1 and summary["pixels"] == NY * NX
    assert summary["column_units"] == {"G": "", "G_stderr": ""}  # a plain dict of numbers states no units
    mdr.map_curves(fit_hertz, curves, jobs=2, out=out)  # mdr's own directory is replaced


def test_a_user_directory_is_refused_before_any_computing(tmp_path):
    user = tmp_path / "mine"
    user.mkdir()
    (user / "notes.txt").write_text("keep")
    with pytest.raises(ValueError, match="out = .*mine"):
        mdr.map_curves(fit_hertz, np.zeros((2, 2, 3, 2)), jobs=1, out=user)
    assert (user / "notes.txt").read_text() == "keep" and os.listdir(user) == ["notes.txt"]
    assert os.listdir(tmp_path) == ["mine"]


def test_a_map_through_the_scheduler_is_the_local_map(cluster):
    curves, _ = synthetic_map(noise=1e-2)
    curves[3, 3, 5, 1] = np.nan
    local = mdr.map_curves(fit_hertz, curves, jobs=2)
    remote = mdr.map_curves(functools.partial(fit_hertz, radius=R), curves, scheduler=cluster.address)
    for name in local.values:
        assert np.array_equal(local.values[name].view(np.int64), remote.values[name].view(np.int64)), name
    np.testing.assert_array_equal(local.status, remote.status)
    np.testing.assert_array_equal(local.reasons, remote.reasons)
    assert remote.batch.workers == 2 and remote.batch.retried == 0


def test_ctrl_c_leaves_no_directory_and_no_process(tmp_path):
    import _thread
    import multiprocessing
    import threading
    import time

    from hertz_curves import slow_fit_hertz

    curves, _ = synthetic_map()
    many = np.tile(curves, (4, 4, 1, 1))  # 672 curves, 7 s on 2 processes
    timer = threading.Timer(1.0, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        mdr.map_curves(slow_fit_hertz, many, jobs=2, out=tmp_path / "map")
    timer.cancel()
    assert time.monotonic() - start < 5
    assert os.listdir(tmp_path) == []
    deadline = time.monotonic() + 5
    while multiprocessing.active_children() and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not multiprocessing.active_children()


def test_a_function_the_workers_cannot_import_fails_the_map_with_the_rule(cluster, tmp_path, monkeypatch):
    (tmp_path / "private_curves.py").write_text("def fit(curve):\n    return {'x': 1.0}\n")
    monkeypatch.syspath_prepend(str(tmp_path))  # importable here only, as a module a user forgot to install
    import private_curves

    with pytest.raises(RuntimeError, match="a chunk failed on a worker.*private_curves.*docs/distributed.md"):
        mdr.map_curves(private_curves.fit, np.zeros((2, 2, 3)), scheduler=cluster.address)
