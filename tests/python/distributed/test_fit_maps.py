"""mdr.fit_map: mdr.fit over every curve of a stack, on synthetic Hertz maps (eq. 31, 35: F = (16/3) G sqrt(R)
d^(3/2) for an incompressible elastic body), locally and through a real Dask scheduler, bit for bit."""

from __future__ import annotations

import numpy as np
import pytest

import mdr
from hertz_curves import hertz_force
from mdr import curve_maps

R = 1.0e-3
CASE = {"material": {"model": "elastic", "G": 3.0e5}, "indenter": {"shape": "sphere", "R": R},
        "fit": {"free": ["material.G"], "contact_point": "fixed", "baseline": "fixed"}}
TIME = np.linspace(0.0, 1.0, 101)
DEPTH = 1.0e-5 * TIME


def force_map(ny: int = 2, nx: int = 3) -> tuple[np.ndarray, np.ndarray]:
    G = 1.0e6 * (1.0 + np.add.outer(np.arange(ny), 3.0 * np.arange(nx)) / 10.0)
    return hertz_force(1.0, DEPTH, R)[None, None, :] * G[..., None], G


def test_a_force_map_gives_back_its_moduli_and_keeps_failures():
    forces, G = force_map()
    forces[1, 2, 50] = np.nan
    result = mdr.fit_map(CASE, forces, time=TIME, depth=DEPTH, jobs=2)
    ok = result.status == curve_maps.OK
    assert result.status[1, 2] == curve_maps.FAILED and result.reasons[1, 2] != ""
    assert np.count_nonzero(ok) == G.size - 1
    np.testing.assert_allclose(result.values["material.G"][ok], G[ok], rtol=2e-3)
    assert set(result.values) >= {"material.G", "material.G_stderr", "residual_to_noise", "noise", "status"}
    # The same curves with their time and depth in the stack.
    stacked = np.stack(np.broadcast_arrays(TIME, DEPTH, forces), axis=-1)
    again = mdr.fit_map(CASE, stacked, jobs=1)
    np.testing.assert_array_equal(again.values["material.G"], result.values["material.G"])


@pytest.mark.parametrize("max_iterations", [200, 10])
def test_a_fit_map_through_the_scheduler_is_the_local_map(cluster, max_iterations):
    # 10 iterations: the fits of the stiffer pixels (from 0.3 MPa) stop short; their pixels keep where they stopped.
    case = dict(CASE, fit=dict(CASE["fit"], max_iterations=max_iterations))
    forces, _ = force_map()
    local = mdr.fit_map(case, forces, time=TIME, depth=DEPTH, jobs=2)
    remote = mdr.fit_map(case, forces, time=TIME, depth=DEPTH, scheduler=cluster.address)
    for name, values in local.values.items():
        if values.dtype.kind == "f":
            assert np.array_equal(values.view(np.int64), remote.values[name].view(np.int64)), name
        else:  # status, flags, failure
            np.testing.assert_array_equal(values, remote.values[name])
    np.testing.assert_array_equal(local.status, remote.status)
    np.testing.assert_array_equal(local.reasons, remote.reasons)
    stopped = local.status == curve_maps.NOT_CONVERGED
    assert stopped.any() == (max_iterations == 10) and np.all(local.status[~stopped] == curve_maps.OK)
    assert np.all(np.isfinite(local.values["material.G"])) and np.all(local.reasons[stopped] == "did not converge "
                                                                       "in 10 iterations")


def test_a_curve_without_time_and_depth_is_a_failed_pixel_with_the_reason():
    forces, _ = force_map(1, 1)
    result = mdr.fit_map(CASE, forces, jobs=1)
    assert result.status[0, 0] == curve_maps.FAILED and "time= and depth=" in result.reasons[0, 0]


def test_bad_fit_settings_fail_every_pixel_with_the_command_line_message():
    forces, _ = force_map(1, 2)
    case = dict(CASE, fit={"free": ["material.G"], "bounds": {"material.G": [1.0e7, 1.0e8]}})
    result = mdr.fit_map(case, forces, time=TIME, depth=DEPTH, jobs=1)
    assert np.all(result.status == curve_maps.FAILED)
    assert "the start value must lie within its bounds" in result.reasons[0, 0]
    with pytest.raises(FileNotFoundError):
        mdr.fit_map("no-such-case.toml", forces, time=TIME, depth=DEPTH)
