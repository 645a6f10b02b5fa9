"""Memory of a long fit (issue 23): `mdr fit` on a CSV of 10^6 rows must peak at a few times its data (time, depth,
force: 24 bytes a row). It peaked at 12 times (288 MB): a copy of the problem's curves for the pre-contact
baseline, Ceres' dense QR's copy of the N x p Jacobian, a copy of each model run kept for reuse; then at 10.5 times
(252 MB): the continuum model's copies of the curve and its record, derivatives nobody read; then at 8.5 times
(203 MB): the diagnostics' copies of the N x p Jacobian (stacked, its SVD's QR, the AR(1) sandwich's), Ceres'
evaluation scratch of the curve's whole Jacobian, two model runs at each candidate. The child's own peak comes from
os.wait4 (ru_maxrss in KiB on Linux)."""

from __future__ import annotations

import json
import math
import os
import random
import subprocess
import sys

import pytest

ROWS = 1_000_000
G, R = 1.0e3, 1.0e-5  # Pa, m


def write_hertz_curve(path, rows):
    # Hertz for a sphere, nu = 1/2 (handbook eq. 13): F = 16/3 G sqrt(R) d^1.5, with Gaussian noise of 1e-3 of the
    # peak force; the depth starts 0.1 um before contact.
    peak = 16.0 / 3.0 * G * math.sqrt(R) * 1e-6 ** 1.5
    noise = random.Random(7)
    with open(path, "w") as file:
        file.write("time,depth,force\n")
        for i in range(rows):
            t = i / (rows - 1)
            d = -1e-7 + 1.1e-6 * t
            force = 16.0 / 3.0 * G * math.sqrt(R) * max(d, 0.0) ** 1.5 + noise.gauss(0.0, 1e-3 * peak)
            file.write(f"{t!r},{d!r},{force!r}\n")


# Runs the command given as arguments and prints its peak resident memory in bytes. A fresh interpreter of ~10 MB:
# a child forked from pytest itself would count pytest's own peak (Linux keeps the larger of the two at exec).
PEAK_OF_CHILD = """
import os, subprocess, sys
child = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=open("stderr.txt", "w"))
_, status, usage = os.wait4(child.pid, 0)
print(os.waitstatus_to_exitcode(status), usage.ru_maxrss * 1024)
"""


@pytest.mark.skipif(os.environ.get("MDR_SANITIZED") == "1", reason="the sanitizers' shadow memory is not the fit's")
def test_a_long_curve_costs_a_few_times_its_data(mdr_binary, workdir):
    write_hertz_curve(workdir / "curve.csv", ROWS)
    (workdir / "case.toml").write_text(
        '[material]\nmodel = "elastic"\nG = 500.0\n[indenter]\nshape = "sphere"\nR = 1.0e-5\n'
        '[fit]\nfree = ["material.G"]\n'
        '[[fit.data]]\nfile = "curve.csv"\ntime = "time"\ndepth = "depth"\nforce = "force"\n')
    measured = subprocess.run([sys.executable, "-c", PEAK_OF_CHILD, mdr_binary, "fit", "case.toml", "--out", "out"],
                              cwd=workdir, capture_output=True, text=True, timeout=120, check=True)
    exit_code, peak_bytes = map(int, measured.stdout.split())
    assert exit_code == 0, (workdir / "stderr.txt").read_text()
    fitted = json.loads((workdir / "out" / "fit.json").read_text())
    assert fitted["parameters"]["material.G"] == pytest.approx(G, rel=1e-4)
    # 12.0 x at first (288 MB), 10.5 x with one copy of the curves and no QR copy (252 MB), 8.5 x with the continuum
    # model reading the curve in place and leaving out what no one reads (203 MB), 4.7 x with the diagnostics
    # summarising the Jacobian block by block, Ceres given the curve in row blocks and one model run kept (114 MB),
    # 4.4 x with a run's residuals made in its own force vector (107 MB), of which ~0.5 x is the binary and its
    # libraries.
    # The bound keeps 15 % above the last and fails 8.5 x (main before this) and 6.7 x (the diagnostics' cut alone).
    data_bytes = 3 * 8 * ROWS
    assert peak_bytes < 5.1 * data_bytes, f"peak {peak_bytes / 1e6:.0f} MB = {peak_bytes / data_bytes:.1f} x the data"
