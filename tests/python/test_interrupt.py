"""Ctrl-C in Python: a long run and a sweep stop with KeyboardInterrupt within a fraction of a second, never with
an abort of the interpreter, and the module works normally afterwards. The interrupt comes from a timer thread
(`_thread.interrupt_main`, what Ctrl-C does to the main thread)."""

from __future__ import annotations

import _thread
import threading
import time

import pytest

import mdr

# Minutes of work: long enough to be interrupted on any machine.
LONG_CASE = {
    "material": {"model": "standard", "G_inf": 1.0e6, "G1": 3.0e6, "tau1": 0.2},
    "indenter": {"shape": "sphere", "R": 0.01},
    "load": {"control": "displacement", "history": [[0.0, 0.0], [1.0, 1.0e-4], [2.0, 0.0]]},
    "numerics": {"elements": 400000, "time_step": 1.0e-5},
}


def interrupted_after(seconds: float, call) -> float:
    """Runs `call` with Ctrl-C after `seconds`; returns how long the stop took."""
    timer = threading.Timer(seconds, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
    return time.monotonic() - start - seconds


@pytest.mark.parametrize("what", ["run", "sweep"])
def test_ctrl_c_stops_with_keyboard_interrupt(what):
    if what == "run":
        delay = interrupted_after(0.5, lambda: mdr.run(LONG_CASE))
    else:
        delay = interrupted_after(0.5, lambda: mdr.sweep(LONG_CASE, {"material.G1": [1e6, 2e6, 3e6, 4e6]}, jobs=2))
    assert delay < 5.0
    small = dict(LONG_CASE, numerics={"elements": 100, "time_step": 0.02})
    assert mdr.run(small).summary["max_force"] > 0.0
    assert list(mdr.sweep(small, {"material.G1": [1e6, 2e6]})["error"]) == ["", ""]


def test_ctrl_c_stops_a_fit():
    # A fit of many model runs (force-driven: the element model, 200 000 elements): stopped at the next model run or
    # progress report.
    t = [0.01 * i for i in range(201)]
    depth = [1e-4 * min(x, 1.0) for x in t]
    force = [5.0 * d ** 1.5 for d in depth]
    case = {"material": {"model": "standard", "G_inf": 1.0e6, "G1": 3.0e6, "tau1": 0.2},
            "indenter": {"shape": "sphere", "R": 0.01},
            "fit": {"free": ["material.G_inf", "material.G1", "material.tau1"], "elements": 200000, "fitted": "depth",
                    "contact_point": "fixed", "baseline": "fixed"}}
    delay = interrupted_after(0.5, lambda: mdr.fit(case, data=[{"time": t, "depth": depth, "force": force}]))
    assert delay < 5.0


def test_ctrl_c_stops_an_instrument_map_on_threads(tmp_path):
    # 256 copies of the vendor JPK map's pixel 109 (scripts/make_instrument_test_files.py; ~30 ms of fitting each),
    # fitted on 2 threads: the calling thread sees Ctrl-C at its next progress report (0.2 s) and the threads stop at
    # their next model run.
    import subprocess
    import sys

    from conftest import REPO_ROOT

    big = tmp_path / "big.jpk-force-map"
    subprocess.run([sys.executable, REPO_ROOT / "scripts" / "make_instrument_test_files.py", "map", "256", big],
                   check=True, capture_output=True, timeout=120)
    case = {"material": {"model": "elastic", "G": 1000.0}, "indenter": {"shape": "sphere", "R": 5.0e-6},
            "fit": {"free": ["material.G"], "data": [{"file": "map.jpk-force-map", "segments": ["extend"]}]}}
    delay = interrupted_after(0.5, lambda: mdr.fit_map(case, big, jobs=2, out=tmp_path / "out"))
    assert delay < 5.0
    assert not (tmp_path / "out").exists()
